#include "step_start_copy.hpp"

#include <algorithm>

namespace remnant::mol {

std::array<int, 3> interior_points(const Block& b, Centering c) {
  const auto e = b.extent(c);
  return {e[0] - 2 * b.ng[0], e[1] - 2 * b.ng[1], e[2] - 2 * b.ng[2]};
}

void StepStartCopy::save(std::span<Block* const> blocks, const std::vector<int>& groups,
                         const VariableRegistry& vars) {
  std::vector<std::int64_t> ids;
  ids.reserve(blocks.size());
  for (const Block* b : blocks) ids.push_back(b->gid);
  if (ids != blocks_) {
    copies_.clear();
    blocks_ = std::move(ids);
  }
  for (Block* b : blocks)
    for (int g : groups) {
      const auto& spec = vars.group(g);
      Copy& copy = copies_[{b->gid, g}];
      copy.points = interior_points(*b, spec.centering);
      const auto [ni, nj, nk] = copy.points;
      copy.values.resize(static_cast<std::size_t>(spec.ncomp()) * static_cast<std::size_t>(ni) *
                         static_cast<std::size_t>(nj) * static_cast<std::size_t>(nk));
      double* out = copy.values.data();
      for (int c = 0; c < spec.ncomp(); ++c) {
        const Field u = b->field(g, c);
        for (int k = 0; k < nk; ++k)
          for (int j = 0; j < nj; ++j, out += ni) std::copy_n(&u(0, j, k), ni, out);
      }
    }
}

const double* StepStartCopy::row(std::int64_t gid, int g, int c, int j, int k) const {
  const Copy& copy = copies_.at({gid, g});
  const auto [ni, nj, nk] = copy.points;
  return copy.values.data() + ((static_cast<std::size_t>(c) * static_cast<std::size_t>(nk) + static_cast<std::size_t>(k)) *
                                   static_cast<std::size_t>(nj) +
                               static_cast<std::size_t>(j)) *
                                  static_cast<std::size_t>(ni);
}

std::size_t StepStartCopy::bytes() const {
  std::size_t n = 0;
  for (const auto& [key, copy] : copies_) n += copy.values.capacity() * sizeof(double);
  return n;
}

}  // namespace remnant::mol
