#!/bin/bash
# Smoke test of the MHD plot scripts on short runs: each writes its PNG and exits 0.
# usage: plot_scripts.sh REMNANT_EXE SOURCE_DIR WORK_DIR
set -euo pipefail
exe=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$exe" "$src/parfiles/field_loop_2d.yaml" Flesh::out_dir="$work/loop" "Grid::ncells=[32,16,1]" "Grid::block_size=[8,8,1]" \
  MoL::final_time=-1 MoL::max_iterations=8 IO::hdf5_every=4 Flesh::progress_every=0 > "$work/loop.log" 2>&1
"$exe" "$src/parfiles/mhd_shocktube_balsara1.yaml" Flesh::out_dir="$work/tube" "Grid::ncells=[100,1,1]" "Grid::block_size=[50,1,1]" \
  MoL::final_time=-1 MoL::max_iterations=10 IO::hdf5_every=10 Flesh::progress_every=0 > "$work/tube.log" 2>&1
/usr/bin/python3 "$src/utils/plot_field_loop" "$work/loop"
/usr/bin/python3 "$src/utils/plot_mhd_2d" "$work/loop"
/usr/bin/python3 "$src/utils/plot_mhd_shocktube" "$work/tube" --reference "$work/tube"
for png in loop/field_loop.png loop/maps.png tube/shocktube.png; do
  [ -s "$work/$png" ] || { echo "missing $work/$png"; exit 1; }
done
echo "plot scripts: 3 PNGs written"
