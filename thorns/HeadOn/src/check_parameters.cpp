// HeadOn_CheckParameters: the grid must be one the binary is defined on (3D Cartesian, 2D
// cylindrical), the stars must not overlap and must lie inside the grid (a lower z face at 0 must
// be the equatorial symmetry plane), and refine_radii must describe nested levels.
#include "check_parameters.hpp"

#include <string>
#include <vector>

#include "model.hpp"
#include "remnant/parameters.hpp"

namespace remnant::headon {
namespace {

std::string num(double x) { return format_number(x); }

}  // namespace

void check_parameters(Context& ctx) {
  const Parameters& p = ctx.params();
  const auto& coords = ctx.param<std::string>("Grid", "coordinates");
  const auto dim = ctx.param<std::int64_t>("Grid", "dimension");
  const bool cartesian = coords == "cartesian" && dim == 3, cylindrical = coords == "cylindrical" && dim == 2;
  if (!cartesian && !cylindrical)
    throw InputError(p.origin("Grid", "coordinates"),
                     "HeadOn needs Grid::coordinates = cartesian with Grid::dimension = 3, or cylindrical with "
                     "dimension = 2 (R, z); got " + coords + " with dimension " + std::to_string(dim));
  std::unique_ptr<tov::TovStar> star;
  std::unique_ptr<tov::ColdSlice> slice;
  try {
    slice = slice_from_parameters(ctx);
    star = std::make_unique<tov::TovStar>(*slice, ctx.param<double>("HeadOn", "rho_central"),
                                          static_cast<int>(ctx.param<std::int64_t>("HeadOn", "samples")));
  } catch (const std::exception& e) {
    throw InputError(p.origin("HeadOn", "rho_central"), std::string("no TOV star for these HeadOn parameters: ") + e.what());
  }
  const double R = star->isotropic_radius(), d = ctx.param<double>("HeadOn", "separation");
  if (!(d > 2 * R))
    throw InputError(p.origin("HeadOn", "separation"),
                     "HeadOn::separation = " + num(d) + " makes the stars overlap (isotropic radius " + num(R) +
                         "); allowed: separation > " + num(2 * R));
  // The z direction: index 2 (Cartesian) or 1 (cylindrical R, z).
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  const auto& blo = ctx.param<std::vector<std::string>>("Grid", "boundary_lower");
  const std::size_t z = cartesian ? 2 : 1;
  auto outside = [&](const std::string& what) {
    throw InputError(p.origin("Grid", "xmax"), "HeadOn: " + what + " (star centres at z = +-" + num(0.5 * d) +
                                                   ", isotropic radius " + num(R) + "; Grid::xmin, Grid::xmax)");
  };
  if (hi[z] < 0.5 * d + R) outside("the star at z > 0 reaches z = " + num(0.5 * d + R) + " beyond the grid's " + num(hi[z]));
  if (lo[z] == 0) {
    if (blo[z] != "reflect")
      throw InputError(p.origin("Grid", "boundary_lower"),
                       "HeadOn: the grid starts at z = 0, so the lower z boundary must be the equatorial symmetry "
                       "plane (Grid::boundary_lower = reflect in z), not " + blo[z]);
  } else if (lo[z] > -(0.5 * d + R)) {
    outside("the star at z < 0 reaches z = " + num(-(0.5 * d + R)) + " beyond the grid's " + num(lo[z]) +
            " (or start the grid at z = 0 with a reflecting boundary)");
  }
  for (std::size_t a = 0; a < (cartesian ? 2u : 1u); ++a) {
    if (hi[a] < R) outside("the stars reach " + num(R) + " off the axis beyond the grid's " + num(hi[a]));
    if (lo[a] == 0 && blo[a] != (cartesian ? "reflect" : "axis"))
      throw InputError(p.origin("Grid", "boundary_lower"),
                       std::string("HeadOn: a grid starting at 0 off the axis needs Grid::boundary_lower = ") +
                           (cartesian ? "reflect" : "axis") + " there, not " + blo[a]);
    if (lo[a] > 0 || (lo[a] < 0 && -lo[a] < R)) outside("the grid does not contain the z axis' neighbourhood");
  }
  const auto& radii = ctx.param<std::vector<double>>("HeadOn", "refine_radii");
  const auto max_level = ctx.param<std::int64_t>("Grid", "max_level");
  if (static_cast<std::int64_t>(radii.size()) > max_level)
    throw InputError(p.origin("HeadOn", "refine_radii"),
                     "HeadOn::refine_radii has " + std::to_string(radii.size()) + " entries but Grid::max_level is " +
                         std::to_string(max_level) + "; allowed: at most max_level entries");
  for (std::size_t l = 1; l < radii.size(); ++l)
    if (!(radii[l] < radii[l - 1]))
      throw InputError(p.origin("HeadOn", "refine_radii"),
                       "HeadOn::refine_radii must decrease (one radius per finer level); entry " + std::to_string(l) +
                           " = " + num(radii[l]) + " is not below " + num(radii[l - 1]));
}

}  // namespace remnant::headon
