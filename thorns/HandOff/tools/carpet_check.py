#!/usr/bin/python3
"""Independent checks of a hand-off of Einstein Toolkit CarpetIOHDF5 data (h5py and numpy only; no
Remnant code), used on real runs for thorns/HandOff/README.md and by the HandOff.command_line test.

  carpet_check.py sum FILE... [--iteration N] [--mirrors xyz] [--buffer-zones N]
      The 3D rest mass sum of sqrt(gamma) rho W dV over the data (HandOff's `source_rest_mass`):
      each component's own points (Carpet's `active` attribute, else the component less its
      cctk_nghostzones on faces with cctk_bbox = 0 when the file holds ghosts, less
      --buffer-zones on refined levels' outer faces), the finest level wins (a coarser point
      within half a finer spacing of a finer level's points is dropped), points on a mirror plane
      weigh half, points below it are dropped, and the sum is unfolded (x 2 per mirror). sqrt(gamma) from ADMBASE::gxx..gzz
      and W from HYDROBASE::vel where the files have them (else 1).
  carpet_check.py metric1d PROFILES ALP_X_ASC METRIC_X_ASC
      psi^4 and alpha of a hand-off's handoff_profiles.tsv against the run's own 1D CarpetIOASCII
      gxx and alp along x (iteration 0, finest level at each x) at the same radius: a spherically
      symmetric star in isotropic coordinates (TOVSolver: gxx = psi^4).
"""
import argparse
import glob
import re
import sys

import h5py
import numpy as np

NAME = re.compile(r"(\S+)::(\S+) it=(\d+) tl=0 (?:m=0 )?rl=(\d+)(?: c=(\d+))?$")
BOX = re.compile(r"\(\[(-?\d+),(-?\d+),(-?\d+)\]:\[(-?\d+),(-?\d+),(-?\d+)\]:\[(\d+),(\d+),(\d+)\]")
METRIC = ["gxx", "gxy", "gxz", "gyy", "gyz", "gzz"]


def ghosts_written(f, path):
    dump = ""
    if "Parameters and Global Attributes/All Parameters" in f:
        raw = f["Parameters and Global Attributes/All Parameters"][()]
        dump = (raw.tobytes() if hasattr(raw, "tobytes") else raw).decode(errors="replace").lower()
    key = "carpetiohdf5::out3d_ghosts" if ".xyz." in path else "carpetiohdf5::output_ghost_points"
    m = re.search(re.escape(key) + r"\s*=\s*\"?(\w+)", dump)
    return not (m and m.group(1) in ("no", "false", "0"))


