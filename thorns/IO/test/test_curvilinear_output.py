#!/usr/bin/python3
"""A 2D grid file in cylindrical (R, z), spherical (r, theta) or Cartesian coordinates, written by
io_fake_output on 1 and 2 ranks, read back with h5py: the blocks are put together into the field
on the full domain and compared with f = R^2 + 3 z at the cell centres; the Cartesian node
positions (x = R, y = z for cylindrical; x = r sin(theta), y = r cos(theta) for spherical) and
the provenance are checked, and utils/check_xdmf validates the XDMF files."""
import argparse
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np


def reconstruct(path):
    """Field, centre coordinates and node positions on the full domain from a remnant-grid-1 file."""
    with h5py.File(path, "r") as f:
        assert f.attrs["format"] == b"remnant-grid-1" or f.attrs["format"] == "remnant-grid-1"
        n0, n1 = (int(x) for x in f.attrs["block_cells"])
        index = f["blocks/index"][:]
        names = {"cylindrical": ("R", "z"), "spherical": ("r", "theta"), "cartesian": ("x", "y")}
        coords = f.attrs["coordinates"]
        coords = coords.decode() if isinstance(coords, bytes) else coords
        a0, a1 = names[coords]
        nb0, nb1 = index[:, 0].max() + 1, index[:, 1].max() + 1
        field = np.full((nb1 * n1, nb0 * n0), np.nan)
        x0 = np.full(nb0 * n0, np.nan)
        x1 = np.full(nb1 * n1, np.nan)
        data = f["data/Test-f.f"][:]
        c0, c1 = f["coords/" + a0][:], f["coords/" + a1][:]
        nodes = f["cartesian_nodes"][:] if "cartesian_nodes" in f else None
        full_nodes = np.full((nb1 * n1 + 1, nb0 * n0 + 1, 2), np.nan)
        for b, (i, j, _) in enumerate(index):
            field[j * n1:(j + 1) * n1, i * n0:(i + 1) * n0] = data[b]
            x0[i * n0:(i + 1) * n0] = c0[b]
            x1[j * n1:(j + 1) * n1] = c1[b]
            if nodes is not None:
                full_nodes[j * n1:(j + 1) * n1 + 1, i * n0:(i + 1) * n0 + 1] = nodes[b]
        prov = f["provenance/parfile"][()]
        assert len(prov) > 0 and "git_revision" in f.attrs and "build_type" in f.attrs, "provenance missing"
        return coords, field, x0, x1, full_nodes if nodes is not None else None, f["blocks/lo"][:], f["blocks/dx"][:], index


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tool", required=True)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--coords", required=True)
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.work, ignore_errors=True)
    results = []
    for np_ in (1, 2):
        out = os.path.join(a.work, "np%d" % np_)
        subprocess.run([a.mpirun, "-np", str(np_), "--oversubscribe", a.tool, out, a.coords], check=True)
        coords, field, x0, x1, nodes, lo, dx, index = reconstruct(os.path.join(out, "grid-volume.it00000000.h5"))
        assert not np.isnan(field).any(), "blocks do not cover the domain"
        X0, X1 = np.meshgrid(x0, x1)
        exact = X0 ** 2 + 3 * X1
        err = np.abs(field - exact).max()
        assert err < 1e-13, "field differs from R^2 + 3 z by %g" % err
        # The full domain: R from 0 to 2 in 4 x 8 cells, the second direction in 3 x 6 cells.
        assert field.shape == (18, 32), field.shape
        assert abs(x0[0] - 2 / 64) < 1e-15 and abs(x0[-1] - (2 - 2 / 64)) < 1e-15
        if coords == "cartesian":
            assert nodes is None
        else:
            assert nodes is not None and not np.isnan(nodes).any()
            n0 = np.concatenate([[0.0], np.cumsum(np.full(32, 2 / 32))])
            lo1, hi1 = (0.0, np.pi) if coords == "spherical" else (-1.0, 1.0)
            n1 = lo1 + (hi1 - lo1) * np.arange(19) / 18
            N0, N1 = np.meshgrid(n0, n1)
            if coords == "cylindrical":
                want = np.stack([N0, N1], axis=-1)
            else:
                want = np.stack([N0 * np.sin(N1), N0 * np.cos(N1)], axis=-1)
            e = np.abs(nodes - want).max()
            assert e < 1e-13, "Cartesian nodes off by %g" % e
        rc = subprocess.run([sys.executable, os.path.join(a.source_dir, "utils", "check_xdmf"),
                             os.path.join(out, "grid-volume.it00000000.xmf"), os.path.join(out, "grid-volume.xmf")])
        assert rc.returncode == 0, "check_xdmf failed"
        results.append(field)
    assert np.array_equal(results[0], results[1]), "1-rank and 2-rank files differ"
    print("%s: the 2D field reconstructed on the full domain; XDMF valid; 1 and 2 ranks agree" % a.coords)


if __name__ == "__main__":
    main()
