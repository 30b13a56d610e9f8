#!/usr/bin/env bash
# utils/plot_magnetized_tov: a PNG and the drift line from a magnetised analysis.tsv (the regression
# suite's reference), status 1 and a clear message for a hydro run's analysis.tsv.
# Usage: plot_script.sh <source dir>
set -uo pipefail
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python=$(head -1 "$src/utils/plot_magnetized_tov" | sed 's/^#!//')
if ! "$python" -c 'import numpy, matplotlib' 2>/dev/null; then echo "skip: $python has no numpy/matplotlib"; exit 0; fi
mkdir -p "$tmp/run"
cp "$src/testsuites/SeedMagneticField/magnetized_tov_short/reference/analysis.tsv" "$tmp/run/analysis.tsv"
out=$("$src/utils/plot_magnetized_tov" "$tmp/run/analysis.tsv" -o "$tmp/p.png" 2>&1)
rc=$?
echo "$out"
[ $rc = 0 ] && grep -q "run: t_end = .* max divB_max = " <<<"$out" && [ "$(head -c 4 "$tmp/p.png" | tail -c 3)" = PNG ] || { echo "FAIL magnetised run"; exit 1; }
out=$("$src/utils/plot_magnetized_tov" "$src/testsuites/GRMHD/bu0_cow_short/reference/analysis.tsv" -o "$tmp/q.png" 2>&1)
rc=$?
echo "$out"
[ $rc = 1 ] && grep -q "lacks the columns divB_max" <<<"$out" || { echo "FAIL hydro run should be refused"; exit 1; }
echo ok
