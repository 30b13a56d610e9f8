#!/usr/bin/env bash
# End-to-end checks of input sanity before the first step (issue 16): grid memory, physics
# parameters that cannot make sense, time steps above the stability limit, YAML slips, and the form
# of error messages (one line from the lowest failing rank, no MPI noise). Every run stops before
# evolving or after a few steps of a 640-cell star.
# Usage: input_sanity.sh <remnant executable> <source dir>
set -uo pipefail
exe=$1
src=$2
star=$src/parfiles/bu0_cow.yaml
wave=$src/parfiles/wavetoy_1d.yaml
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mpirun=(mpirun -np 2 --oversubscribe)
[ "$(id -u)" = 0 ] && mpirun+=(--allow-run-as-root)
quiet=(Flesh::out_dir="$tmp/out" Flesh::timers=false Flesh::progress_every=0)
initial_only=("${quiet[@]}" MoL::max_iterations=0)
passed=0
failed=0

# expect <name> <expected rc: 0 | nonzero> <regex the output must match> <regex it must not match | -> -- command...
# The first regex must match exactly one line (an error printed once, not once per rank).
expect() {
  local name=$1 want=$2 regex=$3 forbidden=$4
  shift 5
  local out rc
  out=$(timeout 120 "$@" 2>&1)
  rc=$?
  local ok=1 count
  count=$(grep -Ec -- "$regex" <<<"$out")
  if [ "$rc" = 124 ]; then ok=0; echo "FAIL $name: timed out (hang?)";
  elif [ "$want" = 0 ] && [ "$rc" != 0 ]; then ok=0; echo "FAIL $name: exit code $rc, expected 0";
  elif [ "$want" = nonzero ] && [ "$rc" = 0 ]; then ok=0; echo "FAIL $name: exit code 0, expected an error";
  fi
  if [ "$count" != 1 ]; then ok=0; echo "FAIL $name: /$regex/ matches $count lines, expected 1"; fi
  if [ "$forbidden" != - ] && grep -Eq -- "$forbidden" <<<"$out"; then ok=0; echo "FAIL $name: output matches /$forbidden/"; fi
  if [ $ok = 1 ]; then passed=$((passed + 1)); echo "ok   $name"; else failed=$((failed + 1)); echo "$out" | tail -20; fi
}
noise="MPI_ABORT|:::|ORTE_ERROR"

# Item 6: the memory estimate comes before any allocation (a grid too large is refused under a 4 GB
# address-space limit, not attempted).
expect print_grid_memory 0 "^  memory +about [0-9.]+ [kMG]B per rank" - -- "$exe" "$star" --print-grid "${quiet[@]}"
expect memory_limit_parameter nonzero "needs about .* per rank.*Flesh::max_memory_gb" "$noise" -- \
  "$exe" "$star" --print-grid Flesh::max_memory_gb=0.0001 "${quiet[@]}"
huge=(Grid::ncells=[4096,4096,4096])  # 10 TB of WaveToy blocks: larger than any machine
expect huge_grid_refused nonzero "Grid::ncells=\[4096,4096,4096\]': error: the grid needs about [0-9.]+ TB per rank" "$noise|bad_alloc" -- \
  bash -c 'ulimit -v 4000000; exec "$@"' _ "$exe" "$src/parfiles/wavetoy_3d.yaml" --print-grid "${huge[@]}" "${quiet[@]}"
expect huge_grid_refused_mpi nonzero "error: the grid needs about [0-9.]+ TB per rank" "$noise" -- \
  "${mpirun[@]}" "$exe" "$src/parfiles/wavetoy_3d.yaml" --print-grid "${huge[@]}" "${quiet[@]}"

# Item 7: stars that cannot make sense stop in TOV_CheckParameters; NaN in initial data is fatal.
expect rho_central_above_eos nonzero "TOV::rho_central = 2 is outside the EOS's densities \[1e-20, 1\]" "$noise" -- \
  "$exe" "$star" TOV::rho_central=2 "${initial_only[@]}"
expect rho_central_below_atmosphere nonzero "Atmosphere::rho_thr = 1e-10 is not below TOV::rho_central = 1e-11" "$noise" -- \
  "$exe" "$star" TOV::rho_central=1e-11 "${initial_only[@]}"
expect rho_thr_above_star nonzero "'Atmosphere::rho_thr=0.01': error: Atmosphere::rho_thr = 0.01 is not below TOV::rho_central" "$noise" -- \
  "$exe" "$star" Atmosphere::rho_thr=0.01 "${initial_only[@]}"
expect star_larger_than_grid nonzero "'TOV::poly_K=1e30': error: the star \(isotropic radius R = .*\) is larger than the grid, which reaches r = 50" "$noise" -- \
  "$exe" "$star" TOV::poly_K=1e30 "${initial_only[@]}"
