#include "config.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <numbers>
#include <vector>

#include "remnant/parameters.hpp"

namespace remnant::grid {

const char* to_string(Boundary b) {
  switch (b) {
    case Boundary::outflow: return "outflow";
    case Boundary::periodic: return "periodic";
    case Boundary::reflect: return "reflect";
    case Boundary::axis: return "axis";
    case Boundary::origin: return "origin";
    case Boundary::interface: return "interface";
  }
  return "?";
}

Boundary parse_boundary(const std::string& keyword, const SourceLocation& where) {
  for (Boundary b : {Boundary::outflow, Boundary::periodic, Boundary::reflect, Boundary::axis, Boundary::origin})
    if (keyword == to_string(b)) return b;
  throw InputError(where, "Grid: unknown boundary '" + keyword + "'; one of: outflow, periodic, reflect, axis, origin");
}

CoordinateSystem parse_coordinates(const std::string& keyword, const SourceLocation& where) {
  for (CoordinateSystem c : {CoordinateSystem::cartesian, CoordinateSystem::cylindrical, CoordinateSystem::spherical})
    if (keyword == to_string(c)) return c;
  throw InputError(where, "Grid: unknown coordinates '" + keyword + "'; one of: cartesian, cylindrical, spherical");
}

namespace {
constexpr double kPi = std::numbers::pi;

const char* axis_name(CoordinateSystem c, int d) {
  static const char* const cart[3] = {"x", "y", "z"};
  static const char* const cyl[3] = {"R", "z", "phi"};
  static const char* const sph[3] = {"r", "theta", "phi"};
  const auto i = static_cast<std::size_t>(d);
  return c == CoordinateSystem::cartesian ? cart[i] : c == CoordinateSystem::cylindrical ? cyl[i] : sph[i];
}

std::string entry(const char* name, int d) { return std::string("Grid::") + name + "[" + std::to_string(d) + "]"; }
std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}
bool near(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

// Axis and origin conditions: where they are allowed, and where they are required.
void check_curvilinear_faces(GridConfig& c, const SettingLocator& where) {
  const auto cs = c.coordinates;
  for (int d = 0; d < c.dimension; ++d) {
    const auto i = static_cast<std::size_t>(d);
    for (bool upper : {false, true}) {
      const Boundary b = upper ? c.boundary_upper[i] : c.boundary_lower[i];
      const double at = upper ? c.xmax[i] : c.xmin[i];
      const char* param = upper ? "boundary_upper" : "boundary_lower";
      const std::string here = entry(param, d) + " = " + to_string(b);
      const bool r_origin = cs == CoordinateSystem::spherical && d == 0 && !upper && at == 0.0;
      const bool cyl_axis = cs == CoordinateSystem::cylindrical && d == 0 && !upper && at == 0.0;
      const bool theta_axis = cs == CoordinateSystem::spherical && d == 1 && (upper ? near(at, kPi) : at == 0.0);
      if (b == Boundary::origin && !r_origin)
        throw InputError(where(param), here + ": 'origin' is the lower r face of spherical coordinates at r = 0");
      if (b == Boundary::axis && !cyl_axis && !theta_axis)
        throw InputError(where(param), here + ": 'axis' is the lower R face of cylindrical coordinates at R = 0, or a "
                                              "theta face of spherical coordinates at theta = 0 or pi");
      if (r_origin && b != Boundary::origin)
        throw InputError(where(param), here + " at r = 0: the origin needs 'origin' (ghosts across it, with the "
                                              "coordinate-basis signs)");
      if ((cyl_axis || theta_axis) && b != Boundary::axis)
        throw InputError(where(param), here + " on the coordinate axis: use 'axis'");
    }
  }
  const bool has_axis_or_origin = [&] {
    for (int d = 0; d < c.dimension; ++d)
      for (Boundary b : {c.boundary_lower[static_cast<std::size_t>(d)], c.boundary_upper[static_cast<std::size_t>(d)]})
        if (b == Boundary::axis || b == Boundary::origin) return true;
    return false;
  }();
  if (has_axis_or_origin && c.dimension == 3) {
    // Ghosts across the axis sit at phi + pi: the full circle, in whole blocks on either side.
    if (c.boundary_lower[2] != Boundary::periodic || c.xmin[2] != 0.0 || !near(c.xmax[2], 2 * kPi))
      throw InputError(where("boundary_lower"), "Grid: a 3D grid with an axis or the origin needs phi in [0, 2 pi] "
                                                "(Grid::xmin[2] = 0, Grid::xmax[2] = 6.283185307179586) and periodic phi boundaries");
    if ((c.ncells[2] / c.block_size[2]) % 2 != 0)
      throw InputError(where("ncells"), "Grid: across the axis, phi + pi must start a block: Grid::ncells[2] / "
                                        "Grid::block_size[2] must be even");
  }
  if (cs == CoordinateSystem::spherical && c.boundary_lower[0] == Boundary::origin && c.dimension >= 2) {
    // The origin maps theta to pi - theta: the theta range must be [0, pi] or [0, pi/2] with the equator.
    const bool full = c.xmin[1] == 0.0 && near(c.xmax[1], kPi);
    const bool half = c.xmin[1] == 0.0 && near(c.xmax[1], kPi / 2) && c.boundary_upper[1] == Boundary::reflect;
    if (!full && !half)
      throw InputError(where("xmax"), "Grid: with the origin, theta must span [0, pi], or [0, pi/2] with "
                                      "Grid::boundary_upper[1] = reflect (equatorial symmetry); got [" +
                                          num(c.xmin[1]) + ", " + num(c.xmax[1]) + "]");
  }
}
}  // namespace

GridConfig checked(GridConfig c, const SettingLocator& where) {
  if (c.dimension < 1 || c.dimension > 3)
    throw InputError(where("dimension"), "Grid::dimension = " + std::to_string(c.dimension) + " is outside [1:3]");
  if (c.ghost_zones < 1 || c.ghost_zones > 8)
    throw InputError(where("ghost_zones"), "Grid::ghost_zones = " + std::to_string(c.ghost_zones) + " is outside [1:8]");
  if (c.max_level < 0 || c.max_level > 20)
    throw InputError(where("max_level"), "Grid::max_level = " + std::to_string(c.max_level) + " is outside [0:20]");
  const auto cs = c.coordinates;
  for (int d = 0; d < 3; ++d) {
    const auto i = static_cast<std::size_t>(d);
    if (d >= c.dimension) {
      // Unused directions: one cell, no ghosts; their entries are ignored. Unused angles span
      // their whole range so that volumes are those of the 3D domain.
      c.ncells[i] = 1;
      c.block_size[i] = 1;
      c.boundary_lower[i] = c.boundary_upper[i] = Boundary::outflow;
      c.axial_reflection[i] = AxialReflection::mirror;
      if (coords::is_angle(cs, d)) {
        c.xmin[i] = 0.0;
        c.xmax[i] = d == 1 && cs == CoordinateSystem::spherical ? kPi : 2 * kPi;
      } else if (!(c.xmax[i] > c.xmin[i])) {
        c.xmax[i] = c.xmin[i] + 1.0;
      }
      continue;
    }
    if (c.axial_reflection[i] == AxialReflection::opposite && c.boundary_lower[i] != Boundary::reflect &&
        c.boundary_upper[i] != Boundary::reflect)
      throw InputError(where("axial_vector_reflection"),
                       entry("axial_vector_reflection", d) + " = opposite, but direction " + std::to_string(d) +
                           " has no reflect face (boundary_lower/upper = " + to_string(c.boundary_lower[i]) + ", " +
                           to_string(c.boundary_upper[i]) + "); use mirror (the default)");
    if (c.ncells[i] < 1)
      throw InputError(where("ncells"), entry("ncells", d) + " = " + std::to_string(c.ncells[i]) + " must be at least 1");
    if (c.block_size[i] < 1)
      throw InputError(where("block_size"), entry("block_size", d) + " = " + std::to_string(c.block_size[i]) +
                                                " must be at least 1");
    if (c.ncells[i] % c.block_size[i] != 0)
      throw InputError(where("block_size"),
                       "Grid::ncells[" + std::to_string(d) + "] = " + std::to_string(c.ncells[i]) +
                           " is not divisible by Grid::block_size[" + std::to_string(d) + "] = " +
                           std::to_string(c.block_size[i]));
    if (c.block_size[i] < c.ghost_zones)
      throw InputError(where("block_size"), entry("block_size", d) + " = " + std::to_string(c.block_size[i]) +
                                                " is smaller than Grid::ghost_zones = " + std::to_string(c.ghost_zones) +
                                                "; ghosts must come from the nearest neighbour block");
    if (c.max_level > 0 && (c.block_size[i] % 2 != 0 || c.block_size[i] < 2 * c.ghost_zones))
      throw InputError(where("block_size"),
                       entry("block_size", d) + " = " + std::to_string(c.block_size[i]) +
                           ": with refinement (Grid::max_level = " + std::to_string(c.max_level) +
                           ") blocks must be even and at least 2 * Grid::ghost_zones = " +
                           std::to_string(2 * c.ghost_zones) + " cells wide");
    if ((c.ncells[i] / c.block_size[i]) << c.max_level >= (std::int64_t{1} << 21))
      throw InputError(where("max_level"), "Grid: more than 2^21 blocks in one direction on the finest level");
    if (!(c.xmax[i] > c.xmin[i]))
      throw InputError(where("xmax"), entry("xmax", d) + " = " + num(c.xmax[i]) + " must be larger than " +
                                          entry("xmin", d) + " = " + num(c.xmin[i]));
    const bool lower_periodic = c.boundary_lower[i] == Boundary::periodic;
    const bool upper_periodic = c.boundary_upper[i] == Boundary::periodic;
    if (lower_periodic != upper_periodic)
      throw InputError(where(lower_periodic ? "boundary_upper" : "boundary_lower"),
                       std::string("Grid: the ") + axis_name(cs, d) + " direction is periodic on one side only (boundary_lower[" +
                           std::to_string(d) + "] = " + to_string(c.boundary_lower[i]) + ", boundary_upper[" +
                           std::to_string(d) + "] = " + to_string(c.boundary_upper[i]) + "); set periodic on both sides");
    // Coordinate ranges of the curvilinear systems.
    if (cs != CoordinateSystem::cartesian && d == 0 && c.xmin[i] < 0)
      throw InputError(where("xmin"), entry("xmin", 0) + " = " + num(c.xmin[i]) + ": " + axis_name(cs, 0) +
                                          " cannot be negative");
    if (cs == CoordinateSystem::spherical && d == 1 && (c.xmin[i] < 0 || c.xmax[i] > kPi * (1 + 1e-14)))
      throw InputError(where(c.xmin[i] < 0 ? "xmin" : "xmax"), "Grid: theta must lie in [0, pi]; got [" +
                                                                   num(c.xmin[i]) + ", " + num(c.xmax[i]) + "]");
  }
  if (cs == CoordinateSystem::cartesian)
    for (int d = 0; d < c.dimension; ++d)
      for (bool upper : {false, true}) {
        const Boundary b = upper ? c.boundary_upper[static_cast<std::size_t>(d)] : c.boundary_lower[static_cast<std::size_t>(d)];
        if (b == Boundary::axis || b == Boundary::origin)
          throw InputError(where(upper ? "boundary_upper" : "boundary_lower"),
                           entry(upper ? "boundary_upper" : "boundary_lower", d) + " = " + to_string(b) +
                               ": Cartesian coordinates have no axis or origin; use reflect for a symmetry plane");
      }
  check_curvilinear_faces(c, where);
  for (std::size_t r = 0; r < c.regions.size(); ++r) {
    const auto& reg = c.regions[r];
    if (reg.level < 0 || reg.level > c.max_level)
      throw InputError(where("region_levels"), "Grid::region_levels[" + std::to_string(r) + "] = " +
                                                   std::to_string(reg.level) + " is outside [0, Grid::max_level = " +
                                                   std::to_string(c.max_level) + "]");
    if (reg.kind != RegionKind::box && !(reg.bounds[1] > reg.bounds[0] && reg.bounds[0] >= 0))
      throw InputError(where("region_bounds"), "Grid::region_bounds of region " + std::to_string(r) +
                                                   ": a sphere or shell needs 0 <= rmin < rmax");
  }
  if (c.refine_threshold <= 0 || c.derefine_ratio < 0 || c.derefine_ratio >= 1)
    throw InputError(where("refine_threshold"), "Grid: need refine_threshold > 0 and derefine_ratio in [0, 1)");
  return c;
}

GridConfig checked(const GridConfig& config) {
  return checked(config, [](const std::string& name) { return SourceLocation{"GridConfig::" + name, 0, 0}; });
}

namespace {
template <class T, std::size_t N>
std::array<T, N> three(const std::vector<T>& v, const char* name, const Parameters& p) {
  if (v.size() != N)
    throw InputError(p.origin("Grid", name), std::string("Grid::") + name + " needs " + std::to_string(N) +
                                                 " entries, got " + std::to_string(v.size()));
  std::array<T, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = v[i];
  return out;
}

std::vector<RefinementRegion> regions_from(const Parameters& p) {
  const auto& kinds = p.get<std::vector<std::string>>("Grid", "regions");
  const auto& modes = p.get<std::vector<std::string>>("Grid", "region_modes");
  const auto& levels = p.get<std::vector<std::int64_t>>("Grid", "region_levels");
  const auto& bounds = p.get<std::vector<double>>("Grid", "region_bounds");
  const std::size_t n = kinds.size();
  if (levels.size() != n)
    throw InputError(p.origin("Grid", "region_levels"), "Grid::region_levels has " + std::to_string(levels.size()) +
                                                            " entries for " + std::to_string(n) + " Grid::regions");
  if (!modes.empty() && modes.size() != n)
    throw InputError(p.origin("Grid", "region_modes"), "Grid::region_modes has " + std::to_string(modes.size()) +
                                                           " entries for " + std::to_string(n) + " Grid::regions (or leave it empty: all at_least)");
  if (bounds.size() != 6 * n)
    throw InputError(p.origin("Grid", "region_bounds"), "Grid::region_bounds needs 6 numbers per region (" +
                                                            std::to_string(6 * n) + "), got " + std::to_string(bounds.size()));
  std::vector<RefinementRegion> out(n);
  for (std::size_t r = 0; r < n; ++r) {
    out[r].kind = kinds[r] == "box" ? RegionKind::box : kinds[r] == "sphere" ? RegionKind::sphere : RegionKind::shell;
    out[r].mode = !modes.empty() && modes[r] == "at_most" ? RegionMode::at_most : RegionMode::at_least;
    out[r].level = static_cast<int>(levels[r]);
    for (std::size_t k = 0; k < 6; ++k) out[r].bounds[k] = bounds[6 * r + k];
    if (out[r].kind == RegionKind::sphere) out[r].bounds[0] = 0.0;
  }
  return out;
}
}  // namespace

GridConfig config_from_parameters(const Parameters& p) {
  GridConfig c;
  c.coordinates = parse_coordinates(p.get<std::string>("Grid", "coordinates"), p.origin("Grid", "coordinates"));
  c.dimension = static_cast<int>(p.get<std::int64_t>("Grid", "dimension"));
  c.ncells = three<std::int64_t, 3>(p.get<std::vector<std::int64_t>>("Grid", "ncells"), "ncells", p);
  const auto bs = three<std::int64_t, 3>(p.get<std::vector<std::int64_t>>("Grid", "block_size"), "block_size", p);
  for (std::size_t i = 0; i < 3; ++i) c.block_size[i] = static_cast<int>(bs[i]);
  c.xmin = three<double, 3>(p.get<std::vector<double>>("Grid", "xmin"), "xmin", p);
  c.xmax = three<double, 3>(p.get<std::vector<double>>("Grid", "xmax"), "xmax", p);
  c.ghost_zones = static_cast<int>(p.get<std::int64_t>("Grid", "ghost_zones"));
  const auto lower = three<std::string, 3>(p.get<std::vector<std::string>>("Grid", "boundary_lower"), "boundary_lower", p);
  const auto upper = three<std::string, 3>(p.get<std::vector<std::string>>("Grid", "boundary_upper"), "boundary_upper", p);
  for (std::size_t i = 0; i < 3; ++i) {
    c.boundary_lower[i] = parse_boundary(lower[i], p.origin("Grid", "boundary_lower"));
    c.boundary_upper[i] = parse_boundary(upper[i], p.origin("Grid", "boundary_upper"));
  }
  const auto axial = three<std::string, 3>(p.get<std::vector<std::string>>("Grid", "axial_vector_reflection"), "axial_vector_reflection", p);
  for (std::size_t i = 0; i < 3; ++i)
    c.axial_reflection[i] = axial[i] == "opposite" ? AxialReflection::opposite : AxialReflection::mirror;
  c.max_level = static_cast<int>(p.get<std::int64_t>("Grid", "max_level"));
  c.regions = regions_from(p);
  c.refine_variable = p.get<std::string>("Grid", "refine_variable");
  c.refine_log = p.get<std::string>("Grid", "refine_scale") == "log";
  c.refine_threshold = p.get<double>("Grid", "refine_threshold");
  c.derefine_ratio = p.get<double>("Grid", "derefine_ratio");
  c.lohner_filter = p.get<double>("Grid", "lohner_filter");
  return checked(c, [&p](const std::string& name) { return p.origin("Grid", name); });
}

}  // namespace remnant::grid
