#!/usr/bin/env bash
# remnant-eos: NaN, inf and out-of-range inputs are refused with a message and exit code 1, never
# evaluated at the table's edge. Usage: eos_cli.sh <remnant-eos> <shared eos dir>
set -uo pipefail
exe=$1
table=$2/SFHo_reduced_39r_39t_20y.h5
if [ ! -f "$table" ]; then echo "REMNANT_TEST_SKIPPED: no table $table"; exit 0; fi
failed=0
# refuse <regex> -- args...
refuse() {
  local regex=$1
  shift 2
  local out rc
  out=$("$exe" "$@" 2>&1)
  rc=$?
  if [ "$rc" != 1 ] || ! grep -Eq -- "$regex" <<<"$out" || grep -Eq "p    =" <<<"$out"; then
    echo "FAIL $*: exit $rc"; echo "$out" | head -5; failed=$((failed + 1))
  else
    echo "ok   $* -> $(grep -E -- "$regex" <<<"$out" | head -1)"
  fi
}
refuse "'nan' is not a finite number" -- eval "$table" 1e14 nan 0.1
refuse "'nan' is not a finite number" -- eval "$table" nan 10 0.1
refuse "'inf' is not a finite number" -- eval "$table" 1e14 10 inf
refuse "'nan' is not a finite number" -- eval "$table" --eps 1e14 nan 0.1
refuse "RHO must be > 0" -- eval "$table" -1e14 10 0.1
refuse "T must be > 0 MeV" -- eval "$table" 1e14 0 0.1
refuse "YE must lie in \[0, 1\]" -- eval "$table" 1e14 10 1.5
refuse "--n=1: allowed integers 2" -- slice "$table" --n=1
# A valid evaluation still works.
out=$("$exe" eval "$table" --cs2=relativistic 1e14 10 0.1 2>&1) || { echo "FAIL valid eval"; failed=$((failed + 1)); }
grep -q "p    =" <<<"$out" && echo "ok   valid eval" || { echo "FAIL valid eval: $out"; failed=$((failed + 1)); }
[ $failed = 0 ] && echo "all passed" || { echo "$failed failed"; exit 1; }
