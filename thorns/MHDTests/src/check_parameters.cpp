// MHDTests_CheckParameters: each problem is defined for one adiabatic index and a Cartesian grid
// (the 2D ones need at least two dimensions); anything else stops the run before the first step.
#include "check_parameters.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "remnant/error.hpp"
#include "settings.hpp"

namespace remnant::mhd_tests {

void check_parameters(Context& ctx) {
  const Settings s = settings_from(ctx);
  const std::string problem(name_of(s.problem));
  const auto& params = ctx.params();
  if (ctx.param<std::string>("EOS", "type") != "ideal_gas")
    throw InputError(params.origin("EOS", "type"),
                     "MHDTests::problem = " + problem + " is defined for an ideal gas: set EOS::type = ideal_gas");
  const double gamma = setup_of(s.problem).gamma, given = ctx.param<double>("EOS", "gamma");
  if (std::abs(given - gamma) > 1e-12 * gamma) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "MHDTests::problem = %s needs EOS::gamma = %.17g (got %.17g)", problem.c_str(),
                  gamma, given);
    throw InputError(params.origin("EOS", "gamma"), buf);
  }
  if (ctx.param<std::string>("HydroBase", "magnetic_field") != "evolved")
    throw InputError(params.origin("HydroBase", "magnetic_field"),
                     "MHDTests::problem = " + problem + " is a magnetised problem: set HydroBase::magnetic_field = evolved");
  if (ctx.grid().coordinates() != CoordinateSystem::cartesian)
    throw InputError(params.origin("Grid", "coordinates"),
                     "MHDTests::problem = " + problem + " runs on Cartesian grids (Grid::coordinates = cartesian)");
  if (!is_riemann_problem(s.problem) && ctx.grid().dimension() < 2)
    throw InputError(params.origin("Grid", "dimension"),
                     "MHDTests::problem = " + problem + " is a 2D problem: Grid::dimension must be 2 or 3");
}

}  // namespace remnant::mhd_tests
