#include "block_layout.hpp"

#include <algorithm>
#include <numeric>

#include "morton.hpp"
#include "remnant/error.hpp"

namespace remnant::grid {

BlockLayout::BlockLayout(const UniformGridConfig& config, int nranks)
    : dimension_(config.dimension), nranks_(nranks) {
  for (std::size_t d = 0; d < 3; ++d) {
    nblocks_[d] = config.ncells[d] / config.block_size[d];
    periodic_[d] = static_cast<int>(d) < dimension_ && config.boundary_lower[d] == Boundary::periodic;
    if (nblocks_[d] >= (std::int64_t{1} << 21))
      throw InputError({"Grid::block_size", 0, 0}, "Grid: more than 2^21 blocks in one direction");
  }
  const std::int64_t total = nblocks_[0] * nblocks_[1] * nblocks_[2];
  index_by_gid_.reserve(static_cast<std::size_t>(total));
  for (std::int64_t k = 0; k < nblocks_[2]; ++k)
    for (std::int64_t j = 0; j < nblocks_[1]; ++j)
      for (std::int64_t i = 0; i < nblocks_[0]; ++i) index_by_gid_.push_back({i, j, k});
  // Non-power-of-two counts simply skip the missing keys: the order stays a Z-curve.
  std::stable_sort(index_by_gid_.begin(), index_by_gid_.end(),
                   [](const BlockIndex& a, const BlockIndex& b) { return morton_key(a) < morton_key(b); });
  gid_by_linear_index_.assign(static_cast<std::size_t>(total), -1);
  for (std::int64_t gid = 0; gid < total; ++gid) {
    const auto& ix = index_by_gid_[static_cast<std::size_t>(gid)];
    gid_by_linear_index_[static_cast<std::size_t>(ix[0] + nblocks_[0] * (ix[1] + nblocks_[1] * ix[2]))] = gid;
  }
}

std::int64_t BlockLayout::gid_of(const BlockIndex& ix) const {
  return gid_by_linear_index_[static_cast<std::size_t>(ix[0] + nblocks_[0] * (ix[1] + nblocks_[1] * ix[2]))];
}

std::int64_t BlockLayout::neighbour(std::int64_t gid, const Offset& offset) const {
  BlockIndex ix = index_of(gid);
  for (std::size_t d = 0; d < 3; ++d) {
    ix[d] += offset[d];
    if (ix[d] < 0 || ix[d] >= nblocks_[d]) {
      if (!periodic_[d]) return -1;
      ix[d] = (ix[d] + nblocks_[d]) % nblocks_[d];
    }
  }
  return gid_of(ix);
}

std::int64_t BlockLayout::first_gid(int rank) const {
  const std::int64_t total = total_blocks();
  const std::int64_t base = total / nranks_, extra = total % nranks_;
  const std::int64_t r = rank;
  return r * base + std::min(r, extra);
}

int BlockLayout::owner(std::int64_t gid) const {
  // first_gid is monotonic: binary search over ranks.
  int lo = 0, hi = nranks_ - 1;
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (first_gid(mid) <= gid) lo = mid; else hi = mid - 1;
  }
  // Ranks without blocks share a first_gid with the next one; the search lands on the last of
  // them, which owns the block only if its range is not empty.
  while (block_count(lo) == 0) --lo;
  return lo;
}

std::vector<Offset> neighbour_offsets(int dimension) {
  std::vector<Offset> out;
  const int kz = dimension >= 3 ? 1 : 0, ky = dimension >= 2 ? 1 : 0;
  for (int k = -kz; k <= kz; ++k)
    for (int j = -ky; j <= ky; ++j)
      for (int i = -1; i <= 1; ++i)
        if (i != 0 || j != 0 || k != 0) out.push_back({i, j, k});
  return out;
}

}  // namespace remnant::grid