def own_boxes(attrs, shape, ghosts, buffer_faces, buffer_zones):
    """Inclusive local index boxes of the component's own points (shape: x first; buffer_faces:
    the 6 faces on a refined level's edge, which lose buffer_zones more points)."""
    if "active" in attrs and "iorigin" in attrs:
        text = attrs["active"]
        text = text.decode() if isinstance(text, bytes) else str(text)
        io = np.array(attrs["iorigin"])
        boxes = []
        for b in BOX.findall(text):
            b = [int(x) for x in b]
            s = np.array(b[6:9])
            boxes.append((np.array(b[0:3]) // s - io, np.array(b[3:6]) // s - io))
        if boxes or "{}" in text:
            return boxes
    g = np.array(attrs["cctk_nghostzones"]) if ghosts and "cctk_nghostzones" in attrs else np.zeros(3, int)
    bb = np.array(attrs["cctk_bbox"]) if "cctk_bbox" in attrs else np.zeros(6, int)
    lo = np.array([0 if bb[2 * q] else g[q] + buffer_zones * buffer_faces[2 * q] for q in range(3)])
    hi = np.array([shape[q] - 1 - (0 if bb[2 * q + 1] else g[q] + buffer_zones * buffer_faces[2 * q + 1]) for q in range(3)])
    return [(lo, hi)]


def read(paths, iteration, buffer_zones):
    data = {}  # (var, rl, c) -> (origin, delta, array [i, j, k], boxes)
    its = {}
    for path in paths:
        with h5py.File(path, "r") as f:
            ghosts = ghosts_written(f, path)
            for name, d in f.items():
                m = NAME.match(name)
                if not m or not isinstance(d, h5py.Dataset):
                    continue
                var = m.group(2)
                its.setdefault(var, set()).add(int(m.group(3)))
                data[(var, int(m.group(3)), int(m.group(4)), int(m.group(5) or 0))] = (
                    np.array(d.attrs["origin"], float), np.array(d.attrs["delta"], float), d[()].T, dict(d.attrs), ghosts)
    if iteration < 0:
        iteration = max(set.intersection(*its.values()))
    coarsest = min(k[2] for k in data)
    ends = {}  # (var, rl) -> the level's lowest and highest coordinates
    for (var, it, rl, c), (o, h, a, attrs, ghosts) in data.items():
        if it == iteration:
            lo, hi = ends.get((var, rl), (o, o + h * (np.array(a.shape) - 1)))
            ends[(var, rl)] = (np.minimum(lo, o), np.maximum(hi, o + h * (np.array(a.shape) - 1)))
    out = {}
    for (var, it, rl, c), (o, h, a, attrs, ghosts) in data.items():
        if it == iteration:
            lo, hi = ends[(var, rl)]
            top = o + h * (np.array(a.shape) - 1)
            faces = [rl != coarsest and abs((o if side == 0 else top)[q] - (lo if side == 0 else hi)[q]) < 1e-6 * h[q]
                     for q in range(3) for side in (0, 1)]
            out[(var, rl, c)] = (o, h, a, own_boxes(attrs, a.shape, ghosts, faces, buffer_zones))
    return iteration, out


def rest_mass(paths, iteration, mirrors, buffer_zones):
    iteration, comps = read(paths, iteration, buffer_zones)
    rho = {k[1:]: v for k, v in comps.items() if k[0] == "rho"}
    finest = max(rl for rl, _ in rho)
    total = 0.0
    for (rl, c), (o, h, a, boxes) in rho.items():
        for lo, hi in boxes:
            sl = tuple(slice(lo[q], hi[q] + 1) for q in range(3))
            X = np.meshgrid(*[o[q] + h[q] * np.arange(lo[q], hi[q] + 1) for q in range(3)], indexing="ij")
            dens = a[sl].copy()
            if all((n, rl, c) in comps for n in METRIC):
                g = {n: comps[(n, rl, c)][2][sl] for n in METRIC}
                det = (g["gxx"] * (g["gyy"] * g["gzz"] - g["gyz"] ** 2) - g["gxy"] * (g["gxy"] * g["gzz"] - g["gyz"] * g["gxz"])
                       + g["gxz"] * (g["gxy"] * g["gyz"] - g["gyy"] * g["gxz"]))
                dens *= np.sqrt(det)
                if all((f"vel[{q}]", rl, c) in comps for q in range(3)):
                    v = [comps[(f"vel[{q}]", rl, c)][2][sl] for q in range(3)]
                    gm = [[g["gxx"], g["gxy"], g["gxz"]], [g["gxy"], g["gyy"], g["gyz"]], [g["gxz"], g["gyz"], g["gzz"]]]
                    v2 = sum(gm[p][q] * v[p] * v[q] for p in range(3) for q in range(3))
                    dens /= np.sqrt(1 - v2)
            keep = np.ones(dens.shape, bool)
            for (r2, c2), (o2, h2, a2, boxes2) in rho.items():
                if r2 <= rl:
                    continue
                for lo2, hi2 in boxes2:
                    inside = np.ones(dens.shape, bool)
                    for q in range(3):
                        inside &= (X[q] >= o2[q] + (lo2[q] - 0.5) * h2[q]) & (X[q] <= o2[q] + (hi2[q] + 0.5) * h2[q])
                    keep &= ~inside
            w = np.full(dens.shape, np.prod(h))
            for q in range(3):
                if mirrors[q]:  # symmetry points below the plane are the mirror's images
                    w[np.abs(X[q]) < 1e-9 * h[q]] *= 0.5
                    keep &= X[q] > -1e-9 * h[q]
            total += (w * dens)[keep].sum()
    return iteration, total * 2 ** sum(mirrors), finest


def etk_line(path):
    best = {}
    for line in open(path):
        f = line.split()
        if not f or line.startswith("#") or int(f[0]) != 0 or float(f[9]) < 0:
            continue
        x, rl = float(f[9]), int(f[2])
        if x not in best or rl > best[x][0]:
            best[x] = (rl, float(f[12]))
    xs = np.array(sorted(best))
    return xs, np.array([best[x][1] for x in xs])


def lagrange(xs, ys, r):
    i = int(np.clip(np.searchsorted(xs, r) - 2, 0, len(xs) - 4))
    X, Y = xs[i:i + 4], ys[i:i + 4]
    return sum(Y[a] * np.prod([(r - X[b]) / (X[a] - X[b]) for b in range(4) if b != a]) for a in range(4))


def metric1d(profiles, alp_asc, metric_asc):
    xa, alp = etk_line(alp_asc)
    xg, gxx = etk_line(metric_asc)
    P = np.loadtxt(profiles)  # line coordinate x y z rho_3d rho gamma13_3d psi4 alpha_3d alpha
    P = P[P[:, 6] > 1e-3 * P[:, 6].max()]
    for line in (0, 1):
        Q = P[P[:, 0] == line]
        r = np.sqrt(Q[:, 2] ** 2 + Q[:, 3] ** 2 + Q[:, 4] ** 2)
        g = np.array([lagrange(xg, gxx, q) for q in r])
        a = np.array([lagrange(xa, alp, q) for q in r])
        print(f"line {line}: {len(Q)} cells with rho > 1e-3 rho_max: max |psi^4 / gxx - 1| = {np.abs(Q[:, 8] / g - 1).max():.3e}, "
              f"max |alpha / alp - 1| = {np.abs(Q[:, 10] / a - 1).max():.3e}")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("sum")
    s.add_argument("files", nargs="+")
    s.add_argument("--iteration", type=int, default=-1)
    s.add_argument("--mirrors", default="")
    s.add_argument("--buffer-zones", type=int, default=0)
    m = sub.add_parser("metric1d")
    m.add_argument("profiles")
    m.add_argument("alp_x")
    m.add_argument("metric_x")
    a = ap.parse_args()
    if a.cmd == "sum":
        paths = sorted({p for pat in a.files for p in glob.glob(pat)})
        if not paths:
            sys.exit(f"carpet_check.py: no file matches {a.files}")
        it, m0, finest = rest_mass(paths, a.iteration, [c in a.mirrors for c in "xyz"], a.buffer_zones)
        print(f"iteration {it}: 3D rest mass {m0:.15g} ({finest + 1} levels)")
    else:
        metric1d(a.profiles, a.alp_x, a.metric_x)


if __name__ == "__main__":
    main()
