#pragma once
// The share of a composite field's pointwise work (sources, equation coefficients, A^ij, vector
// transformations) that one rank computes: the cells of all parts taken in storage order (base,
// then the patches) and cut into contiguous chunks balanced by cells, one per rank. complete()
// makes fields whole again on every rank by MPI_Allgatherv of the chunks: the values are
// copied, not recomputed or summed, so the bits do not depend on the number of ranks. Below
// kMinCells (and on one rank) every rank computes everything and complete() does nothing.
#include <mpi.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace remnant::xcfc {

class CellShare {
 public:
  // Below this a field is not split: the gather would cost more than the work saved (as WorkPartition).
  static constexpr std::size_t kMinCells = 1024;

  CellShare() = default;
  // part_sizes: the cells of each part (interior or ghosted arrays).
  CellShare(const std::vector<std::size_t>& part_sizes, MPI_Comm comm);

  bool split() const { return split_; }
  // [begin, end) of part n's cells that this rank computes (possibly empty).
  std::pair<std::size_t, std::size_t> range(int n) const;
  // Cells this rank computes, of all parts, and the total.
  std::size_t cells() const { return end_ - begin_; }
  std::size_t total() const { return offsets_.empty() ? 0 : offsets_.back(); }
  // The fields' parts (each sized like part_sizes) complete on every rank.
  void complete(const std::vector<std::vector<std::vector<double>>*>& fields) const;
  // Cells computed in this share's loops since construction (for_share_cells counts them): the
  // measure of the pointwise work this rank did.
  void count(std::size_t n) const { computed_ += static_cast<long long>(n); }
  long long computed() const { return computed_; }

 private:
  MPI_Comm comm_ = MPI_COMM_SELF;
  int rank_ = 0, nranks_ = 1;
  bool split_ = false;
  std::vector<std::size_t> offsets_;  // first flat cell of each part, then the total
  std::vector<std::size_t> cuts_;     // first flat cell of each rank's chunk, then the total
  std::size_t begin_ = 0, end_ = 0;   // this rank's chunk
  mutable std::vector<double> send_, recv_;
  mutable long long computed_ = 0;
};

}  // namespace remnant::xcfc
