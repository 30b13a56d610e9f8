#pragma once
// Plain settings of the Grid thorn, so that tests and tools can build a grid without a parameter
// database. Entries of the 3-arrays beyond `dimension` are ignored (that direction has one cell,
// no ghosts; an unused theta or phi spans [0, pi] or [0, 2 pi]).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "remnant/coordinates.hpp"
#include "remnant/domain.hpp"

namespace remnant::grid {

// The face kinds are the shared domain model's (remnant/domain.hpp): outflow (zero-gradient
// extrapolation here), periodic (both sides), reflect (a mirror symmetry plane: equator, octant;
// parities from the tensor type with the extra sign of axial vectors), axis (the cylindrical axis
// R = 0 or the spherical axis theta = 0, pi), origin (r = 0). Axis and origin ghosts are the cells
// across them (phi + pi in 3D), with the signs of the coordinate basis. (interface is not a Grid face.)
using remnant::Boundary;
const char* to_string(Boundary b);

// A static refinement region. box: coordinate ranges [lo_d, hi_d] (bounds = lo0 hi0 lo1 hi1 lo2
// hi2). sphere / shell: Cartesian distance in [rmin, rmax] from a Cartesian centre (bounds = rmin
// rmax cx cy cz, sixth entry unused; a sphere has rmin = 0). at_least: blocks overlapping it are
// refined to at least `level`; at_most: blocks overlapping it are never finer than `level` (the
// paper's single coarse core block around the spherical origin); at_most wins over at_least.
enum class RegionKind { box, sphere, shell };
enum class RegionMode { at_least, at_most };
struct RefinementRegion {
  RegionKind kind = RegionKind::box;
  RegionMode mode = RegionMode::at_least;
  int level = 1;
  std::array<double, 6> bounds{};
};

struct GridConfig {
  CoordinateSystem coordinates = CoordinateSystem::cartesian;
  int dimension = 3;
  std::array<std::int64_t, 3> ncells{32, 32, 32};  // on level 0
  std::array<int, 3> block_size{16, 16, 16};
  std::array<double, 3> xmin{-1, -1, -1};
  std::array<double, 3> xmax{1, 1, 1};
  int ghost_zones = 3;
  std::array<Boundary, 3> boundary_lower{Boundary::outflow, Boundary::outflow, Boundary::outflow};
  std::array<Boundary, 3> boundary_upper{Boundary::outflow, Boundary::outflow, Boundary::outflow};
  // Parity of axial vectors (B) at the reflect faces of each direction (remnant/domain.hpp);
  // `opposite` only where that direction has a reflect face.
  std::array<AxialReflection, 3> axial_reflection{AxialReflection::mirror, AxialReflection::mirror, AxialReflection::mirror};

  // Mesh refinement: finest level allowed (0: a uniform grid), static regions, and the Löhner
  // estimator on one component (empty: none).
  int max_level = 0;
  std::vector<RefinementRegion> regions;
  std::string refine_variable;          // "Thorn::group.component" or "Thorn::group" (component 0)
  bool refine_log = false;              // estimate on log10|u| instead of u
  double refine_threshold = 0.2;        // refine where the estimator exceeds it
  double derefine_ratio = 0.125;        // coarsen where it is below ratio * threshold
  double lohner_filter = 0.01;          // epsilon of the estimator's noise filter
};

}  // namespace remnant::grid
