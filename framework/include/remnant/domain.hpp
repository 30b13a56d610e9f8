#pragma once
// The computational domain and its symmetries, shared by every thorn that fills ghosts across a
// domain face (the Grid's ghost exchange, XCFC's multigrid): the kinds of faces, the ghost images
// as index maps (axis, origin, phi + pi, periodic, reflection) and the parities of tensor
// components under them, from their declared TensorKind. Header-only.
//
// A ghost image is an affine map of the global point indices of one level,
// image(i)_d = sigma_d * i_d + shift_d, and the isometry that relates the field at the ghost to
// the field at its image: the signs the coordinate basis vectors pick up (basis_sign; the
// coordinate components of a tensor take their product), the signs of the Cartesian axes
// (cartesian_sign; Cartesian components likewise) and whether it reverses orientation (axial
// vectors take one more sign).
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "remnant/coordinates.hpp"
#include "remnant/variables.hpp"

namespace remnant {

// What lies beyond a face of the domain.
enum class Boundary : std::uint8_t {
  outflow,    // an outer face: each thorn applies its own condition there (Grid: zero-gradient
              // outflow; XCFC: Robin fall-off or Dirichlet values)
  periodic,   // both sides of the direction (XCFC: phi over [0, 2 pi] of 3D curvilinear grids)
  reflect,    // a mirror symmetry plane: Cartesian x^d = 0, the equator theta = pi/2, cylindrical z = 0
  axis,       // the cylindrical axis R = 0 or the spherical axis theta = 0, pi
  origin,     // the spherical origin r = 0
  interface,  // a face inside the domain (XCFC's refined patches): filled by the owner, no image
  outer = outflow  // XCFC's name of an outer face
};

// A box of global point indices on one level, [lo, hi) per direction.
struct GlobalBox {
  std::array<std::int64_t, 3> lo{0, 0, 0}, hi{1, 1, 1};
  bool empty() const { return lo[0] >= hi[0] || lo[1] >= hi[1] || lo[2] >= hi[2]; }
};
inline GlobalBox intersect(const GlobalBox& a, const GlobalBox& b) {
  GlobalBox r;
  for (std::size_t d = 0; d < 3; ++d) {
    r.lo[d] = a.lo[d] > b.lo[d] ? a.lo[d] : b.lo[d];
    r.hi[d] = a.hi[d] < b.hi[d] ? a.hi[d] : b.hi[d];
  }
  return r;
}

struct IndexMap {
  std::array<int, 3> sigma{1, 1, 1};
  std::array<std::int64_t, 3> shift{0, 0, 0};
  std::array<int, 3> basis_sign{1, 1, 1};      // coordinate basis vectors
  std::array<int, 3> cartesian_sign{1, 1, 1};  // Cartesian axes of the isometry
  bool mirrored = false;                       // orientation reversed (coordinate bookkeeping)
  bool axial_flipped = false;                  // odd number of `opposite` planes crossed (axial vectors)

  std::int64_t apply(int d, std::int64_t i) const {
    return sigma[static_cast<std::size_t>(d)] * i + shift[static_cast<std::size_t>(d)];
  }
  GlobalBox apply(const GlobalBox& b) const {
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
  // i = sigma (j - shift): the same form with shift' = -sigma shift.
  GlobalBox inverse(const GlobalBox& b) const {
    IndexMap inv = *this;
    for (std::size_t d = 0; d < 3; ++d) inv.shift[d] = -sigma[d] * shift[d];
    return inv.apply(b);
  }
  bool preserves_orientation() const { return sigma[0] > 0 && sigma[1] > 0 && sigma[2] > 0; }
  // T(j) = tau j + t composed after the map in direction d.
  void compose(int d, int tau, std::int64_t t) {
    const auto ud = static_cast<std::size_t>(d);
    sigma[ud] *= tau;
    shift[ud] = tau * shift[ud] + t;
  }
  // Parity of a component (coordinate basis) from its tensor type: the product over its indices,
  // with one more sign for an axial vector when the map contains an odd number of reflections.
  double sign(const ComponentSpec& c) const {
    int s = 1;
    for (int idx : c.indices)
      if (idx >= 0) s *= basis_sign[static_cast<std::size_t>(idx)];
    if (c.kind == TensorKind::axial_vector && mirrored != axial_flipped) s = -s;
    return s;
  }
  // Parity of a component in Cartesian components (x, y, z): the product over its indices of the
  // isometry's axis signs, an axial vector times the isometry's determinant.
  double cartesian_parity(const ComponentSpec& c) const {
    int s = 1;
    for (int idx : c.indices)
      if (idx >= 0) s *= cartesian_sign[static_cast<std::size_t>(idx)];
    if (c.kind == TensorKind::axial_vector) {
      s *= cartesian_sign[0] * cartesian_sign[1] * cartesian_sign[2];
      if (axial_flipped) s = -s;
    }
    return s;
  }
};

// How an axial vector (B) behaves at the reflect face(s) of one direction: `mirror`, its
// pseudo-vector mirror image (e.g. a toroidal field about z across x = 0, a poloidal field across
// z = 0), or `opposite`, minus that image (a poloidal field about z across x = 0 and y = 0, a
// toroidal field symmetric in z across z = 0). Polar tensors are unaffected.
enum class AxialReflection : std::uint8_t { mirror, opposite };

// The domain's faces: what the ghost images depend on besides the point counts.
struct DomainFaces {
  CoordinateSystem coordinates = CoordinateSystem::cartesian;
  int dimension = 3;
  std::array<std::array<Boundary, 2>, 3> boundary{};  // [direction][lower, upper]
  // Per direction, the parity of axial vectors at its reflect faces (the spherical equator
  // is direction 1, also where the origin's image uses it).
  std::array<AxialReflection, 3> axial_reflection{AxialReflection::mirror, AxialReflection::mirror, AxialReflection::mirror};

