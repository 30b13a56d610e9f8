#!/usr/bin/env bash
# remnant-c2p-bench: out-of-range options are errors naming the option (exit 2), and the fuzz mode
# finds no NaN and no silently wrong recovery in 1e5 random states over the SFHo table; the
# benchmark planes reach the accuracies the README quotes.
# Usage: bench_cli.sh <remnant-c2p-bench> <shared eos dir>
set -uo pipefail
exe=$1
table=$2/SFHo_reduced_39r_39t_20y.h5
if [ ! -f "$table" ]; then echo "REMNANT_TEST_SKIPPED: no table $table"; exit 0; fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0

# bad <regex the message must match> -- options...
bad() {
  local regex=$1
  shift 2
  local out rc
  out=$("$exe" "$table" --no-timing --out="$tmp/o" "$@" 2>&1)
  rc=$?
  if [ "$rc" != 2 ] || ! grep -Eq -- "$regex" <<<"$out"; then
    echo "FAIL $*: exit $rc, output:"; echo "$out" | head -5; failed=$((failed + 1))
  else
    echo "ok   $* -> $(grep -E -- "$regex" <<<"$out" | head -1)"
  fi
}

bad "option --ye=1.5: allowed 0 <= Ye <= 1" -- --ye=1.5
bad "option --ye=0.9: outside the table .*allowed 0.01 .. 0.6" -- --ye=0.9
bad "option --b2p=-1: allowed" -- --b2p=-1
bad "option --tol=0: allowed 0 < tol" -- --tol=0
bad "option --max-iter=-5: allowed integers 1 .. " -- --max-iter=-5
bad "option --max-iter=2.5: allowed integers" -- --max-iter=2.5
bad "option --W=0.5: allowed 1 <= W" -- --W=0.5
bad "option --W=nan: not a finite number" -- --W=nan
bad "option --n-rho=0: allowed integers 1 .. " -- --n-rho=0
bad "option --rho=-3: allowed rho > 0" -- --rho=-3
bad "option --T=100000: outside the table .*allowed 0.1 .. 131" -- --T=1e5
bad "option --log-b2p=5:1:3: LO must not exceed HI" -- --log-b2p=5:1:3
bad "option --seed=-1: allowed integers 0 .. " -- --seed=-1
bad "option --fuzz=0: allowed integers 1 .. " -- --fuzz=0
bad "option --accuracy=0: allowed 0 < accuracy < 1" -- --accuracy=0
bad "option --rho-max=0: allowed rho > 0" -- --rho-max=0
bad "option --hint=-1: allowed 0 <= F <= 50" -- --hint=-1

# 1e5 random states, both methods: 0 NaN and 0 silently wrong (the tool exits 3 otherwise).
start=$(date +%s.%N)
out=$("$exe" "$table" --fuzz=100000 --no-timing --out="$tmp/fuzz" 2>&1)
rc=$?
echo "$out" | grep -E "^(plane|fuzz)"
echo "fuzz took $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN{printf "%.2f", b - a}') s"
if [ "$rc" != 0 ]; then echo "FAIL fuzz: exit $rc"; echo "$out" | tail -5; failed=$((failed + 1)); fi
# Columns of summary.tsv: silently_wrong (12), nan (14); one row per method.
rows=$(awk -F'\t' '$1 == "fuzz" && $3 == 100000 && $12 == 0 && $14 == 0' "$tmp/fuzz/summary.tsv" | wc -l)
if [ "$rows" != 2 ]; then echo "FAIL fuzz summary:"; cat "$tmp/fuzz/summary.tsv"; failed=$((failed + 1)); fi

# Far-off T hints (T_true e^{10u}) change only the cost: the same per-state results as without.
"$exe" "$table" --fuzz=20000 --no-timing --out="$tmp/fz0" >/dev/null 2>&1 || { echo "FAIL fuzz no hint: exit $?"; failed=$((failed + 1)); }
"$exe" "$table" --fuzz=20000 --no-timing --hint=10 --out="$tmp/fz1" >/dev/null 2>&1 || { echo "FAIL fuzz far hints: exit $?"; failed=$((failed + 1)); }
for m in kastaun palenzuela; do
  # Columns: axes, eps_recov, iterations, status, residual, rules (not evaluations/eos_calls: the cost).
  if ! cmp -s <(cut -f1-4,7-9 "$tmp/fz0/fuzz_$m.tsv") <(cut -f1-4,7-9 "$tmp/fz1/fuzz_$m.tsv"); then
    echo "FAIL far hints changed $m results"; failed=$((failed + 1))
  else echo "ok   far hints: $m results identical to unhinted"; fi
done
# The README's accuracy figures (issue 20, item 6): the paper's two planes on SFHo. Measured mean
# eps_recov on the rho-T plane 5.8e-14 (Kastaun) and 8.43e-14 (Palenzuela) with 16.5 / 24.9 table
# calls (45.4 / 56.1 before issue 21's cached-Ye slice); the W-b^2/2p plane 9.6e-10 / 9.0e-10 with
# 12.7 / 33.9 calls; after issue 21's early stop and fused ln p reads 6.8e-14 / 8.4e-14 with 13.95 /
# 21.9 calls, 9.6e-10 / 9.0e-10 with 11.3 / 29.0. Bounds: 3x the accuracies, +10 % the calls; no failures, flags, silently wrong
# or NaN states (columns 10-14). Issue 21 goal 4 (Kastaun's analytic upper bracket end, three-point
# first Brent step): rho-T Kastaun 13.95 -> 12.73 calls, 6.8e-14 -> 7.2e-14; its bound 15.5 -> 13.3.
"$exe" "$table" --no-timing --out="$tmp/planes" >/dev/null 2>&1 || { echo "FAIL planes: exit $?"; failed=$((failed + 1)); }
check_plane() {  # plane method max_mean_eps max_mean_calls
  local row
  row=$(awk -F'\t' -v p="$1" -v m="$2" -v e="$3" -v c="$4" \
    '$1 == p && $2 == m { ok = ($4 < e && $9 < c && $10 == 0 && $11 == 0 && $12 == 0 && $14 == 0); print (ok ? "ok  " : "FAIL"), $0 }' \
    "$tmp/planes/summary.tsv")
  echo "$row (bounds: mean eps_recov < $3, EOS calls < $4)"
  [[ $row == ok* ]] || failed=$((failed + 1))
}
check_plane rhoT kastaun 2e-13 13.3
check_plane rhoT palenzuela 2.5e-13 24.5
check_plane Wb kastaun 3e-9 12.5
check_plane Wb palenzuela 3e-9 32

[ $failed = 0 ] && echo "all passed" || { echo "$failed failed"; exit 1; }
