#!/usr/bin/env bash
# End-to-end checks of the command line: bad input gives a clear message and a non-zero exit on
# every rank, without hanging under MPI. Usage: cli_errors.sh <remnant executable> <source dir>
set -uo pipefail
exe=$1
src=$2
par=$src/parfiles/wavetoy_1d.yaml
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mpirun=(mpirun -np 2 --oversubscribe)
[ "$(id -u)" = 0 ] && mpirun+=(--allow-run-as-root)
passed=0
failed=0

# expect <name> <expected rc: 0 | nonzero> <regex the output must match> -- command...
expect() {
  local name=$1 want=$2 regex=$3
  shift 4
  local out rc
  out=$(timeout 120 "$@" 2>&1)
  rc=$?
  local ok=1
  if [ "$rc" = 124 ]; then ok=0; echo "FAIL $name: timed out (hang?)";
  elif [ "$want" = 0 ] && [ "$rc" != 0 ]; then ok=0; echo "FAIL $name: exit code $rc, expected 0";
  elif [ "$want" = nonzero ] && [ "$rc" = 0 ]; then ok=0; echo "FAIL $name: exit code 0, expected an error";
  fi
  if ! grep -Eq -- "$regex" <<<"$out"; then ok=0; echo "FAIL $name: output does not match /$regex/"; fi
  if [ $ok = 1 ]; then passed=$((passed + 1)); echo "ok   $name"; else failed=$((failed + 1)); echo "$out" | tail -20; fi
}

expect unknown_parameter nonzero "WaveToy::bogus.*nearest valid names: WaveToy::" -- "$exe" "$par" WaveToy::bogus=1
expect unknown_parameter_mpi nonzero "WaveToy::bogus.*nearest valid names: WaveToy::" -- "${mpirun[@]}" "$exe" "$par" WaveToy::bogus=1
expect typo_suggests nonzero "unknown parameter MoL::cfll.*MoL::cfl" -- "$exe" "$par" MoL::cfll=0.3
expect out_of_range nonzero "MoL::cfl = -1 is out of range: allowed real in \(0:\*\)" -- "$exe" "$par" MoL::cfl=-1
expect out_of_range_mpi nonzero "out of range: allowed real in \(0:\*\)" -- "${mpirun[@]}" "$exe" "$par" MoL::cfl=-1
expect wrong_type nonzero "Grid::dimension expects an integer" -- "$exe" "$par" Grid::dimension=two
printf 'active_thorns: [Grid, MoL]\nGrid:\n  ncells: [1, 2\n  dimension: 1\n' > "$tmp/syntax.yaml"
expect yaml_syntax nonzero "syntax.yaml:[0-9]+:[0-9]+: error: YAML syntax error" -- "$exe" "$tmp/syntax.yaml"
expect yaml_syntax_mpi nonzero "syntax.yaml:[0-9]+:[0-9]+: error: YAML syntax error" -- "${mpirun[@]}" "$exe" "$tmp/syntax.yaml"
printf 'active_thorns: [Grid, MoL, WaveToy, IO]\nMoL:\n  final_time: 1\nWavToy:\n  amplitude: 2\n' > "$tmp/thorn.yaml"
expect unknown_thorn_section nonzero "thorn.yaml:4:1: error: unknown thorn 'WavToy' \(did you mean WaveToy" -- "$exe" "$tmp/thorn.yaml"
printf 'active_thorns: [Grid, MoL]\nMoL:\n  final_time: 1\nWaveToy:\n  amplitude: 2\n' > "$tmp/inactive.yaml"
expect inactive_thorn nonzero "inactive.yaml:4:1: error: parameters of thorn WaveToy are set, but WaveToy is not in active_thorns" -- "$exe" "$tmp/inactive.yaml"
printf 'active_thorns: [Grid, WaveToy]\n' > "$tmp/requires.yaml"
expect missing_capability nonzero "WaveToy requires 'time_integration'.*activate MoL" -- "$exe" "$tmp/requires.yaml"
expect never_ending nonzero "the run would never end" -- "$exe" "$par" MoL::final_time=-1
expect missing_parfile nonzero "nothere.yaml: error: cannot open file" -- "$exe" "$tmp/nothere.yaml"
# A failure on one rank only (rank 0 cannot create the output directory) must not hang the others.
expect one_rank_fails_mpi nonzero "cannot create output directory" -- "${mpirun[@]}" "$exe" "$par" Flesh::out_dir=/proc/remnant_forbidden
expect print_schedule 0 "WaveToy::WaveToy_RHS.*syncs WaveToy::wave" -- "$exe" "$par" --print-schedule
schedule=$("$exe" "$par" --print-schedule 2>&1)
order=$(grep -E '^[a-z_]+:' <<<"$schedule" | cut -d: -f1 | tr '\n' ' ')
if [ "$order" = "startup paramcheck initial postinitial prestep evol poststep analysis checkpoint terminate post_regrid post_recover " ] &&
   grep -q "WaveToy::WaveToy_RHS" <<<"$schedule" && grep -q "MoL::MoL_Update" <<<"$schedule"; then
  passed=$((passed + 1)); echo "ok   print_schedule_order"
else
  failed=$((failed + 1)); echo "FAIL print_schedule_order: $order"
fi
expect describe 0 "^  MoL::cfl$" -- "$exe" --describe MoL
expect describe_ranges 0 "type real; allowed: real in \(0:\*\); default: 0.4" -- "$exe" --describe MoL
expect describe_unknown nonzero "unknown thorn 'Mol' \(did you mean MoL" -- "$exe" --describe Mol
expect runs 0 "Run ends at iteration" -- "$exe" "$par" MoL::final_time=0.1 Flesh::out_dir="$tmp/run"
expect resolved_parfile 0 "cfl: 0.5" -- cat "$tmp/run/parfile.resolved.yaml"
expect walltime_limit 0 "reached MoL::max_walltime_hours" -- "$exe" "$par" MoL::final_time=-1 MoL::max_walltime_hours=1e-9 Flesh::out_dir="$tmp/wall"
expect iteration_limit 0 "Run ends at iteration 3, .*reached MoL::max_iterations = 3" -- "$exe" "$par" MoL::max_iterations=3 Flesh::out_dir="$tmp/it"
expect debug_mode_runs 0 "Run ends at iteration" -- "$exe" "$par" MoL::final_time=0.05 --debug Flesh::out_dir="$tmp/debug"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
