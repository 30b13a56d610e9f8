#!/usr/bin/env python3
"""Cost of the xCFC solves of a run in RK3 matter steps, from the run's own timer table (one run:
both figures share the machine's load). Runs `[mpirun -np N] remnant PARFILE OVERRIDES...` in a
fresh output folder and prints, per evolution solve (xcfc.tsv rows after the initial solve): the
V-cycles of X, psi, alpha psi and beta, the time of the solve's steps (XCFC_VectorPotential,
XCFC_ConformalFactor, XCFC_Lapse, XCFC_Shift; not the matter's recovery or the extrapolation) and
that time over MoL_Step per call.

  thorns/XCFC/bench/solve_cost.py --exe build/bin/remnant parfiles/migration.yaml MoL::max_iterations=300
"""
import argparse
import csv
import os
import sys
import tempfile

from remnant_run import command, run_or_exit, timers

SOLVE_STEPS = ["XCFC::XCFC_VectorPotential", "XCFC::XCFC_ConformalFactor", "XCFC::XCFC_Lapse", "XCFC::XCFC_Shift"]
def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default="build/bin/remnant")
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("parfile")
    ap.add_argument("overrides", nargs="*")
    a = ap.parse_args()
    out = tempfile.mkdtemp(prefix="xcfc_cost_")
    run = run_or_exit(command(a.exe, a.parfile, a.overrides, out, a.np, a.mpirun), "solve_cost")
    t = timers(run.stdout + run.stderr)
    missing = [k for k in SOLVE_STEPS + ["MoL::MoL_Step"] if k not in t]
    if missing:
        sys.exit(f"solve_cost: no timer for {', '.join(missing)} in the run's output (is XCFC active?)")
    with open(os.path.join(out, "xcfc.tsv")) as f:
        rows = [r for r in csv.reader((l for l in f if not l.startswith("#")), delimiter="\t")]
    rows = [r for r in rows if r[2] != "initial"]
    if not rows:
        sys.exit("solve_cost: no evolution solve in xcfc.tsv: run more steps")
    n = len(rows)
    cyc = [sum(int(r[c]) for r in rows) / n for c in (3, 5, 7, 9)]
    solve = sum(t[k][1] for k in SOLVE_STEPS) / n
    step = t["MoL::MoL_Step"][1] / t["MoL::MoL_Step"][0]
    print(f"solves {n}  V-cycles per solve: X {cyc[0]:.2f} psi {cyc[1]:.2f} alpha_psi {cyc[2]:.2f} beta {cyc[3]:.2f} "
          f"total {sum(cyc):.2f}")
    print(f"per solve {1e3 * solve:.2f} ms  MoL_Step {1e3 * step:.2f} ms  solve/step {solve / step:.3f}  "
          f"XCFC_Solve total {t['XCFC::XCFC_Solve'][1]:.3f} s  MoL_Step total {t['MoL::MoL_Step'][1]:.3f} s")


if __name__ == "__main__":
    main()
