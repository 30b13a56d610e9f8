#!/bin/bash
# Every shipped parfile passes the strict parameter validation (types, ranges, keywords, unknown
# names, active thorns): `remnant PARFILE --print-parfile` for each parfiles/*.yaml. A typo in a
# shipped parfile fails here, not in a user's first run.
# Usage: parfiles_resolve.sh REMNANT SOURCE_DIR
set -uo pipefail
remnant=$1 src=$2
cd "$src" || exit 1
n=0 bad=0
for par in parfiles/*.yaml; do
  n=$((n + 1))
  if ! err=$("$remnant" "$par" --print-parfile 2>&1 >/dev/null); then
    echo "FAIL: $par"; echo "$err" | head -5; bad=$((bad + 1))
  fi
done
[[ $n -gt 0 ]] || { echo "FAIL: no parfiles found in $src/parfiles"; exit 1; }
echo "$((n - bad)) of $n parfiles resolve"
[[ $bad -eq 0 ]]
