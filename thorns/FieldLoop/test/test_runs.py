#!/usr/bin/python3
"""Whole runs of the field loop (face-centred B evolved through MoL) that test staggered IO:

  restart_np1 / restart_np2 / restart_1to2 / restart_2to1
      N+M iterations straight vs N, then recover for M on the same or another rank count: the TSV
      series of the magnetic energy and div B are bit-identical (raw faces in the checkpoint)
  moving
      a refined region following the loop (regrids): 1 rank, 2 ranks and a 1 -> 2 recovery give
      bit-identical TSV series
  grid_output
      HDF5 volume output of Bx, By: each cell holds the mean of its two faces, taken from the raw
      faces of a checkpoint at the same iteration (bit for bit), marked "cell average of face_x"
      in the XDMF and the dataset attribute; the raw faces have div B at round-off; edge-centred
      groups are refused
"""
import glob
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "framework", "test", "python"))
import remnant_runs  # noqa: E402

BASE = ["Grid::ncells=[32,32,1]", "Grid::block_size=[8,8,1]", "MoL::final_time=-1", "Flesh::timers=false",
        "FieldLoop::analysis_every=1", "IO::tsv_every=1", "IO::tsv_variables=[FieldLoop::b2,FieldLoop::divB]",
        "IO::tsv_reductions=[minimum,maximum,volume_integral]"]


def tsv_text(d):
    names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(d, "*.tsv")))
    assert names, "no TSV files in %s" % d
    return {n: open(os.path.join(d, n)).read() for n in names}


def mode_restart(r, np1, np2):
    straight, _ = r.run("straight", np1, ["MoL::max_iterations=20"])
    first, _ = r.run("restarted", np1, ["MoL::max_iterations=15", "IO::checkpoint_every=6"])
    _, p = r.run("restarted", np2, ["MoL::max_iterations=20", "IO::recover=auto"])
    assert "recovered from" in p.stdout and "it0000000012" in p.stdout, p.stdout
    a, b = tsv_text(straight), tsv_text(first)
    assert a.keys() == b.keys(), (a.keys(), b.keys())
    for n in a:
        assert a[n] == b[n], "%s differs between the straight and the recovered run" % n
    print("field loop restart %d -> %d ranks: %d TSV files bit-identical" % (np1, np2, len(a)))


