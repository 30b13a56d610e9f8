#!/usr/bin/python3
"""The metric inside a matter step (XCFC::stage_metric; thorns/XCFC/README.md, "Cadence"), whole runs
of the remnant executable (CTest label XCFC):

  order  the unstable-branch star of parfiles/migration.yaml in 1D on 160 cells, which collapses
         (alpha_c 0.28 -> 0.20 by t = 48), at three fixed time steps dt, dt/2, dt/4 with the phase of
         the solves aligned: the changes of rho_c at t = 16, alpha_c and psi_c at t = 48 between
         successive dt fall ~2x per halving with the metric held through the Runge-Kutta stages
         (first order in dt) and 3.2-4.4x with it extrapolated to each stage's time (second order),
         solving every step (dt 0.4, 0.2, 0.1) and every 3 steps (dt 0.2, 0.1, 0.05); the
         extrapolated runs' change is > 5x (rho_c) and > 10x (metric) smaller than the held runs'
  bits   stage_metric = extrapolate solving every 3 steps (the stages between solves and the next
         step's prestep that they make redundant) on an adaptively refined BU0 (two levels, regrid
         every 10): analysis.tsv and xcfc.tsv bit-identical on 1 and 2 ranks and after a 1 -> 2 rank
         restart; the 2D cylindrical head-on (parfiles/headon_cyl_2d.yaml at dx 1.5, refined, solving
         every step) bit-identical on 1 and 2 ranks; stage_metric = extrapolate with
         XCFC::extrapolation = hold is refused with a message naming both
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "framework", "test", "python"))
import remnant_runs  # noqa: E402

QUIET = ["Flesh::timers=false", "Flesh::progress_every=0", "Analysis::every=1"]


def parfile(r, name):
    return os.path.abspath(os.path.join(r.a.source_dir, "parfiles", name))


def columns(path):
    with open(path) as f:
        names = f.readline()[1:].split()
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {n: data[:, i] for i, n in enumerate(names)}


def rows(path, drop_last_column=False):
    out = []
    for line in open(path):
        if not line.startswith("#"):
            f = line.rstrip("\n").split("\t")
            out.append("\t".join(f[:-1] if drop_last_column else f))
    return out


# (column, time, smallest factor by which the extrapolated runs' change with dt is below the held
# runs'): the matter's central density while it is smooth, and the metric at the end.
OBSERVABLES = (("rho_c", 16.0, 5.0), ("alpha_c", 48.0, 10.0), ("psi_c", 48.0, 10.0))


def mode_order(r):
    collapse = remnant_runs.Runner(r.a, parfile(r, "migration.yaml"), QUIET + [
        "Grid::dimension=1", "Grid::ncells=[160,1,1]", "Grid::block_size=[32,1,1]",
        "Grid::boundary_upper=[outflow,outflow,outflow]", "MoL::final_time=48"])
    # Fixed steps: at t = 48 (240, 480 or 960 steps) every run of a cadence is at the same phase of
    # its solve interval.
    for every, dts in ((1, (0.4, 0.2, 0.1)), (3, (0.2, 0.1, 0.05))):
        change = {}
        for stage in ("hold", "extrapolate"):
            values = []
            for dt in dts:
                out, _ = collapse.run("every%d_%s_%g" % (every, stage, dt), 1,
                                      ["XCFC::solve_every=%d" % every, "MoL::dt=%g" % dt, "XCFC::stage_metric=" + stage])
                c = columns(os.path.join(out, "analysis.tsv"))
                values.append([c[col][int(np.argmin(np.abs(c["time"] - t)))] for col, t, _ in OBSERVABLES])
            v = np.array(values)
            change[stage] = (v[0] - v[1], v[1] - v[2])
            for i, (col, t, _) in enumerate(OBSERVABLES):
                d1, d2 = change[stage][0][i], change[stage][1][i]
                print("solve_every %d, stage_metric %-11s %s(t = %g): change dt %g -> %g: %+.3e, %g -> %g: %+.3e,"
                      " ratio %.2f" % (every, stage, col, t, dts[0], dts[1], d1, dts[1], dts[2], d2, d1 / d2))
        for i, (col, t, gain) in enumerate(OBSERVABLES):
            (h1, h2), (e1, e2) = ((change[s][0][i], change[s][1][i]) for s in ("hold", "extrapolate"))
            assert 1.3 < h1 / h2 < 2.6, "held metric: not first order in dt (%s, ratio %.2f)" % (col, h1 / h2)
            assert e1 / e2 > 3.0, "extrapolated metric: not second order in dt (%s, ratio %.2f)" % (col, e1 / e2)
            assert abs(e1) < abs(h1) / gain, "extrapolated metric: dt dependence not %gx below the held one's (%s)" % (gain, col)


def mode_bits(r):
    bu0 = os.path.join(r.a.work, "bu0_dyn_io.yaml")
    with open(bu0, "w") as f:
        f.write("include: %s\n" % parfile(r, "bu0_dyn.yaml"))
        f.write("active_thorns: [Grid, MoL, Spacetime, EOS, Atmosphere, Con2Prim, HydroBase, GRMHD, TOV, Analysis, XCFC, IO]\n")
    star = remnant_runs.Runner(r.a, bu0, QUIET + [
        "XCFC::stage_metric=extrapolate", "XCFC::solve_every=3", "Grid::ncells=[320,1,1]", "Grid::block_size=[16,1,1]",
        "Grid::max_level=2", "Grid::regrid_every=10", "Grid::refine_variable=HydroBase::prim.rho",
        "Grid::refine_scale=log", "Grid::refine_threshold=0.1", "MoL::final_time=-1"])
    one, _ = star.run("star_np1", 1, ["MoL::max_iterations=40"])
    two, _ = star.run("star_np2", 2, ["MoL::max_iterations=40"])
    first, _ = star.run("star_restart", 1, ["MoL::max_iterations=23", "IO::checkpoint_every=22"])
    _, p = star.run("star_restart", 2, ["MoL::max_iterations=40", "IO::recover=auto"])
    assert "recovered from" in p.stdout and "it0000000022" in p.stdout, p.stdout[-3000:]
    for other, what in ((two, "2 ranks"), (first, "a 1 -> 2 rank restart")):
        assert rows(os.path.join(one, "analysis.tsv")) == rows(os.path.join(other, "analysis.tsv")), "analysis.tsv differs on " + what
        assert rows(os.path.join(one, "xcfc.tsv"), True) == rows(os.path.join(other, "xcfc.tsv"), True), "xcfc.tsv differs on " + what
    assert len(rows(os.path.join(one, "xcfc.tsv"))) >= 14
    print("refined BU0, stage_metric = extrapolate, solve every 3: bit-identical on 1 and 2 ranks and after a 1 -> 2 restart")
    # The held and the extrapolated stage metric differ (the option is not a no-op).
    held, _ = star.run("star_held", 1, ["MoL::max_iterations=40", "XCFC::stage_metric=hold"])
    assert rows(os.path.join(one, "analysis.tsv")) != rows(os.path.join(held, "analysis.tsv"))

    # The parfile's table, found from the repository root as the parfile names it (../shared/eos).
    table = os.path.abspath(os.path.join(r.a.source_dir, "..", "shared", "eos", "SRO_LS220_157r_89t_49y.h5"))
    if not os.path.exists(table):
        print("SKIP the head-on part: no EOS table %s" % table)
    else:
        headon = remnant_runs.Runner(r.a, parfile(r, "headon_cyl_2d.yaml"), QUIET + [
            "EOS::table_file=" + table, "XCFC::stage_metric=extrapolate", "Grid::ncells=[16,16,1]",
            "MoL::final_time=-1", "MoL::max_iterations=12"])
        a, _ = headon.run("headon_np1", 1, [])
        b, _ = headon.run("headon_np2", 2, [])
        for name in ("analysis.tsv", "xcfc.tsv"):
            assert rows(os.path.join(a, name), name == "xcfc.tsv") == rows(os.path.join(b, name), name == "xcfc.tsv"), \
                "head-on %s differs on 2 ranks" % name
        print("2D cylindrical head-on (refined, regrid at 10), stage_metric = extrapolate: bit-identical on 1 and 2 ranks")

    _, p = star.run("refused", 2, ["MoL::max_iterations=2", "XCFC::extrapolation=hold"], expect_ok=False)
    assert p.returncode != 0 and "XCFC::stage_metric = extrapolate" in p.stdout and "XCFC::extrapolation" in p.stdout, \
        p.stdout[-2000:]
    print("stage_metric = extrapolate with extrapolation = hold refused (rc %d)" % p.returncode)


class Work:
    """What the modes get: the parsed arguments (each mode makes its own Runners)."""

    def __init__(self, a):
        self.a = a


def main():
    remnant_runs.main(Work, {"order": mode_order, "bits": mode_bits})


if __name__ == "__main__":
    main()
