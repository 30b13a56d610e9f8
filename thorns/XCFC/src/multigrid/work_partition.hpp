#pragma once
// The MPI work partition of a multigrid hierarchy. By default arrays are complete on every rank
// and only the work is split; with distributed storage (3D levels) a split level's arrays hold only
// the owned slab and its halo planes (Level::set_window), and the first level below the split is
// agglomerated: every rank restricts its own slab into it and MPI_Allgatherv completes it. The work
// is split the same way in both: each level of dimension >= 2 that is large enough is cut in slabs of planes along
// its last used direction (k in 3D, j in 2D); a rank computes its own planes and keeps one halo
// plane on each side current (MPI_Sendrecv) before every stencil operation. Smaller (coarser)
// levels are computed by every rank redundantly, from inputs made complete by MPI_Allgatherv.
// With MPI_COMM_SELF no MPI call is made.
#include <mpi.h>

#include <cstddef>
#include <vector>

#include "level_ops.hpp"

namespace remnant::xcfc {

class WorkPartition {
 public:
  // Work partition of one level. Owned planes [lo, hi) along direction s (all of them when not
  // distributed); 2D: the lines along s are solved whole, split by i instead: [line_lo, line_hi).
  struct Part {
    bool dist = false;
    int s = 0, lo = 0, hi = 1, line_lo = 0, line_hi = 1;
    bool flip = false;                     // 2D, the origin's mirror cell lies at theta index n1-1-j: on another rank
    std::ptrdiff_t plane = 0, iplane = 0;  // ghosted / interior plane sizes along s
    // MPI_Allgatherv layouts per rank: ghosted planes, interior planes, the i = 0 column (flip),
    // and the packed column blocks of the line split.
    std::vector<int> counts, displs, icounts, idispls, col_counts, col_displs, blk_counts, blk_displs;
    std::vector<double> sbuf, rbuf, gbuf;  // exchange buffers (no allocation in the cycles)
    // 2D transposes between slabs and the line split (MPI_Alltoallv layouts): columns [cols[r],
    // cols[r + 1]) belong to rank r, which also receives one neighbouring column on each side.
    std::vector<int> cols, tc_s, tc_sd, tc_r, tc_rd, ts_s, ts_sd, ts_r, ts_rd;
    std::vector<double> tsend, trecv;
    std::vector<int> root_counts, root_displs;  // columns_to_root layout (rows per rank times ncols)
    // Distributed storage: this split level's arrays hold only its window (ghosted offset gbase).
    bool windowed = false;
    std::ptrdiff_t gbase = 0;
    // The first level below a windowed split: each rank restricts into the planes [agg_lo, agg_hi)
    // under its fine slab; MPI_Allgatherv layouts of those planes in interior and ghosted arrays.
    bool agglomerated = false;
    int agg_lo = 0, agg_hi = 0;
    std::vector<int> agg_counts, agg_displs, agg_gcounts, agg_gdispls;
  };
  // Below this a level is not split: the halo messages would cost more than the work saved.
  static constexpr std::size_t kMinCells = 1024;

  explicit WorkPartition(MPI_Comm c);
  ~WorkPartition();
  WorkPartition(const WorkPartition&) = delete;
  WorkPartition& operator=(const WorkPartition&) = delete;

  // Partitions a hierarchy (kept by reference: it must outlive this and not reallocate).
  // rank0_extra[l]: lines along the split direction that rank 0 relaxes alone on level l (the
  // origin shells' extra passes); the 2D line split gives rank 0 that many fewer columns.
  // distributed_storage: 3D split levels keep only their slabs (the coarsest split level's cuts
  // then fall on even planes, so that each cell of the level below is restricted by one rank).
  void build(const std::vector<Level>& levels, const std::vector<int>& rank0_extra = {}, bool distributed_storage = false);
  const Part& part(std::size_t l) const { return parts[l]; }
  const std::vector<Part>& all_parts() const { return parts; }
  int rank() const { return rank_; }
  int nranks() const { return nranks_; }
  // The interior cells this rank works on (all of a level that is not split).
  Range range(std::size_t l) const;
  // The cells of an agglomerated level this rank restricts into (all of any other level that is
  // not split; range(l) of a split one).
  Range restricted_range(std::size_t l) const;
  // An agglomerated level's array complete on every rank from each rank's restricted planes.
  void agglomerate(std::size_t l, std::vector<double>& a, bool ghosted) const;
  Range full(std::size_t l) const { return full_range((*lv)[l]); }

  double global_max(double m) const;
  MPI_Comm communicator() const { return comm; }
  // Owned planes (with their in-plane ghosts) of a ghosted or interior array to every rank.
  void replicate(std::size_t l, std::vector<double>& a, bool ghosted) const;
  // The halo planes lo-1 and hi of a ghosted array from the neighbouring ranks (and, where the
  // origin's mirror crosses ranks, the column i = 0): what the stencils of the owned cells and the
  // boundary ghosts they read need.
  void halo(std::size_t l, std::vector<double>& a);
  // 2D line split (lines along j, owned by i): the neighbouring lines line_lo-1 and line_hi.
  void exchange_columns(std::size_t l, std::vector<double>& a);
  // 2D line split: the owned lines to every rank (the whole interior complete again).
  void gather_columns(std::size_t l, std::vector<double>& a);
  // 2D: from slabs to the line split, each rank's columns and their neighbours complete in j
  // (1/P of the level per rank, where replicate moves all of it), and back, each rank's slab
  // complete in i again (halo planes not included: halo() before the next stencil).
  void to_columns(std::size_t l, std::vector<double>& a);
  void to_slabs(std::size_t l, std::vector<double>& a);
  // 2D: the first `ncols` columns of every row to rank 0, which then holds them complete in j
  // (MPI_Gatherv), and back from rank 0 to the slabs' owners (MPI_Scatterv).
  void columns_to_root(std::size_t l, std::vector<double>& a, int ncols);
  void columns_from_root(std::size_t l, std::vector<double>& a, int ncols);
  // Bytes this rank has received in the multigrid's exchanges (machine-independent cost count).
  long long received_bytes() const { return received_; }

 private:
  bool splittable(const GridShape& s) const;
  // First column of each rank's line split (nranks + 1 entries) of n0 columns, rank 0 relaxing
  // `extra` lines besides its own: balanced in lines, at least one column per rank.
  std::vector<int> line_cuts(int n0, int extra) const;
  void set_transposes(Part& p, const GridShape& sh, const std::vector<int>& slab, const std::vector<int>& cols);
  int neighbour(int dr) const;

  MPI_Comm comm = MPI_COMM_SELF;
  int rank_ = 0, nranks_ = 1;
  const std::vector<Level>* lv = nullptr;
  std::vector<Part> parts;
  mutable long long received_ = 0;
};

}  // namespace remnant::xcfc