expect grid_smaller_than_star nonzero "'Grid::xmax=\[5,3.2,6.3\]': error: the star .* is larger than the grid, which reaches r = 5 " "$noise" -- \
  "$exe" "$star" Grid::xmax=[5,3.2,6.3] "${initial_only[@]}"
for amp in 0.9 -0.9; do
  expect "perturbation_amplitude_$amp" nonzero "TOV::perturbation_amplitude = $amp makes the star's fluid move at \|v\| = 1\.[0-9]+ .*allowed: \|amplitude\| < 0\.7" "$noise" -- \
    "$exe" "$star" TOV::perturbation=radial_velocity TOV::perturbation_amplitude=$amp "${initial_only[@]}"
done
table=$src/../shared/eos/SFHo_reduced_39r_39t_20y.h5
if [ -f "$table" ]; then
  expect rho_central_above_table nonzero "TOV::rho_central = 10 is outside the EOS's densities \[.*\] \(the table's range, EOS::table_file\)" "$noise" -- \
    "$exe" "$star" EOS::type=tabulated EOS::table_file="$table" TOV::eos_slice=tabulated_beta TOV::rho_central=10 "${initial_only[@]}"
else
  echo "skip rho_central_above_table: no $table"
fi
expect perturbation_allowed 0 "Run ends at iteration 0" - -- \
  "$exe" "$star" TOV::perturbation=radial_velocity TOV::perturbation_amplitude=0.5 "${initial_only[@]}"
expect star_error_once_mpi nonzero "TOV::rho_central = 2 is outside the EOS's densities" "$noise" -- \
  "${mpirun[@]}" "$exe" "$star" TOV::rho_central=2 "${initial_only[@]}"

# Item 8: time steps above the stability limit.
expect cfl_above_limit_warns 0 "WARNING .*MoL::cfl = 1.5 is above the stability limit 1 of MoL::method = rk3" - -- \
  "$exe" "$star" MoL::cfl=1.5 MoL::max_iterations=1 "${quiet[@]}"
expect cfl_5_names_time_step nonzero "likely cause: the time step dt = .* times the largest stable one .*lower MoL::cfl" "$noise" -- \
  "$exe" "$star" MoL::cfl=5 MoL::max_iterations=20 "${quiet[@]}"
expect dt_1e6_names_time_step nonzero "likely cause: the time step dt = .* times the largest stable one .*lower MoL::dt" "$noise" -- \
  "$exe" "$star" MoL::dt=1e6 MoL::max_iterations=3 "${quiet[@]}"
expect dt_small_is_quiet 0 "Run ends at iteration 3" "stability limit|largest stable" -- \
  "$exe" "$star" MoL::dt=0.01 MoL::max_iterations=3 "${quiet[@]}"

# Item 9: YAML slips are errors with file:line:col.
printf 'active_thorns: [Grid, MoL, WaveToy]\nGrid:\n  dimension: 1\n  dimension: 2\n' > "$tmp/dup.yaml"
expect yaml_duplicate_key nonzero "dup.yaml:4:3: error: duplicate key 'dimension' \(first at line 3:3\)" "$noise" -- "$exe" "$tmp/dup.yaml"
printf 'active_thorns: [Grid, MoL, WaveToy]\nMoL:\n  final_time: 1\n---\nGrid:\n  dimension: 1\n' > "$tmp/docs.yaml"
expect yaml_second_document nonzero "docs.yaml:5:1: error: a second YAML document" "$noise" -- "$exe" "$tmp/docs.yaml"
mkdir -p "$tmp/folder"
printf 'include: folder\nactive_thorns: [Grid, MoL, WaveToy]\n' > "$tmp/incdir.yaml"
expect include_directory nonzero "incdir.yaml:1:10: error: included parfile '.*folder' is a directory" "$noise" -- "$exe" "$tmp/incdir.yaml"
printf 'active_thorns: [Grid, MoL, WaveToy, MoL]\nMoL:\n  final_time: 1\n' > "$tmp/twice.yaml"
expect thorn_listed_twice nonzero "twice.yaml:1:37: error: thorn 'MoL' is listed twice in active_thorns" "$noise" -- "$exe" "$tmp/twice.yaml"

# Item 15: the form of errors: the function named, one line from the lowest failing rank, no MPI noise.
expect error_names_function nonzero "^ERROR in Flesh::create_output_directory: cannot create output directory '/proc/remnant_forbidden'" "$noise" -- \
  "$exe" "$wave" Flesh::out_dir=/proc/remnant_forbidden
expect error_once_mpi nonzero "^ERROR \[rank 0\] in Flesh::create_output_directory: cannot create output directory" "$noise" -- \
  "${mpirun[@]}" "$exe" "$wave" Flesh::out_dir=/proc/remnant_forbidden
expect grid_error_once_mpi nonzero "error: Grid::ncells\[0\] = 7 is not divisible by Grid::block_size\[0\] = 16" "$noise" -- \
  "${mpirun[@]}" "$exe" "$wave" Grid::ncells=[7,1,1] Flesh::out_dir="$tmp/out"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
