#!/bin/bash
# The 2-rank check of the scaling model: the 3D Cartesian refined rotating star (parfiles/
# rns_uniform_cart_3d.yaml at max_level 2: 45,056 cells in 88 blocks of 8^3 on 3 levels), 12 steps
# with an xCFC solve every 3, run REPEATS times on 1 and on 2 ranks (alternately: the machine is
# shared, so the fastest of each is kept), then the model's prediction for 2 ranks next to it. A
# rank's work is its CPU time outside MPI (mpi_cpu_preload), which other jobs on the machine do not
# change; wall time is printed as well.
# Usage: utils/scaling_model/check_two_ranks.sh [build_dir] [out_dir] [repeats]
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$src/build}
out=${2:-$src/output/scaling_check}
repeats=${3:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
# A waiting rank gives its core away (the machine may be oversubscribed).
export OMPI_MCA_mpi_yield_when_idle=1
args=(Grid::max_level=2 Grid::regions=[box,box] Grid::region_levels=[1,2]
      Grid::region_bounds=[-32,32,-32,32,0,32,-16,16,-16,16,0,16] MoL::final_time=7.4 XCFC::solve_every=3
      Flesh::comm_stats=true Flesh::progress_every=0 Analysis::every=1000)
# CPU time inside MPI (comm.tsv clock:mpi_cpu), so that a rank's work is its CPU time outside MPI.
preload=$build/libmpi_cpu_preload.so
test -f "$preload" || { echo "check_two_ranks: $preload missing: cmake --build $build --target mpi_cpu_preload"; exit 1; }
mkdir -p "$out"
cd "$src"
for r in $(seq 1 "$repeats"); do
  for np in 1 2; do
    mpirun -np $np --oversubscribe -x LD_PRELOAD="$preload" "$build/bin/remnant" parfiles/rns_uniform_cart_3d.yaml "${args[@]}" \
      Flesh::out_dir="$out/np${np}_run$r" > "$out/np${np}_run$r.log" 2>&1
  done
done
mpirun -np 2 --oversubscribe "$build/bin/mpi_pingpong" > "$out/pingpong.tsv"
/usr/bin/python3 utils/scaling_model/scaling_model --measured "$out/np1_run*/comm.tsv" \
  --measured2 "$out/np2_run*/comm.tsv" --pingpong "$out/pingpong.tsv" --plot "$out/scaling.png"
