#!/usr/bin/python3
"""A real 2D cylindrical (R, z) simulation's HDF5 output read back with h5py: the blocks are put
together into the field on the full domain, which must cover it without gaps, match the
coordinates of a uniform (R, z) mesh, give the run's own TSV volume integral (the exact cylindrical
cell volumes 2 pi R dR dz) to round-off, peak where the initial bump sits, and map to Cartesian
nodes x = R, y = z. utils/check_xdmf validates the XDMF file. Runs on 1 and 2 ranks; the files
must hold the same field."""
import argparse
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np


def reconstruct(path):
    with h5py.File(path, "r") as f:
        assert f.attrs["coordinates"] in (b"cylindrical", "cylindrical")
        n0, n1 = (int(x) for x in f.attrs["block_cells"])
        index = f["blocks/index"][:]
        nb0, nb1 = index[:, 0].max() + 1, index[:, 1].max() + 1
        field = np.full((nb1 * n1, nb0 * n0), np.nan)
        R = np.full(nb0 * n0 + 1, np.nan)
        z = np.full(nb1 * n1 + 1, np.nan)
        nodes = np.full((nb1 * n1 + 1, nb0 * n0 + 1, 2), np.nan)
        data = f["data/Advection-u.u"][:]
        for b, (i, j, _) in enumerate(index):
            field[j * n1:(j + 1) * n1, i * n0:(i + 1) * n0] = data[b]
            R[i * n0:(i + 1) * n0 + 1] = f["coords/R_nodes"][b]
            z[j * n1:(j + 1) * n1 + 1] = f["coords/z_nodes"][b]
            nodes[j * n1:(j + 1) * n1 + 1, i * n0:(i + 1) * n0 + 1] = f["cartesian_nodes"][b]
        assert len(f["provenance/parfile"][()]) > 0
    return field, R, z, nodes


def tsv_value(path, iteration):
    for line in open(path):
        if line.startswith("#"):
            continue
        cols = line.split()
        if int(cols[0]) == iteration:
            return float(cols[2])
    raise AssertionError("iteration %d not in %s" % (iteration, path))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--mpirun", default="mpirun")
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    parfile = os.path.join(a.source_dir, "parfiles", "advection_cylindrical_2d.yaml")
    fields = []
    for np_ in (1, 2):
        out = os.path.join(a.work, "np%d" % np_)
        cmd = [a.exe, parfile, "Flesh::out_dir=" + out, "Grid::max_level=0", "Grid::regions=[]",
               "Grid::region_levels=[]", "Grid::region_bounds=[]", "MoL::max_iterations=0",
               "IO::hdf5_every=1", "IO::hdf5_variables=[Advection::u]"]
        if np_ > 1:
            cmd = [a.mpirun, "-np", str(np_), "--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else []) + cmd
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        field, R, z, nodes = reconstruct(os.path.join(out, "grid-volume.it00000000.h5"))
        assert not np.isnan(field).any(), "the blocks do not cover the domain"
        assert np.allclose(R, np.linspace(0, 1, R.size), atol=1e-14), "R nodes are not the uniform mesh"
        assert np.allclose(z, np.linspace(-1, 1, z.size), atol=1e-14), "z nodes are not the uniform mesh"
        assert np.array_equal(nodes[..., 0], np.broadcast_to(R, nodes[..., 0].shape)), "x != R"
        assert np.array_equal(nodes[..., 1], np.broadcast_to(z[:, None], nodes[..., 1].shape)), "y != z"
        # The volume integral over the full domain, with exact cylindrical cell volumes.
        vol = np.pi * np.outer(np.diff(z), R[1:] ** 2 - R[:-1] ** 2)
        total = float(np.sum(field * vol))
        ref = tsv_value(os.path.join(out, "Advection-u.u.volume_integral.tsv"), 0)
        rel = abs(total - ref) / abs(ref)
        print("np=%d: %d x %d cells, volume integral %.16e (TSV %.16e, rel. diff %.1e)" %
              (np_, field.shape[1], field.shape[0], total, ref, rel))
        assert rel < 1e-13, "field rebuilt from HDF5 disagrees with the run's volume integral"
        # The bump sits on the axis at z = -0.3 (profile_center of the parfile).
        j, i = np.unravel_index(np.argmax(field), field.shape)
        zc = 0.5 * (z[j] + z[j + 1])
        assert i == 0 and abs(zc + 0.3) <= (z[1] - z[0]), "maximum at R index %d, z = %g" % (i, zc)
        subprocess.run([sys.executable, os.path.join(a.source_dir, "utils", "check_xdmf"),
                        os.path.join(out, "grid-volume.it00000000.xmf")], check=True, stdout=subprocess.DEVNULL)
        fields.append(field)
    assert np.array_equal(fields[0], fields[1]), "1-rank and 2-rank outputs differ"
    print("1 passed, 0 failed")


if __name__ == "__main__":
    main()
