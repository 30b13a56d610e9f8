#!/usr/bin/env python3
"""Compares the star's evolution in several runs from their Analysis TSVs (issue 17: the 3D Cartesian
run of the uniformly rotating star against the 2D cylindrical one).

  compare_evolutions.py [--t-max T] REF.tsv RUN.tsv [RUN.tsv ...]

For each run: rho_c, J and the rest mass relative to their t = 0 values at the end (t_end, or the
largest time all runs reach, or T), their largest drift, and, for every run after the first, the
largest difference from REF of rho_c(t)/rho_c(0), J(t)/J(0), M_0(t)/M_0(0), REF interpolated
linearly to the run's times (the runs' time steps differ). Plain Python, no packages.
Exit 1 with a message naming the file on a missing file, column or an empty table."""
import sys

COLUMNS = ("time", "rho_c", "J", "rest_mass")


def fail(msg):
    sys.stderr.write("compare_evolutions: error: " + msg + "\n")
    sys.exit(1)


def read_tsv(path):
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        fail(f"{path}: cannot read ({e.strerror})")
    header = None
    rows = []
    for n, line in enumerate(lines, 1):
        if not line.strip():
            continue
        if line.startswith("#"):
            header = line.lstrip("#").split()
            continue
        if header is None:
            fail(f"{path}:{n}: data before the '# iteration time ...' header")
        fields = line.split()
        try:
            rows.append({c: float(fields[header.index(c)]) for c in COLUMNS})
        except ValueError:
            missing = [c for c in COLUMNS if c not in header]
            if missing:
                fail(f"{path}: no column {', '.join(missing)} (run with Analysis::rotation = true); has: {' '.join(header)}")
            fail(f"{path}:{n}: not a number in '{line[:80]}'")
        except IndexError:
            fail(f"{path}:{n}: {len(fields)} fields, the header has {len(header)}")
    if not rows:
        fail(f"{path}: no rows")
    return rows


def relative(rows, t_max):
    """(t, rho_c/rho_c0, J/J0, M0/M0_0) up to t_max."""
    r0 = rows[0]
    return [(r["time"], r["rho_c"] / r0["rho_c"], r["J"] / r0["J"], r["rest_mass"] / r0["rest_mass"])
            for r in rows if r["time"] <= t_max * (1 + 1e-12)]


def interpolate(series, t, k):
    for a, b in zip(series, series[1:]):
        if a[0] <= t <= b[0]:
            w = 0.0 if b[0] == a[0] else (t - a[0]) / (b[0] - a[0])
            return (1 - w) * a[k] + w * b[k]
    return None


def main(argv):
    t_cap = None
    if len(argv) >= 2 and argv[0] == "--t-max":
        t_cap = float(argv[1])
        argv = argv[2:]
    if len(argv) < 2:
        fail("usage: compare_evolutions.py [--t-max T] REF.tsv RUN.tsv [RUN.tsv ...]")
    runs = [(p, read_tsv(p)) for p in argv]
    t_end = min(rows[-1]["time"] for _, rows in runs)
    if t_cap is not None:
        t_end = min(t_end, t_cap)
    series = [(p, relative(rows, t_end)) for p, rows in runs]
    print(f"t_end = {t_end:.6g} (code units; {t_end / 203.02:.4g} ms)")
    print("run\tt_last\trho_c/rho_c0-1\tJ/J0-1\tM0/M0_0-1\tmax|drho_c|\tmax|dJ|\tmax|dM0|\tmax|rho-ref|\tmax|J-ref|\tmax|M0-ref|")
    ref = relative(runs[0][1], float("inf"))  # all of it: a run's last time may lie beyond REF's last row before t_end
    for i, (path, s) in enumerate(series):
        last = s[-1]
        drift = [max(abs(row[k] - 1) for row in s) for k in (1, 2, 3)]
        diff = ["-"] * 3
        if i > 0:
            for j, k in enumerate((1, 2, 3)):
                d = [abs(row[k] - v) for row in s for v in [interpolate(ref, row[0], k)] if v is not None]
                diff[j] = f"{max(d):.3e}" if d else "-"
        print(f"{path}\t{last[0]:.4g}\t{last[1] - 1:+.3e}\t{last[2] - 1:+.3e}\t{last[3] - 1:+.3e}\t"
              f"{drift[0]:.3e}\t{drift[1]:.3e}\t{drift[2]:.3e}\t" + "\t".join(diff))


if __name__ == "__main__":
    main(sys.argv[1:])
