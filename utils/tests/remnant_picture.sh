#!/usr/bin/env bash
# utils/remnant without a parfile ends with a picture of the run (issue 16 item 14); a missing
# matplotlib prints how to install it and does not fail the run; with a parfile nothing is plotted.
# Usage: remnant_picture.sh <build dir> <source dir>
set -uo pipefail
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export REMNANT_SKIP_BOOTSTRAP=1
short=(MoL::final_time=20 Flesh::timers=false)
passed=0
failed=0
check() {  # check <name> <condition exit status> <output>
  if [ "$2" = 0 ]; then passed=$((passed + 1)); echo "ok   $1"; else failed=$((failed + 1)); echo "FAIL $1"; echo "$3" | tail -15; fi
}

# The plot script's interpreter (its #! line), to know whether a picture can be drawn here.
python=$(head -1 "$src/utils/plot_modes" | sed 's/^#!//')
out=$(cd "$tmp" && "$src/utils/remnant" --build-dir "$build" "${short[@]}" Flesh::out_dir=run 2>&1)
rc=$?
grep -q "the run's output is in $tmp/run/" <<<"$out" && grep -q "to plot other outputs: utils/plot_modes" <<<"$out" && [ $rc = 0 ]
check output_folder_and_hint $? "$out"
if "$python" -c 'import numpy, matplotlib' 2>/dev/null; then
  grep -q "picture of the run .*: $tmp/run/rho_c_modes.png" <<<"$out" && [ "$(head -c 4 "$tmp/run/rho_c_modes.png" | tail -c 3)" = PNG ]
  check picture_written $? "$out"
else
  echo "skip picture_written: $python has no matplotlib"
fi

# Without matplotlib: the run still succeeds and the message says how to install it.
mkdir -p "$tmp/fake/matplotlib"
echo 'raise ImportError("No module named matplotlib (test)")' > "$tmp/fake/matplotlib/__init__.py"
out=$(cd "$tmp" && PYTHONPATH="$tmp/fake" "$src/utils/remnant" --build-dir "$build" "${short[@]}" Flesh::out_dir=nompl 2>&1)
rc=$?
[ $rc = 0 ] && grep -q "install numpy and matplotlib" <<<"$out" && grep -q "the run itself succeeded" <<<"$out" &&
  ! grep -q Traceback <<<"$out"
check missing_matplotlib_is_not_fatal $? "$out"

# With a parfile: just the run.
out=$(cd "$tmp" && "$src/utils/remnant" --build-dir "$build" "$src/parfiles/wavetoy_1d.yaml" MoL::final_time=0.05 \
      Flesh::out_dir=wave 2>&1)
rc=$?
[ $rc = 0 ] && ! grep -q "picture of the run\|run's output is in" <<<"$out"
check parfile_run_unchanged $? "$out"

echo "$passed passed, $failed failed"
[ "$failed" = 0 ]
