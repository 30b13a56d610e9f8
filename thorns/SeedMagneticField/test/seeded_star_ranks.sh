#!/usr/bin/env bash
# The seeded magnetised TOV parfiles at t = 0 (after the xCFC initial metric) on 1 and 2 ranks: the
# analysis.tsv rows (with divB_max, E_mag, E_mag_pol, E_mag_tor, B_max) are identical, divB_max is
# at round-off and B_max is the asked 1e16 G up to the xCFC re-solve of psi (0.1 %).
# Usage: seeded_star_ranks.sh <remnant> <source dir> <mpiexec>
set -uo pipefail
exe=$1
src=$2
mpiexec=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
for p in magnetized_tov_cyl_2d magnetized_tov_sph_2d magnetized_tov_cart_3d toroidal_tov_sph_2d; do
  for n in 1 2; do
    if ! "$mpiexec" -n $n --oversubscribe "$exe" "$src/parfiles/$p.yaml" MoL::final_time=0 Flesh::timers=false \
         Flesh::out_dir="$tmp/$p.$n" >"$tmp/$p.$n.log" 2>&1; then
      echo "FAIL $p on $n ranks:"; tail -20 "$tmp/$p.$n.log"; failed=1; continue 2
    fi
  done
  if ! cmp -s "$tmp/$p.1/analysis.tsv" "$tmp/$p.2/analysis.tsv"; then
    echo "FAIL $p: analysis.tsv differs between 1 and 2 ranks"; diff "$tmp/$p.1/analysis.tsv" "$tmp/$p.2/analysis.tsv"; failed=1
  fi
  if ! /usr/bin/python3 - "$tmp/$p.1/analysis.tsv" "$p" <<'PY'
import sys
path, name = sys.argv[1], sys.argv[2]
lines = open(path).read().splitlines()
head = lines[0].lstrip("#").split()
row = dict(zip(head, map(float, lines[1].split())))
ok = row["divB_max"] < 1e-14 and row["E_mag"] > 0
if name.startswith("magnetized"):
    ok = ok and abs(row["B_max"] / 1e16 - 1) < 1e-3 and row["E_mag_tor"] < 1e-5 * row["E_mag"]
else:
    ok = ok and row["E_mag_pol"] == 0 and 2e17 < row["B_max"] < 2e18
print(("ok   " if ok else "FAIL ") + "%s: divB_max %.2e, B_max %.6e G, E_mag %.6e (pol %.4e, tor %.4e)" %
      (name, row["divB_max"], row["B_max"], row["E_mag"], row["E_mag_pol"], row["E_mag_tor"]))
sys.exit(0 if ok else 1)
PY
  then failed=1; fi
done
exit $failed
