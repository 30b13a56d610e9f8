#!/usr/bin/python3
"""Whole runs of the remnant executable that test IO (CTest label IO):

  restart_np1 / restart_np2   N+M iterations straight vs N, then recover for M: TSV bit-identical
  restart_1to2 / restart_2to1 the same, recovering on another rank count: within 1e-14 relative
  kill       SIGKILL in the middle of writing a checkpoint (IO::test_kill_at_checkpoint); the
             previous checkpoint is used by IO::recover = auto and the continuation is bit-identical
  corrupt    a flipped byte in the data of the newest checkpoint: reported, the previous one used
  truncate   the newest checkpoint cut in half: reported, the previous one used
  walltime   a run ended by MoL::max_walltime_hours leaves a final checkpoint that continues exactly
  params     recovering with a changed steerable: never parameter is an error naming it
  metadata   damaged scalar metadata of the newest checkpoint (iteration sign bit, iteration -5, a
             bit of the time, time 1e10): rejected by name, the previous one used, every TSV row
             and grid file of the first run kept, the continuation bit-identical
  mesh       a damaged mesh/blocks entry: rejected by name, the previous one used
  renamed    a copy of checkpoint 4 named it18 beside a valid 12: rejected (stored iteration 4),
             12 used, and with checkpoint_keep = 1 the new 16 is kept (the copy counts for nothing); IO::recover = <an HDF5 file that is no checkpoint>: "not a Remnant checkpoint"
  ckdir      an IO::checkpoint_dir that cannot be created stops the run before any output changes
  sparse_error  a quantity computed every 8 steps (WaveToy::wave_error) but written every step:
             the rows after the recovered iteration are bit-identical to a straight run's
  grid_output  HDF5 volume/slices/lines on 1 and 2 ranks: utils/check_xdmf, h5py consistency
  plots      utils/plot_timeseries and utils/plot_slice make PNG files
"""
import glob
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "framework", "test", "python"))
import remnant_runs  # noqa: E402

BASE = ["Grid::ncells=[16,16,16]", "Grid::block_size=[8,8,8]", "MoL::final_time=-1",
        "Grid::boundary_lower=[periodic,periodic,reflect]", "Grid::boundary_upper=[periodic,periodic,outflow]",
        "WaveToy::initial_data=gaussian", "WaveToy::gaussian_center=[0.5,0.5,0.3]",
        "IO::tsv_every=1", "IO::tsv_variables=[WaveToy::wave]",
        "IO::tsv_reductions=[minimum,maximum,sum,volume_integral,norm1,norm2,centre]",
        "IO::centre=[0.5,0.5,0.5]", "Flesh::timers=false"]


def tsv_files(d):
    return sorted(os.path.basename(p) for p in glob.glob(os.path.join(d, "*.tsv")))


def compare_tsv(a, b, rel):
    names = tsv_files(a)
    assert names and names == tsv_files(b), "different TSV files: %s vs %s" % (names, tsv_files(b))
    worst = 0.0
    for n in names:
        ta, tb = open(os.path.join(a, n)).read(), open(os.path.join(b, n)).read()
        if rel == 0:
            assert ta == tb, "%s differs between %s and %s" % (n, a, b)
            continue
        la = [l for l in ta.splitlines() if not l.startswith("#")]
        lb = [l for l in tb.splitlines() if not l.startswith("#")]
        assert len(la) == len(lb), "%s: %d vs %d rows" % (n, len(la), len(lb))
        for x, y in zip(la, lb):
            xa, ya = x.split("\t"), y.split("\t")
            assert xa[0] == ya[0], "%s: iterations differ: %s vs %s" % (n, x, y)
            for u, v in zip(xa[1:], ya[1:]):
                u, v = float(u), float(v)
                d = abs(u - v) / max(abs(u), abs(v), 1e-300) if u != v else 0.0
                worst = max(worst, d)
                assert d <= rel, "%s: %r vs %r (relative %g > %g)" % (n, u, v, d, rel)
    return len(names), worst


