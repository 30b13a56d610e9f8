#!/bin/bash
# Smoke test of the scaling model's chain: a tiny 3D refined GRMHD + xCFC run with
# Flesh::comm_stats on 1 and 2 ranks, the MPI ping-pong, then utils/scaling_model on their outputs
# (prediction for 2 ranks, projection, plot).
# Usage: scaling_model.sh REMNANT MPI_PINGPONG MPI_CPU_PRELOAD SOURCE_DIR
set -euo pipefail
remnant=$1 pingpong=$2 preload=$3 src=$4
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
export OMPI_MCA_mpi_yield_when_idle=1
out=$(mktemp -d /tmp/remnant-scaling-model-XXXXXX)
trap 'rm -rf "$out"' EXIT
cd "$src"
args=(Grid::ncells=[16,16,8] Grid::max_level=1 Grid::regions=[box] Grid::region_levels=[1]
      Grid::region_bounds=[-32,32,-32,32,0,32] MoL::final_time=6 XCFC::solve_every=1 XCFC::tolerance_initial=1e-6
      Flesh::comm_stats=true Flesh::progress_every=0 Flesh::timers=false Analysis::every=1000)
for np in 1 2; do
  mpirun -np $np --oversubscribe "$remnant" parfiles/rns_uniform_cart_3d.yaml "${args[@]}" Flesh::out_dir="$out/np$np" \
    > "$out/np$np.log" 2>&1 || { cat "$out/np$np.log"; exit 1; }
done
# The 1-rank run sends and gathers nothing; the 2-rank run exchanges ghosts and gathers multigrid levels.
awk -F'\t' '($4 == "p2p" || $4 == "allgather") && $7 > 0 { bad = 1 } END { exit bad }' "$out/np1/comm.tsv" ||
  { echo "FAIL: a 1-rank run counted bytes"; exit 1; }
for kind in ghost_exchange mg_tier_exchange xcfc_bridge_allreduce; do
  awk -F'\t' -v k=$kind '$2 == k && $7 > 0 { found = 1 } END { exit !found }' "$out/np2/comm.tsv" ||
    { echo "FAIL: no $kind bytes in the 2-rank comm.tsv"; exit 1; }
done
mpirun -np 2 --oversubscribe "$pingpong" > "$out/pingpong.tsv"
/usr/bin/python3 utils/scaling_model/scaling_model --measured "$out/np1/comm.tsv" --measured2 "$out/np2/comm.tsv" \
  --pingpong "$out/pingpong.tsv" --max-ranks 100 --plot "$out/scaling.png" | tee "$out/model.txt"
grep -q "model:    1 rank" "$out/model.txt" || { echo "FAIL: no 2-rank prediction"; exit 1; }
grep -qE "^ +100 " "$out/model.txt" || { echo "FAIL: no row for 100 ranks"; exit 1; }
test -s "$out/scaling.png" || { echo "FAIL: no plot"; exit 1; }
echo "scaling model smoke test passed"
