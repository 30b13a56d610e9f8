#include "outer_boundary.hpp"

#include <cstddef>

namespace remnant::grid {

namespace {

// Sets the ghost layers of one face of one component: outflow copies the nearest interior layer,
// reflect mirrors the interior across the face and multiplies by the parity.
void fill_face(const Field& f, const Block& b, int d, bool upper, Boundary bc, double parity) {
  const std::size_t ud = static_cast<std::size_t>(d);
  const std::ptrdiff_t stride[3] = {1, f.sj, f.sk};
  // The two other directions, over their full extent (ghosts included); `a` is the lower one so
  // that the inner loop is contiguous where possible.
  const int a = d == 0 ? 1 : 0, c = d == 2 ? 1 : 2;
  const auto ua = static_cast<std::size_t>(a), uc = static_cast<std::size_t>(c);
  const int a_lo = -b.ng[ua], a_hi = b.n[ua] + b.ng[ua];
  const int c_lo = -b.ng[uc], c_hi = b.n[uc] + b.ng[uc];
  const int n = b.n[ud];
  for (int m = 0; m < b.ng[ud]; ++m) {
    const int ghost = upper ? n + m : -1 - m;
    const int source = bc == Boundary::reflect ? (upper ? n - 1 - m : m) : (upper ? n - 1 : 0);
    for (int ic = c_lo; ic < c_hi; ++ic)
      for (int ia = a_lo; ia < a_hi; ++ia) {
        const std::ptrdiff_t base = ia * stride[a] + ic * stride[c];
        f.origin[base + ghost * stride[d]] = parity * f.origin[base + source * stride[d]];
      }
  }
}

}  // namespace

void apply_outer_boundaries(Block& block, const BlockLayout& layout, const UniformGridConfig& config,
                            const VariableRegistry& vars, std::span<const int> groups) {
  for (int d = 0; d < layout.dimension(); ++d) {
    const auto ud = static_cast<std::size_t>(d);
    for (const bool upper : {false, true}) {
      const Boundary bc = upper ? config.boundary_upper[ud] : config.boundary_lower[ud];
      if (bc == Boundary::periodic) continue;
      if (upper ? !layout.at_upper_face(block.gid, d) : !layout.at_lower_face(block.gid, d)) continue;
      for (int g : groups) {
        const auto& spec = vars.group(g);
        for (int comp = 0; comp < spec.ncomp(); ++comp) {
          const double parity =
              bc == Boundary::reflect ? spec.components[static_cast<std::size_t>(comp)].reflection_parity[ud] : 1.0;
          fill_face(block.field(g, comp), block, d, upper, bc, parity);
        }
      }
    }
  }
}

}  // namespace remnant::grid
