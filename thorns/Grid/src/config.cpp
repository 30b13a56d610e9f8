#include "config.hpp"

#include <cstddef>
#include <vector>

#include "remnant/parameters.hpp"

namespace remnant::grid {

const char* to_string(Boundary b) {
  switch (b) {
    case Boundary::outflow: return "outflow";
    case Boundary::periodic: return "periodic";
    case Boundary::reflect: return "reflect";
  }
  return "?";
}

Boundary parse_boundary(const std::string& keyword, const SourceLocation& where) {
  if (keyword == "outflow") return Boundary::outflow;
  if (keyword == "periodic") return Boundary::periodic;
  if (keyword == "reflect") return Boundary::reflect;
  throw InputError(where, "Grid: unknown boundary '" + keyword + "'; one of: outflow, periodic, reflect");
}

namespace {
const char* const kAxis[3] = {"x", "y", "z"};

std::string entry(const char* name, int d) {
  return std::string("Grid::") + name + "[" + std::to_string(d) + "]";
}
}  // namespace

UniformGridConfig checked(UniformGridConfig c, const SettingLocator& where) {
  if (c.coordinates != "cartesian")
    throw InputError(where("coordinates"),
                     "Grid::coordinates = " + c.coordinates +
                         ": only cartesian coordinates are implemented so far; cylindrical and "
                         "spherical come with the Grid issue");
  if (c.dimension < 1 || c.dimension > 3)
    throw InputError(where("dimension"), "Grid::dimension = " + std::to_string(c.dimension) +
                                             " is outside [1:3]");
  if (c.ghost_zones < 1 || c.ghost_zones > 8)
    throw InputError(where("ghost_zones"), "Grid::ghost_zones = " + std::to_string(c.ghost_zones) +
                                               " is outside [1:8]");
  for (int d = 0; d < 3; ++d) {
    const auto i = static_cast<std::size_t>(d);
    if (d >= c.dimension) {
      // Unused directions: one cell, no ghosts; their entries are ignored.
      c.ncells[i] = 1;
      c.block_size[i] = 1;
      c.boundary_lower[i] = c.boundary_upper[i] = Boundary::outflow;
      if (!(c.xmax[i] > c.xmin[i])) c.xmax[i] = c.xmin[i] + 1.0;
      continue;
    }
    if (c.ncells[i] < 1)
      throw InputError(where("ncells"), entry("ncells", d) + " = " + std::to_string(c.ncells[i]) +
                                            " must be at least 1");
    if (c.block_size[i] < 1)
      throw InputError(where("block_size"), entry("block_size", d) + " = " +
                                                std::to_string(c.block_size[i]) + " must be at least 1");
    if (c.ncells[i] % c.block_size[i] != 0)
      throw InputError(where("block_size"),
                       "Grid::ncells[" + std::to_string(d) + "] = " + std::to_string(c.ncells[i]) +
                           " is not divisible by Grid::block_size[" + std::to_string(d) + "] = " +
                           std::to_string(c.block_size[i]));
    if (c.block_size[i] < c.ghost_zones)
      throw InputError(where("block_size"),
                       entry("block_size", d) + " = " + std::to_string(c.block_size[i]) +
                           " is smaller than Grid::ghost_zones = " + std::to_string(c.ghost_zones) +
                           "; ghosts must come from the nearest neighbour block");
    if (!(c.xmax[i] > c.xmin[i]))
      throw InputError(where("xmax"), entry("xmax", d) + " = " + std::to_string(c.xmax[i]) +
                                          " must be larger than " + entry("xmin", d) + " = " +
                                          std::to_string(c.xmin[i]));
    const bool lower_periodic = c.boundary_lower[i] == Boundary::periodic;
    const bool upper_periodic = c.boundary_upper[i] == Boundary::periodic;
    if (lower_periodic != upper_periodic)
      throw InputError(where(lower_periodic ? "boundary_upper" : "boundary_lower"),
                       std::string("Grid: the ") + kAxis[d] +
                           " direction is periodic on one side only (boundary_lower[" +
                           std::to_string(d) + "] = " + to_string(c.boundary_lower[i]) +
                           ", boundary_upper[" + std::to_string(d) + "] = " +
                           to_string(c.boundary_upper[i]) + "); set periodic on both sides");
  }
  return c;
}

UniformGridConfig checked(const UniformGridConfig& config) {
  return checked(config, [](const std::string& name) {
    return SourceLocation{"UniformGridConfig::" + name, 0, 0};
  });
}

namespace {
template <class T, std::size_t N>
std::array<T, N> three(const std::vector<T>& v, const char* name, const Parameters& p) {
  if (v.size() != N)
    throw InputError(p.origin("Grid", name), std::string("Grid::") + name + " needs " +
                                                 std::to_string(N) + " entries, got " +
                                                 std::to_string(v.size()));
  std::array<T, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = v[i];
  return out;
}
}  // namespace

UniformGridConfig config_from_parameters(const Parameters& p) {
  UniformGridConfig c;
  c.coordinates = p.get<std::string>("Grid", "coordinates");
  c.dimension = static_cast<int>(p.get<std::int64_t>("Grid", "dimension"));
  c.ncells = three<std::int64_t, 3>(p.get<std::vector<std::int64_t>>("Grid", "ncells"), "ncells", p);
  const auto bs = three<std::int64_t, 3>(p.get<std::vector<std::int64_t>>("Grid", "block_size"),
                                         "block_size", p);
  for (std::size_t i = 0; i < 3; ++i) c.block_size[i] = static_cast<int>(bs[i]);
  c.xmin = three<double, 3>(p.get<std::vector<double>>("Grid", "xmin"), "xmin", p);
  c.xmax = three<double, 3>(p.get<std::vector<double>>("Grid", "xmax"), "xmax", p);
  c.ghost_zones = static_cast<int>(p.get<std::int64_t>("Grid", "ghost_zones"));
  const auto lower = three<std::string, 3>(
      p.get<std::vector<std::string>>("Grid", "boundary_lower"), "boundary_lower", p);
  const auto upper = three<std::string, 3>(
      p.get<std::vector<std::string>>("Grid", "boundary_upper"), "boundary_upper", p);
  for (std::size_t i = 0; i < 3; ++i) {
    c.boundary_lower[i] = parse_boundary(lower[i], p.origin("Grid", "boundary_lower"));
    c.boundary_upper[i] = parse_boundary(upper[i], p.origin("Grid", "boundary_upper"));
  }
  return checked(c, [&p](const std::string& name) { return p.origin("Grid", name); });
}

}  // namespace remnant::grid
