#include "forest.hpp"

#include <algorithm>

#include "morton.hpp"
#include "remnant/error.hpp"

namespace remnant::grid {

Forest::Forest(const GridConfig& config, std::vector<BlockKey> leaves, int nranks)
    : dimension_(config.dimension), nranks_(nranks), leaves_(std::move(leaves)) {
  for (std::size_t d = 0; d < 3; ++d) {
    block_cells_[d] = config.block_size[d];
    base_blocks_[d] = config.ncells[d] / config.block_size[d];
  }
  for (const BlockKey& k : leaves_) finest_level_ = std::max(finest_level_, k.level);
  // Position on the finest level: leaves never overlap, so the keys are distinct.
  const int finest = finest_level_;
  auto curve_key = [finest](const BlockKey& k) {
    const int shift = finest - k.level;
    return morton_key({k.index[0] << shift, k.index[1] << shift, k.index[2] << shift});
  };
  // Non-power-of-two counts simply skip the missing keys: the order stays a Z-curve.
  std::stable_sort(leaves_.begin(), leaves_.end(),
                   [&](const BlockKey& a, const BlockKey& b) { return curve_key(a) < curve_key(b); });
  gid_of_.reserve(leaves_.size() * 2);
  for (std::size_t g = 0; g < leaves_.size(); ++g)
    if (!gid_of_.emplace(leaves_[g], static_cast<std::int64_t>(g)).second)
      throw RunError("Grid: block (level " + std::to_string(leaves_[g].level) + ") listed twice");
}

std::vector<BlockKey> Forest::base_level(const GridConfig& c) {
  std::vector<BlockKey> out;
  const std::int64_t nb[3] = {c.ncells[0] / c.block_size[0], c.ncells[1] / c.block_size[1], c.ncells[2] / c.block_size[2]};
  for (std::int64_t k = 0; k < nb[2]; ++k)
    for (std::int64_t j = 0; j < nb[1]; ++j)
      for (std::int64_t i = 0; i < nb[0]; ++i) out.push_back(BlockKey{0, {i, j, k}});
  return out;
}

BlockIndex Forest::blocks_on_level(int level) const {
  BlockIndex b = base_blocks_;
  for (int d = 0; d < dimension_; ++d) b[static_cast<std::size_t>(d)] <<= level;
  return b;
}

std::int64_t Forest::find(int level, const BlockIndex& index) const {
  auto it = gid_of_.find(BlockKey{level, index});
  return it == gid_of_.end() ? -1 : it->second;
}

std::vector<std::int64_t> Forest::blocks_per_level() const {
  std::vector<std::int64_t> n(static_cast<std::size_t>(finest_level_ + 1), 0);
  for (const BlockKey& k : leaves_) ++n[static_cast<std::size_t>(k.level)];
  return n;
}

std::int64_t Forest::first_gid(int rank) const {
  const std::int64_t total = total_blocks();
  const std::int64_t base = total / nranks_, extra = total % nranks_;
  const std::int64_t r = rank;
  return r * base + std::min(r, extra);
}

int Forest::owner(std::int64_t gid) const {
  int lo = 0, hi = nranks_ - 1;
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (first_gid(mid) <= gid) lo = mid; else hi = mid - 1;
  }
  // Ranks without blocks share a first_gid with the next one.
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