def mode_moving(r):
    # Regrids every 4 iterations (new fine blocks prolonged, taking kept neighbours' faces, old ones
    # restricted, blocks moving between ranks): 1 and 2 ranks give the same bits, and a recovery
    # on 2 ranks from a 1-rank checkpoint continues them.
    moving = ["FieldLoop::refine_radius=0.45", "Grid::regrid_every=4", "MoL::max_iterations=30"]
    one, _ = r.run("np1", 1, moving)
    two, _ = r.run("np2", 2, moving)
    first, _ = r.run("restarted", 1, moving[:2] + ["MoL::max_iterations=22", "IO::checkpoint_every=10"])
    _, p = r.run("restarted", 2, moving + ["IO::recover=auto"])
    assert "recovered from" in p.stdout and "it0000000020" in p.stdout, p.stdout
    a, b, c = tsv_text(one), tsv_text(two), tsv_text(first)
    for n in a:
        assert a[n] == b[n], "%s differs between 1 and 2 ranks" % n
        assert a[n] == c[n], "%s differs after recovery on 2 ranks" % n
    div = [float(l.split("\t")[2]) for l in a["FieldLoop-divB.divB.maximum.tsv"].splitlines() if not l.startswith("#")]
    print("field loop with moving refinement: 1 rank, 2 ranks and 1 -> 2 recovery bit-identical; max div B %.2e" % max(div))


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def mode_grid_output(r):
    import h5py
    out, _ = r.run("out", 2, ["MoL::max_iterations=8", "IO::checkpoint_every=8", "IO::hdf5_every=8",
                              "IO::hdf5_variables=[FieldLoop::Bx,FieldLoop::By]", "IO::hdf5_output=[volume]"])
    ck = sorted(glob.glob(os.path.join(out, "checkpoints", "*.h5")))[-1]
    with h5py.File(ck) as c, h5py.File(os.path.join(out, "grid-volume.it%08d.h5" % 8)) as g:
        keys = [tuple(k) for k in c["mesh/blocks"][:]]
        n = 8
        checked = 0
        worst_div = 0.0
        for b, (level, idx) in enumerate(zip(g["blocks/level"][:], g["blocks/index"][:])):
            row = keys.index((level, idx[0], idx[1], idx[2]))
            bx = c["groups/FieldLoop::Bx"][row].reshape(n, n + 1)  # [j][i], n + 1 faces in x
            by = c["groups/FieldLoop::By"][row].reshape(n + 1, n)  # [j][i], n + 1 faces in y
            assert np.array_equal(g["data/FieldLoop-Bx.Bx"][b], 0.5 * (bx[:, :-1] + bx[:, 1:])), "Bx cell average"
            assert np.array_equal(g["data/FieldLoop-By.By"][b], 0.5 * (by[:-1, :] + by[1:, :])), "By cell average"
            dx = g["blocks/dx"][b]
            div = (bx[:, 1:] - bx[:, :-1]) / dx[0] + (by[1:, :] - by[:-1, :]) / dx[1]
            worst_div = max(worst_div, float(np.abs(div).max() * dx[0]))
            checked += 1
        scale = max(float(np.abs(c["groups/FieldLoop::Bx"][:]).max()), float(np.abs(c["groups/FieldLoop::By"][:]).max()))
        assert worst_div <= 1e-13 * scale, "div B of the checkpointed faces: %g (scale %g)" % (worst_div, scale)
        assert text(g["data/FieldLoop-Bx.Bx"].attrs["centering"]) == "cell average of face_x", \
            g["data/FieldLoop-Bx.Bx"].attrs["centering"]
        assert text(c["groups/FieldLoop::By"].attrs["centering"]) == "face_y"
    xmf_path = os.path.join(out, "grid-volume.it%08d.xmf" % 8)
    rc = subprocess.run([sys.executable, os.path.join(r.a.source_dir, "utils", "check_xdmf"), xmf_path])
    assert rc.returncode == 0, "check_xdmf failed on " + xmf_path
    xmf = open(xmf_path).read()
    assert '<Information Name="centering" Value="cell average of face_x"/>' in xmf, xmf[:2000]
    assert '<Information Name="centering" Value="cell average of face_y"/>' in xmf
    # Edge-centred groups have no cell-average output: refused with the parameter named.
    _, p = r.run("edges", 1, ["MoL::max_iterations=1", "IO::hdf5_every=1", "IO::hdf5_variables=[FieldLoop::Ez]"],
                 expect_ok=False)
    assert p.returncode != 0 and "IO::hdf5_variables: FieldLoop::Ez.Ez is edge_z-centred" in p.stdout, p.stdout[-2000:]
    print("field loop grid output: %d blocks hold the means of the checkpointed faces; max |div B| dx = %.2e "
          "(max |B| %.2e); XDMF and attributes say 'cell average of face_x/y'" % (checked, worst_div, scale))


def main():
    modes = {"restart_np1": lambda r: mode_restart(r, 1, 1), "restart_np2": lambda r: mode_restart(r, 2, 2),
             "restart_1to2": lambda r: mode_restart(r, 1, 2), "restart_2to1": lambda r: mode_restart(r, 2, 1),
             "grid_output": mode_grid_output, "moving": mode_moving}
    remnant_runs.main(
        lambda a: remnant_runs.Runner(a, os.path.join(a.source_dir, "parfiles", "field_loop_ct_example.yaml"), BASE), modes)


if __name__ == "__main__":
    main()
