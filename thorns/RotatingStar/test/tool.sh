#!/usr/bin/env bash
# remnant-rotstar end to end: one model prints `name = value` lines (exit 0), a sequence writes a TSV
# and stops with exit 1 at mass shedding, bad input gives a clear error and a non-zero exit, never
# a NaN model. Usage: tool.sh <remnant-rotstar> <source dir>
set -uo pipefail
exe=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() {  # name, expected exit code, pattern expected in the output, command...
  local name=$1 code=$2 pattern=$3
  shift 3
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  if [ "$rc" != "$code" ] || ! grep -qE -e "$pattern" <<<"$out" || grep -qiE "= *-?nan" <<<"$out"; then
    echo "FAIL $name (exit $rc, expected $code; pattern '$pattern'):"; echo "$out" | head -5; fail=1
  else echo "ok   $name"; fi
}
check uniform 0 "^M_komar = 1\.528" "$exe" --K=100 --gamma=2 --rho-c=1.28e-3 --omega=0.02
check axis_ratio 0 "^axis_ratio = 0\.7$" "$exe" --rho-c=1.28e-3 --axis-ratio=0.7 --nr=200
check j_constant 0 "^Omega_e = 0\.009" "$exe" --rho-c=1.28e-3 --A2=70 --omega-c=0.02575 --nr=200
check piecewise 0 "^M_komar = " "$exe" --K=100 --gammas=2,3 --rho-bounds=5e-4 --rho-c=1.28e-3 --axis-ratio=0.8 --nr=200
check piecewise_bad 1 "Gammas need 1 density divisions" "$exe" --K=100 --gammas=2,3 --rho-c=1.28e-3 --omega=0.01 --nr=200
check beyond_shedding 1 "beyond mass shedding" "$exe" --rho-c=1.28e-3 --omega=0.04 --nr=200
check toroidal_field 0 "^H_over_W = 0\.2017" "$exe" --K=110 --rho-c=1.366e-3 --Km=3.746 --m=1 --nr=200
check toroidal_gauss 0 "^B_max_gauss = 6\.13[0-9]*e\+17" "$exe" --K=110 --rho-c=1.366e-3 --Km=3.746 --nr=200
check toroidal_too_wide 1 "toroidal field \(K_m = 6\) makes the star prolate: try r_out_factor 3" "$exe" --rho-c=1.28e-3 --Km=6 --nr=200
check toroidal_bad_m 1 "m = 0.5 of the toroidal field must be >= 1" "$exe" --rho-c=1.28e-3 --Km=3 --m=0.5 --nr=100
check m_without_km 2 "--m is the exponent of the toroidal field: it needs --Km" "$exe" --rho-c=1.28e-3 --m=2
check bad_number 2 "--omega=abc: not a number" "$exe" --rho-c=1.28e-3 --omega=abc
check unknown_option 2 "unknown option --omgea" "$exe" --rho-c=1.28e-3 --omgea=0.01
check both_targets 2 "not both" "$exe" --rho-c=1.28e-3 --omega=0.01 --axis-ratio=0.8
check static_ratio 0 "^Omega_c = 0$" "$exe" --rho-c=1.28e-3 --axis-ratio=1 --nr=100
check sequence 1 "the sequence stops here" "$exe" --rho-c=1.28e-3 --nr=100 --sequence=axis-ratio:0.9:0.5:5 --out="$tmp/seq.tsv"
rows=$(($(wc -l <"$tmp/seq.tsv") - 1))
if [ "$rows" = 4 ] && head -1 "$tmp/seq.tsv" | grep -q "M_komar"; then echo "ok   sequence_tsv ($rows models before shedding)";
else echo "FAIL sequence_tsv: $rows rows"; cat "$tmp/seq.tsv"; fail=1; fi
check sequence_rho 0 "^wrote " "$exe" --rho-c=1e-3 --axis-ratio=0.8 --nr=100 --sequence=rho-c:8e-4:1.6e-3:3 --out="$tmp/rho.tsv"
if [ "$(cut -f1 "$tmp/rho.tsv" | tr '\n' ' ')" = "rho_c 0.0008 0.0012 0.0016 " ]; then echo "ok   sequence_rho_tsv (central densities)";
else echo "FAIL sequence_rho_tsv:"; cat "$tmp/rho.tsv"; fail=1; fi
table="$src/../shared/eos/SFHo_reduced_39r_39t_20y.h5"
if [ -f "$table" ]; then
  check table_density 1 "outside the EOS table's density range" "$exe" --eos-table="$table" --rho-c=100 --omega=0.01
  check table_fixed_ye 0 "^M_komar = 1\.33" "$exe" --eos-table="$table" --rho-c=1.2e-3 --omega=0.02633 --ye=0.1 --T=0.5 --nr=200
  check table_bad_ye 1 "slice Ye 0.9 is outside the table's range" "$exe" --eos-table="$table" --rho-c=1.2e-3 --omega=0.01 --ye=0.9
  check table_model 0 "^M_komar = 1\.3" "$exe" --eos-table="$table" --rho-c=1.2e-3 --omega=0.02633 --nr=200
else echo "skip table checks: $table missing"; fi
exit $fail
