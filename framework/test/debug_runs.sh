#!/usr/bin/env bash
# Every physics parfile runs a few iterations with --debug (NaN-poisoned outputs, undeclared writes,
# views of undeclared groups): a scheduled function whose thorn.yaml declarations do not match what
# it does fails here. Usage: debug_runs.sh <remnant executable> <source dir>
set -uo pipefail
exe=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0
run() {
  local name=$1 parfile=$2
  shift 2
  local out rc
  out=$(timeout 300 "$exe" "$src/parfiles/$parfile" --debug MoL::final_time=-1 "Flesh::out_dir=$tmp/$name" "$@" 2>&1)
  rc=$?
  if [ "$rc" = 0 ]; then passed=$((passed + 1)); echo "ok   $name";
  else failed=$((failed + 1)); echo "FAIL $name (exit $rc):"; echo "$out" | grep -E "ERROR|error|debug check" | head -5; fi
}
run bu0_cow bu0_cow.yaml MoL::max_iterations=3
# Solves every other step: the metric extrapolation and recovery between solves run too.
run bu0_dyn bu0_dyn.yaml MoL::max_iterations=4 XCFC::solve_every=2
run migration_2d migration.yaml MoL::max_iterations=3 "Grid::ncells=[64,16,1]" "Grid::block_size=[16,16,1]"
run rns_cyl_2d rns_uniform_cyl_2d.yaml MoL::max_iterations=3 RotatingStar::nr=200
run shocktube shocktube_mm1.yaml MoL::max_iterations=3
run wavetoy_3d wavetoy_3d.yaml MoL::max_iterations=3
run advection_amr advection_cartesian_2d.yaml MoL::max_iterations=3
ls220="$src/../shared/eos/SRO_LS220_157r_89t_49y.h5"
if [ -f "$ls220" ]; then
  run headon_cyl_2d headon_cyl_2d.yaml MoL::max_iterations=3 "EOS::table_file=$ls220"
  run headon_3d headon_3d.yaml MoL::max_iterations=3 Grid::max_level=1 "HeadOn::refine_radii=[12]" Grid::regrid_every=2 \
    "EOS::table_file=$ls220"
else
  echo "skip headon_cyl_2d, headon_3d: $ls220 is missing"
fi
# Magnetic fields: seeding, GRMHD's (idle) initial field, the xCFC hooks that change Bvec.
for p in magnetized_tov_cyl_2d magnetized_tov_sph_2d magnetized_tov_cart_3d toroidal_tov_sph_2d; do
  run "$p" "$p.yaml" MoL::max_iterations=2 XCFC::solve_every=1
done
run magnetized_drns magnetized_drns.yaml MoL::max_iterations=2
for p in field_loop_2d mhd_shocktube_balsara1 rotor_2d; do
  run "$p" "$p.yaml" MoL::max_iterations=3
done
echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
