#!/bin/bash
# End to end on the command line: remnant-handoff-testdata writes BU0 as 3D Carpet data, remnant runs
# parfiles/handoff_tov_cyl_2d.yaml on it (hand-off only), the report and the profiles are written,
# and utils/plot_handoff reads the profiles; the report's 3D rest mass equals tools/carpet_check.py's
# independent sum over the files to 1e-12; a wrong file pattern fails with a message naming it;
# utils/handoff_evolution summarises a short evolution; parfiles/headon_handoff_cyl_2d.yaml asks for
# its file.
# usage: cli_handoff.sh REMNANT_EXE TESTDATA_EXE SOURCE_DIR
set -u
exe=$1 tool=$2 src=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
"$tool" --out=handoff_data > tool.log 2>&1 || fail "remnant-handoff-testdata: $(cat tool.log)"
[ -f handoff_data/tov3d.file_0.h5 ] && [ -f handoff_data/tov3d.file_1.h5 ] || fail "no Carpet files written"
"$exe" "$src/parfiles/handoff_tov_cyl_2d.yaml" MoL::final_time=0 Flesh::out_dir=out > run.log 2>&1 || fail "the hand-off run failed: $(tail -5 run.log)"
grep -q "^imported_rest_mass" out/handoff_report.txt || fail "no report"
grep -q "HandOff: note: no HydroBase::Y_e" run.log || fail "the missing Ye is not noted in the log"
python3 "$src/utils/plot_handoff" --no-plot out/handoff_profiles.tsv > plot.log 2>&1 || fail "plot_handoff: $(cat plot.log)"
grep -q "^line 0: 48 cells" plot.log && grep -q "^line 1: 48 cells" plot.log || fail "plot_handoff: $(cat plot.log)"
# The 3D rest mass against an independent reader (tools/carpet_check.py: h5py, no Remnant code).
if /usr/bin/python3 -c "import h5py, numpy" 2> /dev/null; then
  /usr/bin/python3 "$src/thorns/HandOff/tools/carpet_check.py" sum 'handoff_data/tov3d.file_*.h5' --mirrors xyz --buffer-zones 2 \
    > sum.log 2>&1 || fail "carpet_check.py: $(cat sum.log)"
  m_py=$(sed -n 's/.*3D rest mass \([^ ]*\).*/\1/p' sum.log)
  m_cpp=$(awk '$1 == "source_rest_mass" {print $2}' out/handoff_report.txt)
  awk -v a="$m_py" -v b="$m_cpp" 'BEGIN { d = a / b - 1; exit !(d < 1e-12 && d > -1e-12) }' ||
    fail "3D rest mass: carpet_check.py $m_py, the report $m_cpp"
else
  echo "note: /usr/bin/python3 without h5py: the independent rest-mass sum is skipped"
fi
if "$exe" "$src/parfiles/handoff_tov_cyl_2d.yaml" MoL::final_time=0 Flesh::out_dir=out2 'HandOff::files=[nowhere/*.h5]' > bad.log 2>&1; then
  fail "a pattern that matches nothing did not fail"
fi
grep -q "nowhere/\*.h5" bad.log || fail "the error does not name the pattern: $(tail -3 bad.log)"
# A few steps after the hand-off, summarised by utils/handoff_evolution (report and analysis.tsv).
"$exe" "$src/parfiles/handoff_tov_cyl_2d.yaml" MoL::final_time=5 Analysis::every=2 Flesh::out_dir=evol > evol.log 2>&1 ||
  fail "the short evolution failed: $(tail -5 evol.log)"
python3 "$src/utils/handoff_evolution" --every 1 evol > summary.log 2>&1 || fail "handoff_evolution: $(cat summary.log)"
grep -q "^hand-off: 3D rest mass on the grid" summary.log && grep -q "^rest mass + outflow - atmosphere source" summary.log &&
  grep -q "max |rho_c/rho_c(0) - 1|" summary.log || fail "handoff_evolution: $(cat summary.log)"
# The head-on hand-off parfile is complete but for the file, which the user names.
if "$exe" "$src/parfiles/headon_handoff_cyl_2d.yaml" EOS::type=ideal_gas Flesh::out_dir=out3 > headon.log 2>&1; then
  fail "parfiles/headon_handoff_cyl_2d.yaml ran without HandOff::files"
fi
grep -q "headon_handoff_cyl_2d.yaml:.*HandOff::files is empty" headon.log || fail "no HandOff::files error: $(tail -3 headon.log)"
echo "ok: $(grep '^normalisation' out/handoff_report.txt); 3D rest mass ${m_cpp:-} (carpet_check.py ${m_py:-skipped})"
