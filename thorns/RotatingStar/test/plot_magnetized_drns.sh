#!/usr/bin/env bash
# parfiles/magnetized_drns.yaml for two steps (solver at nr = 200), HDF5 at t = 0 and the end, and
# utils/plot_star_profiles with its magnetic row: the picture is written and B's change is printed.
# Usage: plot_magnetized_drns.sh <remnant> <source dir>
set -uo pipefail
exe=$1
src=$2
plot="$src/utils/plot_star_profiles"
py=$(head -1 "$plot" | sed 's/^#!//')  # the script's own interpreter
if ! $py -c "import h5py, matplotlib" 2>/dev/null; then echo "SKIP: $py lacks h5py or matplotlib"; exit 0; fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" "$src/parfiles/magnetized_drns.yaml" MoL::max_iterations=2 MoL::final_time=-1 RotatingStar::nr=200 \
  IO::hdf5_every_time=0 IO::hdf5_every=2 "Flesh::out_dir=$tmp/run" >"$tmp/log" 2>&1 || { echo "FAIL: the run"; tail -5 "$tmp/log"; exit 1; }
out=$($py "$plot" "$tmp/run/grid-volume.it00000000.h5" "$tmp/run/grid-volume.it00000002.h5" -o "$tmp/p.png" 2>&1)
echo "$out"
if [ -s "$tmp/p.png" ] && grep -q "max |B - B(0)| / max B(0) inside" <<<"$out"; then echo "ok"; else echo "FAIL: no picture or no B row"; exit 1; fi
