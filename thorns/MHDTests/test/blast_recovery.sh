#!/bin/bash
# The strong-field cylindrical blast parfile at 100^2 to t = 1: no failed primitive recovery.
# With the old settings (MC, uct_hll, CFL 0.3) D went negative in the light gas swept off the
# cylinder's top and bottom from t ~ 0.2 on (4035 invalid recoveries to t = 4, W up to 9e5).
# usage: blast_recovery.sh REMNANT_EXE SOURCE_DIR WORK_DIR [extra overrides...]
set -euo pipefail
exe=$1 src=$2 work=$3; shift 3
rm -rf "$work" && mkdir -p "$work"
"$exe" "$src/parfiles/blast_cylindrical_2d.yaml" Flesh::out_dir="$work/run" "Grid::ncells=[100,100,1]" \
  MoL::final_time=1.0 IO::hdf5_every_time=0 IO::tsv_every=0 Flesh::progress_every=0 "$@" > "$work/run.log" 2>&1 \
  || { tail -20 "$work/run.log"; echo "run failed"; exit 1; }
if grep -q "primitive recovery failed\|inaccurate or ambiguous" "$work/run.log"; then
  grep "primitive recovery failed\|inaccurate or ambiguous" "$work/run.log" | head -5
  echo "blast: $(grep -c 'primitive recovery failed' "$work/run.log") substeps with failed recoveries"; exit 1
fi
echo "blast: no failed recovery to t = 1 at 100^2"
