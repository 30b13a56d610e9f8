#!/usr/bin/env bash
# thorns/RotatingStar/tools/compare_evolutions.py on two small hand-made Analysis TSVs: the end
# values, drifts and the largest difference from the reference (interpolated to the run's times)
# are the ones computed by hand; a TSV without the rotation columns is refused naming the file.
#   compare_evolutions.sh <repo root>
set -euo pipefail
repo=$1
tool="$repo/thorns/RotatingStar/tools/compare_evolutions.py"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf '# iteration\ttime\trho_c\tJ\trest_mass\n0\t0\t1.0\t2.0\t4.0\n10\t2\t0.98\t2.0\t4.0\n20\t4\t0.96\t2.002\t3.996\n' > "$dir/ref.tsv"
# The run's t = 1 lies between the reference's rows: reference rho_c/rho_c0 there is 0.99.
printf '# iteration\ttime\trho_c\tJ\trest_mass\n0\t0\t2.0\t1.0\t2.0\n5\t1\t1.95\t1.001\t2.0\n9\t3\t1.90\t1.002\t2.0\n' > "$dir/run.tsv"
out=$(python3 "$tool" "$dir/ref.tsv" "$dir/run.tsv")
echo "$out"
ref_line=$(grep '^.*ref.tsv' <<< "$out")
run_line=$(grep '^.*run.tsv' <<< "$out")
fail() { echo "FAIL: $*"; exit 1; }
grep -q '^t_end = 3 ' <<< "$out" || fail "t_end is the smallest last time (3)"
# Reference up to t = 3: last row t = 2, rho 0.98, J 1, M0 1.
[[ $(cut -f2-5 <<< "$ref_line") == $'2\t-2.000e-02\t+0.000e+00\t+0.000e+00' ]] || fail "reference end values: $ref_line"
# Run at t = 3: rho 0.95, J 1.002, M0 1; differences from the reference at t = 1 (0.99 vs 0.975)
# and t = 3 (0.97 vs 0.95 -> 0.02; J 1.0005 vs 1.002 -> 1.5e-3; M0 0.9995 vs 1 -> 5e-4).
[[ $(cut -f2-5 <<< "$run_line") == $'3\t-5.000e-02\t+2.000e-03\t+0.000e+00' ]] || fail "run end values: $run_line"
[[ $(cut -f9-11 <<< "$run_line") == $'2.000e-02\t1.500e-03\t5.000e-04' ]] || fail "differences from the reference: $run_line"
# Bad input: no J column.
printf '# iteration\ttime\trho_c\trest_mass\n0\t0\t1\t1\n' > "$dir/bad.tsv"
if err=$(python3 "$tool" "$dir/ref.tsv" "$dir/bad.tsv" 2>&1); then fail "a TSV without J was accepted"; fi
grep -q "bad.tsv: no column J" <<< "$err" || fail "the error names the file and the column: $err"
echo "compare_evolutions: OK"
