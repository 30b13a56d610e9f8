#!/usr/bin/env python3
"""The speed-up of the xCFC solve on N ranks (issue 21, goal 5), from the runs' comm.tsv
(Flesh::comm_stats): the CPU time outside MPI (`work:` rows) of XCFC_Solve, MoL_Step and the
evolution (both plus MoL_ComputeTimeStep) on the busiest rank, 1 rank against N ranks for each
XCFC::multigrid_storage given. On a shared machine wall times of several ranks measure the other
jobs; the CPU time outside MPI measures each rank's own work (preload build/libmpi_cpu_preload.so,
`--preload`, so that time spent polling inside MPI is set apart).

  thorns/XCFC/bench/rank_speedup.py --exe build/bin/remnant --preload build/libmpi_cpu_preload.so \\
      --storage replicated,distributed parfiles/rns_uniform_cart_3d.yaml MoL::max_iterations=10 XCFC::solve_every=1
"""
import argparse
import collections
import os
import sys
import tempfile

from remnant_run import command, run_or_exit

KEYS = ("XCFC::XCFC_Solve", "MoL::MoL_Step", "MoL::MoL_ComputeTimeStep")


def work_per_rank(path):
    """{rank: {function: CPU seconds outside MPI}} from a comm.tsv."""
    w = collections.defaultdict(dict)
    with open(path) as f:
        for line in f:
            if line.startswith(("#", "rank")):
                continue
            c = line.rstrip("\n").split("\t")
            if c[1].startswith("work:"):
                w[int(c[0])][c[1][5:]] = float(c[8])
    if not w:
        sys.exit(f"rank_speedup: no work: rows in {path} (Flesh::comm_stats)")
    return w


def busiest(w):
    """(solve, step, evolution) of the busiest rank in each."""
    solve = max(r.get(KEYS[0], 0.0) for r in w.values())
    step = max(r.get(KEYS[1], 0.0) for r in w.values())
    evol = max(sum(r.get(k, 0.0) for k in KEYS) for r in w.values())
    return solve, step, evol


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default="build/bin/remnant")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--preload", default="", help="libmpi_cpu_preload.so (CPU time inside MPI set apart)")
    ap.add_argument("--storage", default="replicated", help="XCFC::multigrid_storage values on N ranks, comma-separated")
    ap.add_argument("--out", default="", help="run directories (default: a temporary one)")
    ap.add_argument("parfile")
    ap.add_argument("overrides", nargs="*")
    a = ap.parse_args()
    storages = a.storage.split(",")
    for s in storages:
        if s not in ("replicated", "distributed"):
            sys.exit(f"rank_speedup: --storage {s}: allowed values are replicated, distributed")
    out = a.out or tempfile.mkdtemp(prefix="xcfc_speedup_")
    base = [*a.overrides, "Flesh::comm_stats=true", "Flesh::progress_every=0"]

    def run(np, storage):
        d = os.path.join(out, f"np{np}_{storage}")
        cmd = command(a.exe, a.parfile, base + [f"XCFC::multigrid_storage={storage}"], d, np, a.mpirun)
        if np > 1 and a.preload:
            cmd[1:1] = ["-x", f"LD_PRELOAD={os.path.abspath(a.preload)}"]
        run_or_exit(cmd, "rank_speedup")
        return busiest(work_per_rank(os.path.join(d, "comm.tsv")))

    one = run(1, "replicated")
    print(f"1 rank: XCFC_Solve {one[0]:.3f} s, MoL_Step {one[1]:.3f} s, evolution {one[2]:.3f} s (CPU outside MPI)")
    for storage in storages:
        n = run(a.np, storage)
        print(f"{a.np} ranks, {storage} storage: XCFC_Solve {n[0]:.3f} s (speed-up {one[0] / n[0]:.2f}), "
              f"MoL_Step {n[1]:.3f} s ({one[1] / n[1]:.2f}), evolution {n[2]:.3f} s ({one[2] / n[2]:.2f}) on the busiest rank")


if __name__ == "__main__":
    main()
