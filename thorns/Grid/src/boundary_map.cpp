#include "boundary_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "remnant/error.hpp"

namespace remnant::grid {

GlobalBox intersect(const GlobalBox& a, const GlobalBox& b) {
  GlobalBox r;
  for (std::size_t d = 0; d < 3; ++d) {
    r.lo[d] = std::max(a.lo[d], b.lo[d]);
    r.hi[d] = std::min(a.hi[d], b.hi[d]);
  }
  return r;
}

GlobalBox IndexMap::apply(const GlobalBox& b) const {
  GlobalBox r;
  for (std::size_t d = 0; d < 3; ++d) {
    if (sigma[d] > 0) {
      r.lo[d] = b.lo[d] + shift[d];
      r.hi[d] = b.hi[d] + shift[d];
    } else {
      r.lo[d] = shift[d] - (b.hi[d] - 1);
      r.hi[d] = shift[d] - b.lo[d] + 1;
    }
  }
  return r;
}

GlobalBox IndexMap::inverse(const GlobalBox& b) const {
  // i = sigma (j - shift): the same form with shift' = -sigma shift.
  IndexMap inv = *this;
  for (std::size_t d = 0; d < 3; ++d) inv.shift[d] = -sigma[d] * shift[d];
  return inv.apply(b);
}

double IndexMap::sign(const ComponentSpec& c) const {
  int s = 1;
  for (int idx : c.indices)
    if (idx >= 0) s *= basis_sign[static_cast<std::size_t>(idx)];
  if (mirrored && c.kind == TensorKind::axial_vector) s = -s;
  return s;
}

BoundaryMaps::BoundaryMaps(const GridConfig& config) : config_(config) {
  if (config.coordinates == CoordinateSystem::spherical && config.dimension >= 2) {
    const double dtheta = (config.xmax[1] - config.xmin[1]) / static_cast<double>(config.ncells[1]);
    theta_cells_to_pi_ = std::llround(std::numbers::pi / dtheta);
  }
}

Range BoundaryMaps::cells_on_level(int level) const {
  Range n{};
  for (std::size_t d = 0; d < 3; ++d)
    n[d] = static_cast<int>(d) < config_.dimension ? config_.ncells[d] << level : 1;
  return n;
}

namespace {
// T(j) = tau j + t composed after m.
void compose(IndexMap& m, int d, int tau, std::int64_t t) {
  const auto ud = static_cast<std::size_t>(d);
  m.sigma[ud] *= tau;
  m.shift[ud] = tau * m.shift[ud] + t;
}
}  // namespace

std::optional<IndexMap> BoundaryMaps::image(int level, const std::array<int, 3>& stagger, const GlobalBox& box) const {
  const Range n = cells_on_level(level);
  const int dim = config_.dimension;
  IndexMap m;
  // Each step moves the box into the domain in one direction; the origin may push theta out of
  // the domain again (equatorial symmetry), so allow a few rounds.
  for (int round = 0; round < 8; ++round) {
    const GlobalBox cur = m.apply(box);
    int d = -1;
    bool upper = false;
    for (int e = 0; e < dim && d < 0; ++e) {
      const auto ue = static_cast<std::size_t>(e);
      const std::int64_t points = n[ue] + stagger[ue];
      if (cur.hi[ue] <= 0) d = e;
      else if (cur.lo[ue] >= points) { d = e; upper = true; }
      else if (cur.lo[ue] < 0 || cur.hi[ue] > points)
        throw RunError("Grid: internal error: a ghost box straddles a domain face");
    }
    if (d < 0) return m;
    const auto ud = static_cast<std::size_t>(d);
    const std::int64_t s = stagger[ud];
    const Boundary bc = upper ? config_.boundary_upper[ud] : config_.boundary_lower[ud];
    // Mirror about the face: cells i -> -1 - i, faces i -> -i (and likewise at the upper face).
    auto mirror = [&](int e, bool up) {
      const auto ue = static_cast<std::size_t>(e);
      const std::int64_t se = stagger[ue];
      compose(m, e, -1, up ? 2 * n[ue] - (1 - se) : -(1 - se));
    };
    // Towards the middle of the phi range, so that a box holding the periodic face phi = 2 pi
    // (face-centred phi groups) lands inside instead of straddling the seam.
    auto shift_phi_by_pi = [&] {
      if (dim == 3) compose(m, 2, 1, cur.lo[2] >= n[2] / 2 ? -n[2] / 2 : n[2] / 2);
    };
    switch (bc) {
      case Boundary::outflow: return std::nullopt;
      case Boundary::periodic: compose(m, d, 1, upper ? -n[ud] : n[ud]); break;
      case Boundary::reflect:
        mirror(d, upper);
        m.basis_sign[ud] = -m.basis_sign[ud];
        m.mirrored = !m.mirrored;
        break;
      case Boundary::axis:
        mirror(d, upper);
        m.basis_sign[ud] = -m.basis_sign[ud];
        shift_phi_by_pi();
        break;
      case Boundary::origin:
        // (-r, theta, phi) is (r, pi - theta, phi + pi): d_r and d_theta flip, d_phi does not.
        mirror(0, false);
        m.basis_sign[0] = -m.basis_sign[0];
        m.basis_sign[1] = -m.basis_sign[1];
        if (dim >= 2) compose(m, 1, -1, (theta_cells_to_pi_ << level) - (1 - stagger[1]));
        shift_phi_by_pi();
        break;
    }
    (void)s;
  }
  throw RunError("Grid: internal error: no image of a ghost box in the domain");
}

}  // namespace remnant::grid
