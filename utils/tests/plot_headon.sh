#!/bin/bash
# utils/plot_headon on two synthetic analysis.tsv files with the collision columns: one with
# rho_max_point_norm (first maximum 2.7 against rho_max_norm's 2.5), one without (an older run):
# the point value's first maximum (not its wiggle at contact) and its difference between the runs
# are printed for the first,
# nothing about it for the second, and the figure is written; a copy of the first whose norm columns
# drop 3 % halfway (a run recovered before the Analysis fix) gives the first's numbers.
# Usage: plot_headon.sh SOURCE_DIR
set -euo pipefail
src=$1
tmp=$(mktemp -d /tmp/remnant-plot-headon.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 - "$tmp" <<'PY'
import math, sys
cols = ["iteration", "time", "rho_max", "rho_max_norm", "quad_dI", "z_rho_max_upper", "M_adm", "M_rest_total",
        "outflow", "rest_mass", "mass_budget"]
def write(path, peak, point_peak):
    names = cols + (["rho_max_point", "rho_max_point_norm"] if point_peak else [])
    with open(path, "w") as f:
        f.write("# " + "\t".join(names) + "\n")
        for i in range(201):
            t = 2.0 * i  # the maxima meet at t = 100, the first maximum at t = 200 * 0.6 = 120
            bump = math.exp(-((t - 120) / 15) ** 2)
            row = {"iteration": i, "time": t, "rho_max_norm": 1 + (peak - 1) * bump, "quad_dI": math.sin(t / 30),
                   "z_rho_max_upper": max(30 - 0.3 * t, 0.375), "M_adm": 1, "M_rest_total": 1, "outflow": 0,
                   "rest_mass": 1, "mass_budget": 1}
            row["rho_max"] = 1e-3 * row["rho_max_norm"]
            if point_peak:
                # with a wiggle at contact (a local maximum of its own at t = 102, as in real runs)
                row["rho_max_point_norm"] = 1 + (point_peak - 1) * bump + 0.3 * math.exp(-((t - 102) / 1.0) ** 2)
                row["rho_max_point"] = 1.05e-3 * row["rho_max_point_norm"]
            f.write("\t".join(repr(float(row[n])) for n in names) + "\n")
write(sys.argv[1] + "/a.tsv", 2.5, 2.7)
write(sys.argv[1] + "/b.tsv", 2.4, 2.97)
write(sys.argv[1] + "/c.tsv", 2.4, None)
# D: A's run recovered at row 50 by a code that normalised by the first row after the recovery: its
# columns are 3 % low from there on; the first maximum must still be A's, from rho_max itself.
with open(sys.argv[1] + "/a.tsv") as f, open(sys.argv[1] + "/d.tsv", "w") as g:
    lines = f.read().splitlines()
    names = lines[0][2:].split("\t")
    g.write(lines[0] + "\n")
    for n, line in enumerate(lines[1:]):
        v = line.split("\t")
        if n > 50:
            for c in ("rho_max_norm", "rho_max_point_norm"):
                v[names.index(c)] = repr(float(v[names.index(c)]) / 1.03)
        g.write("\t".join(v) + "\n")
PY
out=$(/usr/bin/python3 "$src/utils/plot_headon" -o "$tmp/h.png" --labels A,B,C,D "$tmp/a.tsv" "$tmp/b.tsv" "$tmp/c.tsv" "$tmp/d.tsv")
echo "$out"
fail=0
grep -q "^A .*first maximum 2.5000 at 0.5911 ms (point value 2.7000 at 0.5911 ms)" <<<"$out" || { echo "FAIL: A's point value"; fail=1; }
grep -q "^B .*vs A:.*first maximum of rho_max -4.00 %, of its point value +10.00 %" <<<"$out" || { echo "FAIL: B vs A"; fail=1; }
grep -q "^C .*first maximum 2.4000" <<<"$out" && ! grep -q "^C .*point value" <<<"$out" || { echo "FAIL: C (no column)"; fail=1; }
grep -q "^D .*first maximum 2.5000 at 0.5911 ms (point value 2.7000 at 0.5911 ms)" <<<"$out" || { echo "FAIL: D (recovered columns)"; fail=1; }
[[ -s "$tmp/h.png" ]] || { echo "FAIL: no figure"; fail=1; }
exit $fail
