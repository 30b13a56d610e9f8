#include "outer_boundary.hpp"

#include <cstddef>

namespace remnant::grid {

namespace {

// Copies the outermost interior layer (cells or faces) of direction d into the ghost layers.
void fill_face(const Field& f, const Block& b, const std::array<int, 3>& stagger, int d, bool upper) {
  const std::size_t ud = static_cast<std::size_t>(d);
  const std::ptrdiff_t stride[3] = {1, f.sj, f.sk};
  // The two other directions over their full extent (ghosts included); `a` is the lower one so
  // that the inner loop is contiguous where possible.
  const int a = d == 0 ? 1 : 0, c = d == 2 ? 1 : 2;
  const auto ua = static_cast<std::size_t>(a), uc = static_cast<std::size_t>(c);
  const int sa = b.ng[ua] > 0 ? stagger[ua] : 0, sc = b.ng[uc] > 0 ? stagger[uc] : 0;
  const int a_lo = -b.ng[ua], a_hi = b.n[ua] + sa + b.ng[ua];
  const int c_lo = -b.ng[uc], c_hi = b.n[uc] + sc + b.ng[uc];
  const int points = b.n[ud] + stagger[ud];
  for (int m = 0; m < b.ng[ud]; ++m) {
    const int ghost = upper ? points + m : -1 - m;
    const int source = upper ? points - 1 : 0;
    for (int ic = c_lo; ic < c_hi; ++ic)
      for (int ia = a_lo; ia < a_hi; ++ia) {
        const std::ptrdiff_t base = ia * stride[a] + ic * stride[c];
        f.origin[base + ghost * stride[d]] = f.origin[base + source * stride[d]];
      }
  }
}

}  // namespace

void apply_outflow(Block& block, const Forest& forest, const GridConfig& config, const VariableRegistry& vars,
                   std::span<const int> groups, const std::map<int, std::vector<GridDriver::OutflowCondition>>& conditions) {
  const BlockIndex nb = forest.blocks_on_level(block.level);
  for (int d = 0; d < forest.dimension(); ++d) {
    const auto ud = static_cast<std::size_t>(d);
    for (const bool upper : {false, true}) {
      const Boundary bc = upper ? config.boundary_upper[ud] : config.boundary_lower[ud];
      if (bc != Boundary::outflow) continue;
      if (upper ? block.index[ud] != nb[ud] - 1 : block.index[ud] != 0) continue;
      for (int g : groups) {
        const auto& spec = vars.group(g);
        const auto stagger = staggering(spec.centering);
        for (int comp = 0; comp < spec.ncomp(); ++comp) fill_face(block.field(g, comp), block, stagger, d, upper);
        if (const auto it = conditions.find(g); it != conditions.end())
          for (const auto& condition : it->second) condition(block, d, upper);
      }
    }
  }
}

}  // namespace remnant::grid