def straight_and_first(r, np_first, n_total, n_first, extra_first):
    straight, _ = r.run("straight", np_first, ["MoL::max_iterations=%d" % n_total])
    first, _ = r.run("restarted", np_first, ["MoL::max_iterations=%d" % n_first] + extra_first, expect_ok=False)
    return straight, first


def mode_restart(r, np1, np2):
    # The first run checkpoints at 6 and 12 and goes on to 15: rows 13-15 must be dropped.
    straight, first = straight_and_first(r, np1, 20, 15, ["IO::checkpoint_every=6"])
    _, p = r.run("restarted", np2, ["MoL::max_iterations=20", "IO::recover=auto"])
    assert "recovered from" in p.stdout and "it0000000012" in p.stdout, p.stdout
    rel = 0.0 if np1 == np2 else 1e-14
    n, worst = compare_tsv(straight, first, rel)
    print("restart %d -> %d ranks: %d TSV files agree (worst relative difference %g)" % (np1, np2, n, worst))


def checkpoint_dir(d):
    return os.path.join(d, "checkpoints")


def mode_kill(r):
    straight, _ = r.run("straight", 2, ["MoL::max_iterations=20"])
    out, p = r.run("restarted", 2, ["MoL::max_iterations=20", "IO::checkpoint_every=4", "IO::checkpoint_keep=5",
                                    "IO::test_kill_at_checkpoint=12"], expect_ok=False)
    assert p.returncode != 0, "the run was not killed"
    ck = sorted(os.listdir(checkpoint_dir(out)))
    assert "checkpoint.it0000000012.h5.tmp" in ck, ck
    assert "checkpoint.it0000000012.h5" not in ck, ck
    assert "checkpoint.it0000000008.h5" in ck, ck
    _, p = r.run("restarted", 2, ["MoL::max_iterations=20", "IO::recover=auto", "IO::checkpoint_every=4"])
    assert "recovered from" in p.stdout and "it0000000008.h5 at iteration 8" in p.stdout, p.stdout
    n, _ = compare_tsv(straight, out, 0.0)
    print("killed while writing checkpoint 12 (left %s); recovered from 8; %d TSV files bit-identical" % (ck, n))


