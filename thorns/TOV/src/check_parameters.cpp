// TOV_CheckParameters: a star that cannot make sense stops the run before the first step, naming
// the parameters: a central density outside the EOS's range or not above the atmosphere threshold,
// a star larger than the grid, a perturbation faster than light (issue 16).
#include "check_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "TOV/tov_solver.hpp"
#include "remnant/parameters.hpp"
#include "slice_from_parameters.hpp"

namespace remnant::tov {
namespace {

std::string num(double x) { return format_number(x); }

// Radius of the largest sphere about the origin inside the grid (a lower bound of 0 is a symmetry
// plane, the origin or an axis: the domain continues across it). Infinity without Grid parameters.
double grid_reach(const Parameters& p) {
  if (!p.find("Grid", "xmax")) return std::numeric_limits<double>::infinity();
  const auto& coords = p.get<std::string>("Grid", "coordinates");
  const auto dim = p.get<std::int64_t>("Grid", "dimension");
  const auto& lo = p.get<std::vector<double>>("Grid", "xmin");
  const auto& hi = p.get<std::vector<double>>("Grid", "xmax");
  auto reach = [&](std::size_t d) { return lo[d] >= 0 ? hi[d] : std::min(-lo[d], hi[d]); };
  if (coords == "spherical") return hi[0];
  double r = coords == "cylindrical" ? hi[0] : reach(0);
  for (std::size_t d = 1; d < static_cast<std::size_t>(dim); ++d)
    if (coords == "cartesian" || d == 1) r = std::min(r, reach(d));
  return r;
}

}  // namespace

void check_parameters(Context& ctx) {
  const Parameters& p = ctx.params();
  const double rho_c = ctx.param<double>("TOV", "rho_central");
  const auto rho_where = p.origin("TOV", "rho_central");
  const DensityRange range = slice_density_range(ctx);
  if (rho_c > range.max || rho_c < range.min)
    throw InputError(rho_where, "TOV::rho_central = " + num(rho_c) + " is outside the EOS's densities [" +
                                    num(range.min) + ", " + num(range.max) + "] (" + range.source +
                                    "); the star would be cut off there");
  if (p.find("Atmosphere", "rho_thr")) {
    const double rho_thr = ctx.param<double>("Atmosphere", "rho_thr");
    if (!(rho_c > rho_thr))
      throw InputError(p.user_origin({{"Atmosphere", "rho_thr"}, {"TOV", "rho_central"}}),
                       "Atmosphere::rho_thr = " + num(rho_thr) + " is not below TOV::rho_central = " + num(rho_c) +
                           ": the whole star would be atmosphere (M = 0); allowed: rho_thr < rho_central");
  }
  const auto slice = slice_from_parameters(ctx);
  std::unique_ptr<TovStar> star;
  try {
    star = std::make_unique<TovStar>(*slice, rho_c, static_cast<int>(ctx.param<std::int64_t>("TOV", "samples")));
  } catch (const std::exception& e) {
    throw InputError(p.user_origin({{"TOV", "rho_central"}, {"TOV", "poly_K"}, {"TOV", "poly_gamma"}}),
                     std::string("no TOV star for these parameters: ") + e.what());
  }
  const double R = star->isotropic_radius(), M = star->gravitational_mass();
  if (!std::isfinite(R) || !std::isfinite(M) || !(M > 0))
    throw InputError(p.user_origin({{"TOV", "rho_central"}, {"TOV", "poly_K"}, {"TOV", "poly_gamma"}}),
                     "the TOV star has mass M = " + num(M) + " and radius R = " + num(R) +
                         ": check TOV::rho_central, TOV::poly_K, TOV::poly_gamma");
  const double reach = grid_reach(p);
  if (R >= reach)
    throw InputError(p.user_origin({{"TOV", "poly_K"}, {"TOV", "rho_central"}, {"TOV", "poly_gamma"}, {"Grid", "xmax"}}),
                     "the star (isotropic radius R = " + num(R) + ", M = " + num(M) +
                         ") is larger than the grid, which reaches r = " + num(reach) +
                         " (Grid::xmin, Grid::xmax): enlarge the grid or change TOV::rho_central, TOV::poly_K, "
                         "TOV::poly_gamma");
  // v = A sin(pi r / R) radially in the conformally flat metric: |v| = psi^2 |A sin(pi r / R)| < 1.
  if (ctx.param<std::string>("TOV", "perturbation") == "radial_velocity") {
    const double amp = ctx.param<double>("TOV", "perturbation_amplitude");
    double worst = 0, where = 0;
    for (int k = 1; k < 2000; ++k) {
      const double r = R * k / 2000.0;
      const double w = std::pow(star->at(r).psi, 2) * std::abs(std::sin(std::numbers::pi * r / R));
      if (w > worst) worst = w, where = r;
    }
    if (!(std::abs(amp) * worst < 1))
      throw InputError(p.origin("TOV", "perturbation_amplitude"),
                       "TOV::perturbation_amplitude = " + num(amp) + " makes the star's fluid move at |v| = " +
                           num(std::abs(amp) * worst) + " (the speed of light is 1) at r = " + num(where) +
                           "; allowed: |amplitude| < " + num(1 / worst));
  }
}

}  // namespace remnant::tov
