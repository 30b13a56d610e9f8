#!/usr/bin/python3
"""The collision columns of analysis.tsv across a recovery (CTest label Analysis): rho_max_norm and
rho_max_point_norm divide by the first row's values, h_plus differentiates against the previous row;
a recovered run reads both rows back from the analysis.tsv it resumes (Analysis/collision_reference.hpp).

  restart   the tiny head-on octant (thorns/HeadOn/test/headon_tiny.yaml, as testsuites/HeadOn/octant_tiny)
            8 steps straight on 1 rank vs 6 steps with a checkpoint at 4, then recovered on 2 ranks to 8:
            analysis.tsv bit-identical (before the fix the recovered rows were normalised by row 5 and
            row 5's h_plus was 0). Then recovered once more with analysis.tsv deleted: the run goes on,
            says so, and its first row has rho_max_norm = 1.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "framework", "test", "python"))
import remnant_runs  # noqa: E402

BASE = ["active_thorns+=[IO]", "Grid::ncells=[16,16,16]", "Grid::block_size=[8,8,8]", "Grid::max_level=1",
        "Grid::regrid_every=3", "HeadOn::refine_radii=[12]", "HeadOn::infall_velocity=0.02", "Analysis::every=1",
        "Flesh::timers=false"]


def rows(out):
    with open(os.path.join(out, "analysis.tsv")) as f:
        lines = f.read().splitlines()
    return [l for l in lines if not l.startswith("#")], [l for l in lines if l.startswith("#")][-1][2:].split("\t")


def mode_restart(r):
    straight, _ = r.run("straight", 1, ["MoL::max_iterations=8"])
    out, _ = r.run("restarted", 1, ["MoL::max_iterations=6", "IO::checkpoint_every=4"])
    _, p = r.run("restarted", 2, ["MoL::max_iterations=8", "IO::recover=auto"])
    assert "recovered from" in p.stdout and "at iteration 4" in p.stdout, p.stdout[-3000:]
    a, names = rows(straight)
    b, _ = rows(out)
    assert len(a) == 9 and len(b) == 9, (len(a), len(b))
    for x, y in zip(a, b):
        if x != y:
            bad = [n for n, u, v in zip(names, x.split("\t"), y.split("\t")) if u != v]
            sys.exit("analysis.tsv differs after the recovery at iteration %s in %s:\n  straight  %s\n  restarted %s"
                     % (x.split("\t")[0], bad, x, y))
    norm = names.index("rho_max_norm")
    print("recovered at 4 on 2 ranks: analysis.tsv bit-identical to the straight run (rho_max_norm at 8: %s)"
          % a[-1].split("\t")[norm])
    os.remove(os.path.join(out, "analysis.tsv"))
    _, p = r.run("restarted", 1, ["MoL::max_iterations=6", "IO::recover=auto"])
    assert "recovered without earlier collision rows" in p.stdout, p.stdout[-3000:]
    c, _ = rows(out)
    assert float(c[0].split("\t")[norm]) == 1.0, c[0]
    print("analysis.tsv missing at the recovery: said so, the first row's rho_max_norm is 1")


def main():
    remnant_runs.main(lambda a: remnant_runs.Runner(
        a, os.path.join(a.source_dir, "thorns", "HeadOn", "test", "headon_tiny.yaml"), BASE), {"restart": mode_restart})


if __name__ == "__main__":
    main()