def damage_and_recover(r, how):
    straight, _ = r.run("straight", 1, ["MoL::max_iterations=16"])
    out, _ = r.run("restarted", 1, ["MoL::max_iterations=12", "IO::checkpoint_every=4", "IO::checkpoint_keep=3"])
    newest = os.path.join(checkpoint_dir(out), "checkpoint.it0000000012.h5")
    if how == "corrupt":
        import h5py
        with h5py.File(newest, "r") as f:
            ds = f["groups/WaveToy::wave"]
            offset = ds.id.get_offset() + ds.id.get_storage_size() // 2
        with open(newest, "r+b") as f:
            f.seek(offset)
            b = f.read(1)
            f.seek(offset)
            f.write(bytes([b[0] ^ 0x10]))
        unseal(newest)
        expect = "does not match its checksum"
    else:
        size = os.path.getsize(newest)
        with open(newest, "r+b") as f:
            f.truncate(size // 2)
        expect = "unusable"
    _, p = r.run("restarted", 2, ["MoL::max_iterations=16", "IO::recover=auto"])
    assert "checkpoint.it0000000012.h5 is unusable" in p.stdout and expect in p.stdout, p.stdout
    assert "recovered from" in p.stdout and "it0000000008.h5 at iteration 8" in p.stdout, p.stdout
    n, worst = compare_tsv(straight, out, 1e-14)
    msg = [l for l in p.stdout.splitlines() if "unusable" in l][0]
    print("%s: reported as '%s'; recovered from 8 on 2 ranks; %d TSV files agree (worst %g)" % (how, msg.strip(), n, worst))


def mode_walltime(r):
    out, p = r.run("restarted", 1, ["MoL::max_iterations=100000", "MoL::max_walltime_hours=2e-6"])
    assert "max_walltime_hours" in p.stdout, p.stdout
    ck = sorted(glob.glob(os.path.join(checkpoint_dir(out), "checkpoint.it*.h5")))
    assert ck, "no final checkpoint after the wall-clock limit"
    last = int(os.path.basename(ck[-1])[13:23])
    rows = [l for l in open(os.path.join(out, "WaveToy-wave.u.norm2.tsv")) if not l.startswith("#")]
    assert int(rows[-1].split("\t")[0]) == last, "the final checkpoint is not at the last iteration"
    straight, _ = r.run("straight", 1, ["MoL::max_iterations=%d" % (last + 5)])
    r.run("restarted", 1, ["MoL::max_iterations=%d" % (last + 5), "IO::recover=auto"])
    n, _ = compare_tsv(straight, out, 0.0)
    print("wall-clock limit ended the run at iteration %d with a checkpoint; continuation bit-identical (%d files)" % (last, n))


def mode_params(r):
    out, _ = r.run("restarted", 1, ["MoL::max_iterations=4", "IO::checkpoint_every=4"])
    _, p = r.run("restarted", 1, ["MoL::max_iterations=8", "IO::recover=auto", "Grid::ncells=[16,16,32]"], expect_ok=False)
    assert p.returncode != 0 and "steerable: never" in p.stdout and "Grid::ncells" in p.stdout, p.stdout
    _, p = r.run("restarted", 1, ["MoL::max_iterations=8", "IO::recover=auto", "MoL::cfl=0.3"])
    assert "MoL::cfl" in p.stdout and "recovered from" in p.stdout, p.stdout
    _, p = r.run("restarted", 1, ["MoL::max_iterations=10", "IO::recover=" + os.path.join(out, "nonexistent.h5")],
                 expect_ok=False)
    assert p.returncode != 0 and "no checkpoint file" in p.stdout, p.stdout
    print("a changed Grid::ncells stops the recovery naming it; MoL::cfl (steerable: recover) may change")


def first_run_with_checkpoints(r):
    """A straight run to 16 and a first run to 12 with checkpoints at 4, 8, 12 and grid output
    every 4 iterations; returns (straight, first)."""
    grid = ["IO::hdf5_every=4", "IO::hdf5_variables=[WaveToy::wave.u]", "IO::hdf5_output=[volume]"]
    straight, _ = r.run("straight", 1, ["MoL::max_iterations=16"] + grid)
    first, _ = r.run("first", 1, ["MoL::max_iterations=12", "IO::checkpoint_every=4", "IO::checkpoint_keep=5"] + grid)
    return straight, first, grid


def copy_of(r, first, name):
    import shutil
    out = os.path.join(r.a.work, name)
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(first, out)
    return out


def output_lines(d):
    """Every line of every TSV file and the names of the grid files in folder d."""
    lines = {n: open(os.path.join(d, n)).read().splitlines() for n in tsv_files(d)}
    grids = sorted(os.path.basename(p) for p in glob.glob(os.path.join(d, "grid-*.it*")))
    return lines, grids


def recover_rejecting(r, straight, first, grid, name, damage, expect):
    """Damages checkpoint 12 of a copy of `first`; the continuation to 16 must reject it by name,
    recover from 8, keep every earlier row and grid file, and end bit-identical to `straight`."""
    out = copy_of(r, first, name)
    newest = os.path.join(checkpoint_dir(out), "checkpoint.it0000000012.h5")
    damage(newest)
    before_lines, before_grids = output_lines(out)
    _, p = r.run(name, 1, ["MoL::max_iterations=16", "IO::recover=auto", "IO::checkpoint_every=4",
                           "IO::checkpoint_keep=5"] + grid)
    assert p.returncode == 0, p.stdout
    assert "checkpoint.it0000000012.h5 is unusable" in p.stdout and expect in p.stdout, p.stdout
    assert "it0000000008.h5 at iteration 8" in p.stdout, p.stdout
    after_lines, after_grids = output_lines(out)
    for n, lines in before_lines.items():
        kept = [l for l in lines if l.startswith("#") or int(l.split("\t")[0]) <= 8]
        assert after_lines[n][:len(kept)] == kept, "%s lost rows of iterations <= 8" % n
    assert set(g for g in before_grids if int(g.split(".it")[1][:8]) <= 8) <= set(after_grids), (before_grids, after_grids)
    assert len(glob.glob(os.path.join(checkpoint_dir(out), "checkpoint.it*.h5"))) <= 5
    compare_tsv(straight, out, 0.0)
    msg = [l for l in p.stdout.splitlines() if "unusable" in l][0]
    print("%s: %s; recovered from 8; outputs kept, continuation bit-identical" % (name, msg.split("unusable: ")[1]))


def unseal(path):
    """Clears the file seal in the HDF5 user block, as in a checkpoint written before seals existed:
    the seal would reject any damage first (CheckpointRecovery.* covers that), so the damage tests
    here remove it to reach the metadata and data checksums behind it."""
    with open(path, "r+b") as f:
        f.write(b"\0" * 32)


def set_attr(name, value):
    def damage(path):
        import h5py
        with h5py.File(path, "r+") as f:
            old = f.attrs[name]
            f.attrs.modify(name, np.array(value(np.asarray(old).reshape(-1)[0]), dtype=np.asarray(old).dtype).reshape(np.shape(old)))
        unseal(path)
    return damage


def flip_bit(v, bit):
    a = np.array([v])
    return (a.view(np.uint64) ^ np.uint64(1 << bit)).view(a.dtype)[0]


def mode_metadata(r):
    straight, first, grid = first_run_with_checkpoints(r)
    # The sign-flipped iteration comes last: before the fix that run would go on for 2^63 steps.
    cases = [("iteration_minus5", set_attr("iteration", lambda v: -5)),
             ("time_bit", set_attr("time", lambda v: flip_bit(v, 52))),
             ("time_1e10", set_attr("time", lambda v: 1e10)),
             ("iteration_sign", set_attr("iteration", lambda v: flip_bit(v, 63)))]
    for name, damage in cases:
        recover_rejecting(r, straight, first, grid, name, damage, "do not match their checksum")


def mode_mesh(r):
    import h5py
    straight, first, grid = first_run_with_checkpoints(r)

    def damage(path):
        with h5py.File(path, "r+") as f:
            b = f["mesh/blocks"][:]
            b[1, 1] = 99
            f["mesh/blocks"][:] = b
        unseal(path)
    recover_rejecting(r, straight, first, grid, "mesh", damage, "do not match their checksum")


def mode_renamed(r):
    import shutil
    straight, first, grid = first_run_with_checkpoints(r)
    ck = checkpoint_dir(first)
    shutil.copy(os.path.join(ck, "checkpoint.it0000000004.h5"), os.path.join(ck, "checkpoint.it0000000018.h5"))
    _, p = r.run("first", 1, ["MoL::max_iterations=16", "IO::recover=auto", "IO::checkpoint_every=4",
                              "IO::checkpoint_keep=1"] + grid)
    assert "checkpoint.it0000000018.h5 is unusable: its stored iteration 4 is not the 18 of its file name" in p.stdout, p.stdout
    assert "it0000000012.h5 at iteration 12" in p.stdout, p.stdout
    compare_tsv(straight, first, 0.0)
    # keep = 1: the newest one written (16) survives; the rejected copy counts for nothing.
    left = sorted(os.listdir(ck))
    assert left == ["checkpoint.it0000000016.h5", "checkpoint.it0000000018.h5"], left
    not_a_checkpoint = os.path.join(first, "grid-volume.it00000004.h5")
    _, p = r.run("other", 1, ["MoL::max_iterations=16", "IO::recover=" + not_a_checkpoint], expect_ok=False)
    assert p.returncode != 0 and "grid-volume.it00000004.h5 is unusable: it is not a Remnant checkpoint" in p.stdout, p.stdout
    print("a copy of checkpoint 4 named it18 is rejected (stored iteration 4), 12 used; an output file given to "
          "IO::recover: not a Remnant checkpoint")


def mode_ckdir(r):
    out, _ = r.run("ckdir", 1, ["MoL::max_iterations=12"])
    before = output_lines(out)
    blocker = os.path.join(r.a.work, "a_file")
    open(blocker, "w").write("x")
    for bad in (os.path.join(blocker, "checkpoints"), "/proc/remnant_checkpoints"):
        _, p = r.run("ckdir", 1, ["MoL::max_iterations=4", "IO::checkpoint_every=4", "IO::checkpoint_dir=" + bad],
                     expect_ok=False)
        assert p.returncode != 0 and "IO::checkpoint_dir" in p.stdout and bad in p.stdout, p.stdout
        assert output_lines(out) == before, "outputs changed before the checkpoint folder was found unusable"
        print("IO::checkpoint_dir=%s: %s" % (bad, [l for l in p.stdout.splitlines() if "checkpoint_dir" in l][0][:160]))


def mode_sparse_error(r):
    wave = ["WaveToy::initial_data=plane_wave", "WaveToy::wave_numbers=[1,1,1]", "WaveToy::error_every=8",
            "IO::tsv_variables=[WaveToy::wave,WaveToy::wave_error]"]
    straight, _ = r.run("straight", 1, ["MoL::max_iterations=20"] + wave)
    out, _ = r.run("restarted", 1, ["MoL::max_iterations=15", "IO::checkpoint_every=12"] + wave)
    _, p = r.run("restarted", 1, ["MoL::max_iterations=20", "IO::recover=auto"] + wave)
    assert "it0000000012.h5 at iteration 12" in p.stdout, p.stdout
    n, _ = compare_tsv(straight, out, 0.0)
    print("wave_error computed every 8 steps, written every step: %d TSV files bit-identical after recovery at 12" % n)


def mode_grid_output(r):
    import h5py
    args = ["MoL::max_iterations=10", "IO::hdf5_every=5", "IO::hdf5_variables=[WaveToy::wave]",
            "IO::hdf5_output=[volume,slice_xy,slice_xz,slice_yz,line_x,line_y,line_z]", "IO::slice_point=[0.3,0.6,0.1]"]
    outs = {}
    for np_ in (1, 2):
        out, _ = r.run("np%d" % np_, np_, args)
        outs[np_] = out
        xmfs = sorted(glob.glob(os.path.join(out, "*.xmf")))
        assert len(xmfs) == 4 * 3 + 4, xmfs
        rc = subprocess.run([sys.executable, os.path.join(r.a.source_dir, "utils", "check_xdmf")] + xmfs)
        assert rc.returncode == 0, "check_xdmf failed"
    for it in (0, 5, 10):
        name = "grid-volume.it%08d.h5" % it
        with h5py.File(os.path.join(outs[1], name)) as f1, h5py.File(os.path.join(outs[2], name)) as f2:
            for k in ("data/WaveToy-wave.u", "data/WaveToy-wave.rho", "coords/x", "blocks/index"):
                assert np.array_equal(f1[k][:], f2[k][:]), "%s %s differs between 1 and 2 ranks" % (name, k)
            for k in ("provenance/parfile", "provenance/thorns"):
                assert len(f1[k][()]) > 0
            assert f1.attrs["git_revision"] and f1.attrs["build_type"] is not None
            assert f1["data/WaveToy-wave.u"].attrs["nan_count"] == 0
            # Volume as one 16^3 array [z][y][x] from its 8 blocks.
            u = np.full((16, 16, 16), np.nan)
            for b, (i, j, k) in enumerate(f1["blocks/index"][:]):
                u[8 * k:8 * k + 8, 8 * j:8 * j + 8, 8 * i:8 * i + 8] = f1["data/WaveToy-wave.u"][b]
            assert not np.isnan(u).any()
        # x = 0.3 -> cell 4, y = 0.6 -> cell 9, z = 0.1 -> cell 1 (16 cells on [0, 1]).
        with h5py.File(os.path.join(outs[2], "grid-slice_xy.it%08d.h5" % it)) as f:
            s = np.full((16, 16), np.nan)
            for b, (i, j, _) in enumerate(f["blocks/index"][:]):
                s[8 * j:8 * j + 8, 8 * i:8 * i + 8] = f["data/WaveToy-wave.u"][b]
            assert np.array_equal(s, u[1]), "slice_xy is not the z = 0.1 plane of the volume"
            assert abs(f["blocks/fixed"][0][2] - 1.5 / 16) < 1e-15
        with h5py.File(os.path.join(outs[2], "grid-line_y.it%08d.h5" % it)) as f:
            order = np.argsort(f["coords/y"][:, 0])
            line = np.concatenate([f["data/WaveToy-wave.u"][b] for b in order])
            assert np.array_equal(line, u[1, :, 4]), "line_y is not the row x = 0.3, z = 0.1 of the volume"
    # Output by simulation time: one file whenever t crosses a multiple of 0.05.
    out, p = r.run("by_time", 1, ["MoL::max_iterations=12", "IO::hdf5_every_time=0.05",
                                  "IO::hdf5_variables=[WaveToy::wave.u]", "IO::hdf5_output=[volume]"])
    its = sorted(int(os.path.basename(x).split(".it")[1][:8]) for x in glob.glob(os.path.join(out, "grid-volume.it*.h5")))
    times = {}
    for l in open(os.path.join(out, "WaveToy-wave.u.norm2.tsv")):
        if not l.startswith("#"):
            t = l.split("\t")
            times[int(t[0])] = float(t[1])
    want = [0] + [i for i in range(1, 13) if int(times[i] / 0.05 + 1e-9) > int(times[i - 1] / 0.05 + 1e-9)]
    assert its == want, "outputs at %s, expected %s" % (its, want)
    print("grid output: %d XDMF files valid on 1 and 2 ranks; volume identical; slices and lines match the volume;"
          " time-based output at iterations %s" % (len(xmfs), its))


def mode_plots(r):
    out, _ = r.run("np2", 2, ["MoL::max_iterations=6", "IO::hdf5_every=6", "IO::hdf5_variables=[WaveToy::wave]",
                              "IO::hdf5_output=[volume,slice_xy,line_x]"])
    py = sys.executable
    u = os.path.join(r.a.source_dir, "utils")
    png = os.path.join(r.a.work, "ts.png")
    subprocess.run([py, os.path.join(u, "plot_timeseries"), "-o", png,
                    os.path.join(out, "WaveToy-wave.u.norm2.tsv"), os.path.join(out, "WaveToy-wave.u.maximum.tsv")], check=True)
    assert os.path.getsize(png) > 1000
    for f, var in (("grid-slice_xy.it00000006.h5", "WaveToy-wave.u"), ("grid-line_x.it00000006.h5", "WaveToy-wave.rho"),
                   ("grid-volume.it00000006.h5", "WaveToy-wave.u")):
        png = os.path.join(r.a.work, f + ".png")
        subprocess.run([py, os.path.join(u, "plot_slice"), os.path.join(out, f), "--var", var, "-o", png], check=True)
        assert os.path.getsize(png) > 1000, png
    print("plot_timeseries and plot_slice wrote PNG files")


def main():
    modes = {
        "restart_np1": lambda r: mode_restart(r, 1, 1), "restart_np2": lambda r: mode_restart(r, 2, 2),
        "restart_1to2": lambda r: mode_restart(r, 1, 2), "restart_2to1": lambda r: mode_restart(r, 2, 1),
        "kill": mode_kill, "corrupt": lambda r: damage_and_recover(r, "corrupt"),
        "truncate": lambda r: damage_and_recover(r, "truncate"), "walltime": mode_walltime,
        "params": mode_params, "grid_output": mode_grid_output, "plots": mode_plots, "metadata": mode_metadata,
        "mesh": mode_mesh, "renamed": mode_renamed, "ckdir": mode_ckdir, "sparse_error": mode_sparse_error,
    }
    remnant_runs.main(
        lambda a: remnant_runs.Runner(a, os.path.join(a.source_dir, "parfiles", "wavetoy_3d.yaml"), BASE), modes)


if __name__ == "__main__":
    main()
