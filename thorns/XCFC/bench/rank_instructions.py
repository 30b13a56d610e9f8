#!/usr/bin/env python3
"""How the xCFC solve's work is split between MPI ranks, counted in instructions (callgrind), not
timed: the machine's load does not change the counts. Runs `remnant PARFILE OVERRIDES...` under
`valgrind --tool=callgrind` on 1 rank and on N ranks, collecting only inside the solve's scheduled
steps (XCFC_VectorPotential, XCFC_ConformalFactor, XCFC_Lapse, XCFC_Shift: remnant::xcfc::step_*),
and prints per rank: the instructions in those steps, the part inside MPI calls (copies, reductions
and the polling while waiting) and the rest, "compute"; then 1-rank compute over the largest rank's
compute (the speed-up of the solve if messages were free) and the functions whose instructions did
not fall with the ranks (each rank does at least 80 % of the 1-rank work: replicated work).

  thorns/XCFC/bench/rank_instructions.py --exe build/bin/remnant parfiles/migration.yaml \\
      MoL::max_iterations=6 XCFC::solve_every=1

Slow (callgrind: about 40x); keep the runs to a few steps.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

from remnant_run import command, run_or_exit

ENTRY = re.compile(r"\s*([\d,]+)\s+\(\s*[\d.]+%\)\s+(.*)$")
MPI_CALL = re.compile(r":P?MPI_[A-Z][a-z_]+ \[")


def annotate(path, inclusive):
    """{function: instructions} from callgrind_annotate (inclusive or self), and the total."""
    cmd = ["callgrind_annotate", "--threshold=100", path] + (["--inclusive=yes"] if inclusive else [])
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    total, funcs = 0, {}
    for line in out.splitlines():
        m = ENTRY.match(line)
        if not m:
            continue
        n, name = int(m.group(1).replace(",", "")), m.group(2)
        if "PROGRAM TOTALS" in name:
            total = n
        else:
            funcs[name] = funcs.get(name, 0) + n
    return total, funcs


def short(name):
    name = name.split(":", 1)[1] if ":" in name and not name.startswith("???:") else name[4:]
    return re.sub(r"\(.*", "", name)[:90]


def run(a, nprocs, out):
    tag = os.path.join(out, f"cg{nprocs}")
    vg = [a.valgrind, "--tool=callgrind", "--toggle-collect=remnant::xcfc::step_*"]
    # One output per rank (%q: the environment variable Open MPI sets per rank).
    vg.append(f"--callgrind-out-file={tag}.0.out" if nprocs == 1 else f"--callgrind-out-file={tag}.%q{{OMPI_COMM_WORLD_RANK}}.out")
    run_or_exit(command(a.exe, a.parfile, a.overrides, f"{out}/run{nprocs}", nprocs, a.mpirun, vg), "rank_instructions")
    ranks = []
    for rank in range(nprocs):
        path = f"{tag}.{rank}.out"
        total, incl = annotate(path, True)
        mpi = sum(v for k, v in incl.items() if MPI_CALL.search(k))
        _, self_cost = annotate(path, False)
        ranks.append((total, mpi, {short(k): v for k, v in self_cost.items()}))
    return ranks


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default="build/bin/remnant")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--valgrind", default="valgrind")
    ap.add_argument("--top", type=int, default=12, help="replicated functions listed")
    ap.add_argument("parfile")
    ap.add_argument("overrides", nargs="*")
    a = ap.parse_args()
    out = tempfile.mkdtemp(prefix="xcfc_ranks_")
    one = run(a, 1, out)[0]
    many = run(a, a.np, out)
    if one[0] == 0:
        sys.exit("rank_instructions: no instructions inside remnant::xcfc::step_* (is XCFC solving in evolution?)")
    one_compute = one[0] - one[1]
    print(f"instructions in the xCFC solve steps (M): 1 rank: compute {one_compute / 1e6:.1f}")
    for r, (total, mpi, _) in enumerate(many):
        print(f"  {a.np} ranks, rank {r}: total {total / 1e6:.1f}  in MPI calls {mpi / 1e6:.1f}  compute {(total - mpi) / 1e6:.1f}")
    worst = max(total - mpi for total, mpi, _ in many)
    print(f"compute speed-up bound on {a.np} ranks: {one_compute / worst:.3f} (ideal {a.np})")
    rows = []
    for name, n1 in one[2].items():
        per_rank = max(r[2].get(name, 0) for r in many)
        if n1 > 0.002 * one_compute and per_rank >= 0.8 * n1:
            rows.append((n1, per_rank, name))
    print("replicated (largest rank >= 80 % of 1 rank), M instructions: 1 rank, largest rank")
    for n1, per_rank, name in sorted(rows, reverse=True)[: a.top]:
        print(f"  {n1 / 1e6:8.1f} {per_rank / 1e6:8.1f}  {name}")


if __name__ == "__main__":
    main()
