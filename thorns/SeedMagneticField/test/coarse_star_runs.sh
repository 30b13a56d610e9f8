# Shared by star_field_decay.sh and star_kinematic_field.sh (sourced; the caller sets exe, src, tmp):
# the magnetised TOV parfile on a coarse 32^2 grid to R, z = 16 (dx = 0.5, no refinement), and the
# relative change of E_mag between the first and the last row of a run's analysis.tsv.

# coarse_star_run NAME FINAL_TIME [Thorn::param=value ...]: runs into $tmp/NAME, exits 1 on failure.
coarse_star_run() {
  local name=$1 final_time=$2
  shift 2
  if ! "$exe" "$src/parfiles/magnetized_tov_cyl_2d.yaml" 'Grid::ncells=[32,32,1]' 'Grid::xmax=[16,16,6.283185307179586]' \
       Grid::max_level=0 'Grid::region_levels=[0]' MoL::final_time="$final_time" Analysis::every=20 Flesh::progress_every=0 \
       Flesh::timers=false Flesh::out_dir="$tmp/$name" "$@" >"$tmp/$name.log" 2>&1; then
    echo "FAIL: the $name run failed:"; tail -20 "$tmp/$name.log"; exit 1
  fi
}

# emag_change NAME: prints "<last time> <E_mag(last) / E_mag(first) - 1>" of run NAME.
emag_change() {
  /usr/bin/python3 - "$tmp/$1/analysis.tsv" <<'PY'
import sys
lines = [l for l in open(sys.argv[1]).read().splitlines() if l.strip()]
head = lines[0].lstrip("#").split()
rows = [dict(zip(head, map(float, l.split()))) for l in lines[1:]]
print(rows[-1]["time"], rows[-1]["E_mag"] / rows[0]["E_mag"] - 1)
PY
}
