#include "check_parameters.hpp"

#include <cstdio>
#include <vector>

namespace remnant::seed {

std::string format_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

SourceLocation user_origin(const Parameters& p, std::initializer_list<std::pair<const char*, const char*>> names) {
  for (const bool command_line : {true, false})
    for (const auto& [thorn, name] : names) {
      if (!p.find(thorn, name)) continue;
      const SourceLocation& where = p.origin(thorn, name);
      const bool is_default =
          where.file.find("thorn.yaml") != std::string::npos || where.file.find("flesh.yaml") != std::string::npos;
      if (!is_default && (!command_line || where.file.rfind("command line", 0) == 0)) return where;
    }
  const auto& [thorn, name] = *names.begin();
  return p.origin(thorn, name);
}

namespace {

// The Grid's reflect boundaries keep B even (a pseudo-vector's mirror image). A poloidal star field
// is odd under mirrors through planes that contain its axis (x = 0, y = 0), a toroidal one under
// the equatorial mirror: such a boundary would evolve another field than the one seeded.
void check_symmetry(Context& ctx, const std::string& type, const std::string& coords, std::int64_t dim) {
  const Parameters& p = ctx.params();
  const auto& lower = ctx.param<std::vector<std::string>>("Grid", "boundary_lower");
  const auto& upper = ctx.param<std::vector<std::string>>("Grid", "boundary_upper");
  const bool poloidal = type != "toroidal", toroidal = type != "poloidal";
  if (poloidal && coords == "cartesian" && dim == 3 && (lower[0] == "reflect" || lower[1] == "reflect"))
    throw InputError(user_origin(p, {{"Grid", "boundary_lower"}, {"SeedMagneticField", "type"}}),
                     "SeedMagneticField::type = " + type + " with Grid::boundary_lower = [" + lower[0] + ", " + lower[1] +
                         ", " + lower[2] + "]: a poloidal field is odd under the mirrors x = 0 and y = 0 (planes containing "
                         "the star's axis) while reflect boundaries keep B even; allowed: reflect at z = 0 only (cover x and "
                         "y on both sides of the axis)");
  bool equator = false;
  const char* which = "boundary_lower";
  if (coords == "cartesian" && dim == 3) equator = lower[2] == "reflect";
  if (coords == "cylindrical") equator = lower[1] == "reflect";
  if (coords == "spherical") equator = upper[1] == "reflect", which = "boundary_upper";
  if (toroidal && equator)
    throw InputError(user_origin(p, {{"Grid", which}, {"SeedMagneticField", "type"}}),
                     "SeedMagneticField::type = " + type + " with an equatorial reflect boundary (Grid::" + which +
                         "): a toroidal field is odd under the equatorial mirror while reflect boundaries keep B even; "
                         "allowed: the whole star across the equator (e.g. theta up to pi with an axis boundary)");
}

}  // namespace

void check_parameters(Context& ctx) {
  const Parameters& p = ctx.params();
  const std::string mode = p.find("HydroBase", "magnetic_field") ? ctx.param<std::string>("HydroBase", "magnetic_field") : "none";
  if (mode != "evolved")
    throw InputError(user_origin(p, {{"HydroBase", "magnetic_field"}, {"SeedMagneticField", "type"}}),
                     "SeedMagneticField is active but HydroBase::magnetic_field = " + mode +
                         ": the run has no magnetic field to seed; set HydroBase::magnetic_field: evolved or remove "
                         "SeedMagneticField from active_thorns");
  const std::string type = ctx.param<std::string>("SeedMagneticField", "type");
  const bool poloidal = type != "toroidal";
  const double fraction = ctx.param<double>("SeedMagneticField", "p_cut_fraction");
  if (poloidal && !(fraction < 1.0))
    throw InputError(user_origin(p, {{"SeedMagneticField", "p_cut_fraction"}}),
                     "SeedMagneticField::p_cut_fraction = " + format_number(fraction) +
                         " puts p_cut at or above the maximum pressure p_max, so the poloidal potential "
                         "A_phi = A_b varpi^2 max(p - p_cut, 0)^n_s vanishes everywhere; allowed: [0, 1)");
  if (p.find("Grid", "coordinates")) {
    const std::string coords = ctx.param<std::string>("Grid", "coordinates");
    const auto dim = ctx.param<std::int64_t>("Grid", "dimension");
    check_symmetry(ctx, type, coords, dim);
    const bool axisymmetric_2d = dim == 2 && coords != "cartesian";
    if (dim != 3 && !axisymmetric_2d)
      throw InputError(user_origin(p, {{"Grid", "dimension"}, {"Grid", "coordinates"}, {"SeedMagneticField", "type"}}),
                       "SeedMagneticField needs the star's axis on the grid: Grid::dimension = " + std::to_string(dim) +
                           " with Grid::coordinates = " + coords +
                           " has none; allowed: dimension 2 with cylindrical or spherical coordinates, or dimension 3");
  }
}

}  // namespace remnant::seed