  bool used(int d) const { return d < dimension; }
  // Across the axis or the origin of a 3D curvilinear grid the image is the cell at phi + pi.
  bool turns_phi() const {
    if (dimension < 3 || coordinates == CoordinateSystem::cartesian) return false;
    for (int d = 0; d < 2; ++d)
      for (const Boundary b : boundary[static_cast<std::size_t>(d)])
        if (b == Boundary::axis || b == Boundary::origin) return true;
    return false;
  }
  // Point reflection through the spherical origin maps theta to pi - theta unless the domain ends
  // at the equator with a reflection (then the image keeps theta: the origin's map composed with the
  // equatorial mirror).
  bool origin_flips_theta() const { return !(dimension >= 2 && boundary[1][1] == Boundary::reflect); }

  // Composes the crossing of face (d, upper) onto m. points: points per direction of the level and
  // centering; theta_points_to_pi: cells of the level in [0, pi] (the origin's theta mirror);
  // stagger: 1 in a direction where the points are faces. Outflow and interface faces have no
  // image; for them the map is the plain mirror (the cell an even extrapolation would read).
  // phi_lo: the lowest phi index of the box being mapped, or -1; a box in the upper half of phi turns
  // by -pi instead of +pi, so that a box holding the periodic face phi = 2 pi (face-centred phi
  // groups) lands inside the domain instead of straddling the seam (cells land on the same images).
  void cross(IndexMap& m, int d, bool upper, const std::array<std::int64_t, 3>& cells, std::int64_t theta_cells_to_pi,
             const std::array<int, 3>& stagger, std::int64_t phi_lo = -1) const {
    const auto ud = static_cast<std::size_t>(d);
    // Mirror about the face: cells i -> -1 - i, faces i -> -i (and likewise at the upper face).
    auto mirror = [&](int e, bool up) {
      const auto ue = static_cast<std::size_t>(e);
      m.compose(e, -1, up ? 2 * cells[ue] - (1 - stagger[ue]) : -(1 - stagger[ue]));
    };
    auto shift_phi_by_pi = [&] {
      if (turns_phi()) m.compose(2, 1, phi_lo >= cells[2] / 2 ? -cells[2] / 2 : cells[2] / 2);
    };
    const bool curvilinear = coordinates != CoordinateSystem::cartesian;
    switch (upper ? boundary[ud][1] : boundary[ud][0]) {
      case Boundary::outflow:
      case Boundary::interface: mirror(d, upper); break;  // no image: the mirror cell, no signs
      case Boundary::periodic: m.compose(d, 1, upper ? -cells[ud] : cells[ud]); break;
      case Boundary::reflect:
        mirror(d, upper);
        m.basis_sign[ud] = -m.basis_sign[ud];
        m.mirrored = !m.mirrored;
        if (axial_reflection[ud] == AxialReflection::opposite) m.axial_flipped = !m.axial_flipped;
        // Curvilinear mirror planes are z-planes (the equator, cylindrical z = const).
        m.cartesian_sign[curvilinear ? 2 : ud] = -m.cartesian_sign[curvilinear ? 2 : ud];
        break;
      case Boundary::axis:
        mirror(d, upper);
        m.basis_sign[ud] = -m.basis_sign[ud];
        shift_phi_by_pi();
        // 3D: the image is the physical point itself. Otherwise (axisymmetry) it is the point at
        // phi + pi seen from phi: a rotation by pi about z.
        if (!turns_phi()) m.cartesian_sign[0] = -m.cartesian_sign[0], m.cartesian_sign[1] = -m.cartesian_sign[1];
        break;
      case Boundary::origin: {
        // (-r, theta, phi) is (r, pi - theta, phi + pi): d_r and d_theta flip, d_phi does not.
        mirror(0, false);
        m.basis_sign[0] = -m.basis_sign[0];
        const bool flip_theta = origin_flips_theta();
        if (flip_theta) {
          m.basis_sign[1] = -m.basis_sign[1];
          if (dimension >= 2) m.compose(1, -1, theta_cells_to_pi - (1 - stagger[1]));
        } else {
          m.mirrored = !m.mirrored;  // pi - theta, then the equatorial mirror: theta kept
          if (axial_reflection[1] == AxialReflection::opposite) m.axial_flipped = !m.axial_flipped;
        }
        shift_phi_by_pi();
        // The isometry: 3D the point itself (phi + pi), with the equatorial mirror where theta is
        // kept; axisymmetric 2D a rotation by pi about z (and the mirror); 1D the point reflection.
        auto flip = [&](int a) { m.cartesian_sign[static_cast<std::size_t>(a)] = -m.cartesian_sign[static_cast<std::size_t>(a)]; };
        if (turns_phi()) {
          if (!flip_theta) flip(2);
        } else if (dimension == 1) {
          flip(0), flip(1), flip(2);
        } else {
          flip(0), flip(1);
          if (!flip_theta) flip(2);
        }
        break;
      }
    }
  }

