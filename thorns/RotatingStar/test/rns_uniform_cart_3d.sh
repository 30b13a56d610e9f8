#!/usr/bin/env bash
# parfiles/rns_uniform_cart_3d.yaml (the 3D Cartesian twin of rns_uniform_cyl_2d, issue 17) sets up
# what it says: four nested levels down to dx = 0.5 around the star, bitant symmetry (reflect in z
# only), and at t = 0 (no step) Analysis's J and rest mass are half the model's (z >= 0) to the
# grid's discretisation error (measured J -4.7e-6, M_0 +1.1e-4 at dx = 0.5).
#   rns_uniform_cart_3d.sh <remnant executable> <repo root>
set -euo pipefail
exe=$1
par="$2/parfiles/rns_uniform_cart_3d.yaml"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

grid=$("$exe" "$par" --print-grid 2>&1)
echo "$grid"
grep -q '3D, 4 levels' <<< "$grid" || fail "four levels"
grep -q 'level 3 .*spacing 0.5 x 0.5 x 0.5' <<< "$grid" || fail "the finest spacing is 0.5"
grep -q 'x: outflow, y: outflow, z: reflect/outflow' <<< "$grid" || fail "bitant: reflect in z only"

log=$("$exe" "$par" MoL::max_iterations=0 MoL::final_time=-1 "Flesh::out_dir=$dir/out" 2>&1) || { echo "$log"; fail "the run stopped"; }
model=$(grep -o 'M_rest = [0-9.e+-]* .* J = [0-9.e+-]*' <<< "$log" | head -1)
m0=$(awk '{print $3}' <<< "$model"); J=$(awk '{print $NF}' <<< "$model")
row=$(grep -v '^#' "$dir/out/analysis.tsv" | head -1)
header=$(grep '^#' "$dir/out/analysis.tsv" | head -1 | sed 's/^# *//')
col() { awk -v name="$1" '{for (i = 1; i <= NF; ++i) if ($i == name) print i}' <<< "$header"; }
grid_m0=$(cut -f"$(col rest_mass)" <<< "$row"); grid_J=$(cut -f"$(col J)" <<< "$row")
echo "model M_0 = $m0, J = $J; grid (z >= 0) rest_mass = $grid_m0, J = $grid_J"
awk -v a="$grid_m0" -v b="$m0" -v c="$grid_J" -v d="$J" 'BEGIN {
  e0 = 2 * a / b - 1; eJ = 2 * c / d - 1
  printf "2 x grid / model - 1: M_0 %.2e, J %.2e\n", e0, eJ
  exit !(e0 * e0 < 1e-6 && eJ * eJ < 1e-6) }' || fail "J or M_0 is not half the model's to 1e-3"
echo "rns_uniform_cart_3d: OK"
