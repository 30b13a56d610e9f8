#!/usr/bin/env bash
# utils/magnetized_tov_energy_budget on the magnetised TOV star (1e16 G) on a coarse 32^2 grid for 1 ms
# (~5 s): the change of E_mag must be the time integral of the Lorentz-force power P = int F_ji psi^6 vt^j
# B^i sqrt f plus the psi part, to within what the coarse scheme dissipates (|rest| 1.5e-3 of E_mag, with
# |int P dt| up to 4.9e-3; a sign error in P leaves 8e-3, a missing psi^6 3e-3), and the estimate of the
# unbalanced Lorentz acceleration must give -dE_mag/E_mag/t^2 = 1.9e-3 / ms^2 (README, issue 15: the runs'
# dynamical part is 2.0-2.2e-3 at 64^2 and 128^2).
# Usage: energy_budget_script.sh <remnant> <source dir>
set -uo pipefail
exe=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! "$exe" "$src/parfiles/magnetized_tov_cyl_2d.yaml" 'active_thorns+=[IO]' 'Grid::ncells=[32,32,1]' \
     'Grid::xmax=[16,16,6.283185307179586]' Grid::max_level=0 'Grid::region_levels=[0]' MoL::final_time=200 \
     Analysis::every=2 Flesh::progress_every=0 Flesh::timers=false Flesh::out_dir="$tmp/out" IO::hdf5_every=2 \
     'IO::hdf5_variables=[HydroBase::prim,HydroBase::Bvec,Spacetime::metric]' IO::hdf5_xdmf=false \
     >"$tmp/run.log" 2>&1; then
  echo "FAIL: the run failed:"; tail -20 "$tmp/run.log"; exit 1
fi
if ! out=$("$src/utils/magnetized_tov_energy_budget" "$tmp/out" --every 50 --estimate 2>&1); then
  echo "FAIL: the tool failed:"; echo "$out"; exit 1
fi
echo "$out"
/usr/bin/python3 - "$out" <<'PY'
import re, sys
text = sys.argv[1]
e_tsv, e_file = map(float, re.search(r"E_mag\(0\) (\S+) \(analysis.tsv\), (\S+)", text).groups())
rest, work = map(float, re.search(r"largest \|rest\| (\S+), largest \|int P dt\| (\S+)", text).groups())
est = float(re.search(r"-dE_mag/E_mag/t\^2 = (\S+) 1/ms", text).group(1))
checks = [("E_mag(0) of the file vs analysis.tsv", abs(e_file / e_tsv - 1), 1e-3),
          ("largest |rest|", rest, 2e-3), ("estimate - 1.9e-3 [1/ms^2]", abs(est - 1.9e-3), 2e-4)]
ok = work > 3e-3
print(("ok  " if ok else "FAIL") + " largest |int P dt| %.3e (> 3e-3: the flow does measurable work)" % work)
for name, value, bound in checks:
    print(("ok  " if value < bound else "FAIL") + " %s %.3e (bound %.1e)" % (name, value, bound))
    ok = ok and value < bound
sys.exit(0 if ok else 1)
PY