  // The map that takes a box (each direction entirely inside, below or above the domain) of a
  // centering with staggering `stagger` on a level with `cells` into the domain; nullopt when it
  // lies beyond an outflow face in some direction (the Grid's outflow pass fills it).
  std::optional<IndexMap> image(const std::array<std::int64_t, 3>& cells, std::int64_t theta_cells_to_pi,
                                const std::array<int, 3>& stagger, const GlobalBox& box) const {
    IndexMap m;
    // Each step moves the box into the domain in one direction; corners take a few rounds.
    for (int round = 0; round < 8; ++round) {
      const GlobalBox cur = m.apply(box);
      int d = -1;
      bool upper = false;
      for (int e = 0; e < dimension && d < 0; ++e) {
        const auto ue = static_cast<std::size_t>(e);
        const std::int64_t points = cells[ue] + stagger[ue];
        if (cur.hi[ue] <= 0) d = e;
        else if (cur.lo[ue] >= points) d = e, upper = true;
        else if (cur.lo[ue] < 0 || cur.hi[ue] > points) throw std::logic_error("domain: a ghost box straddles a domain face");
      }
      if (d < 0) return m;
      const Boundary b = boundary[static_cast<std::size_t>(d)][upper ? 1 : 0];
      if (b == Boundary::outflow || b == Boundary::interface) return std::nullopt;
      cross(m, d, upper, cells, theta_cells_to_pi, stagger, cur.lo[2]);
    }
    throw std::logic_error("domain: no image of a ghost box in the domain");
  }

  // The cell whose value (times the field's parity at that face) the ghost cell I beyond face
  // (d, side) takes, on a level with `cells` (theta over [0, pi] where the origin flips it):
  // periodic and phi-turned coordinates wrap into the domain, other coordinates beyond other faces
  // are kept.
  std::array<long long, 3> cell_image(std::array<long long, 3> I, int d, int side, const std::array<std::int64_t, 3>& cells) const {
    IndexMap m;
    cross(m, d, side == 1, cells, cells[1], {0, 0, 0});
    const Boundary b = boundary[static_cast<std::size_t>(d)][static_cast<std::size_t>(side)];
    auto wrap = [&](int e) {
      const long long n = cells[static_cast<std::size_t>(e)];
      I[static_cast<std::size_t>(e)] = ((I[static_cast<std::size_t>(e)] % n) + n) % n;
    };
    if (b == Boundary::periodic) {
      wrap(d);
      return I;
    }
    for (int e = 0; e < 3; ++e) I[static_cast<std::size_t>(e)] = m.apply(e, I[static_cast<std::size_t>(e)]);
    if ((b == Boundary::axis || b == Boundary::origin) && turns_phi()) wrap(2);
    return I;
  }
};

// The domain a grid was built on: its faces, the cells of level 0, the block size and the extent.
struct Domain {
  DomainFaces faces;
  std::array<std::int64_t, 3> cells{1, 1, 1};  // level 0; 1 in unused directions
  std::array<int, 3> block_cells{1, 1, 1};
  std::array<double, 3> lo{0, 0, 0}, hi{1, 1, 1};  // coordinate extent of the used directions
};

// The parity of a component with the given tensor type at a face, in Cartesian components (+1 for
// outflow and interface faces, which have no image).
inline double cartesian_face_parity(const DomainFaces& f, int d, int side, const ComponentSpec& c,
                                    const std::array<std::int64_t, 3>& cells) {
  const Boundary b = f.boundary[static_cast<std::size_t>(d)][static_cast<std::size_t>(side)];
  if (b == Boundary::outflow || b == Boundary::interface || b == Boundary::periodic) return 1.0;
  IndexMap m;
  f.cross(m, d, side == 1, cells, cells[1], {0, 0, 0});
  return m.cartesian_parity(c);
}

}  // namespace remnant
