// RotatingStar_CheckParameters: a magnetised equilibrium (RotatingStar::K_m > 0) is written to the
// grid by SeedMagneticField's toroidal law, evaluated on the grid's rho, h, alpha, psi after
// RotatingStar_Initial: the run needs evolved B and that thorn with the same law (K_m, m), or the
// evolved star would not be the equilibrium that was solved for.
#include <algorithm>
#include <string>

#include "check_field.hpp"
#include "remnant/error.hpp"
#include "remnant/parameters.hpp"

namespace remnant::rotstar {
namespace {

// Every bit: the seeded field's K_m and m must equal the equilibrium's exactly.
std::string number(double x) { return format_number(x, 17); }

}  // namespace

void check_field_parameters(Context& ctx) {
  const Parameters& p = ctx.params();
  const double K_m = ctx.param<double>("RotatingStar", "K_m"), m = ctx.param<double>("RotatingStar", "m");
  if (K_m == 0) return;
  // Point at what the user changed last: a command-line override of any of these, else K_m (set by
  // the user: its default is 0).
  const SourceLocation& where = p.user_origin({{"RotatingStar", "K_m"}, {"RotatingStar", "m"}, {"SeedMagneticField", "K_m"},
                                               {"SeedMagneticField", "m"}, {"SeedMagneticField", "type"}, {"HydroBase", "magnetic_field"}});
  const std::string what = "RotatingStar::K_m = " + number(K_m) + " (m = " + number(m) + ") solves for a star in equilibrium with a toroidal field";
  const std::string mode = p.find("HydroBase", "magnetic_field") ? ctx.param<std::string>("HydroBase", "magnetic_field") : "none";
  if (mode != "evolved")
    throw InputError(where, what + ", but HydroBase::magnetic_field = " + mode +
                                " evolves no field; set HydroBase::magnetic_field: evolved and activate SeedMagneticField "
                                "(type: toroidal, the same K_m and m), or set RotatingStar::K_m: 0");
  const auto& thorns = ctx.active_thorns();
  if (std::find(thorns.begin(), thorns.end(), "SeedMagneticField") == thorns.end())
    throw InputError(where, what + ", which SeedMagneticField writes onto the grid: add SeedMagneticField to active_thorns "
                                "with type: toroidal, K_m: " + number(K_m) + ", m: " + number(m));
  const std::string type = ctx.param<std::string>("SeedMagneticField", "type");
  const double seed_K = ctx.param<double>("SeedMagneticField", "K_m"), seed_m = ctx.param<double>("SeedMagneticField", "m");
  if (type == "poloidal" || seed_K != K_m || seed_m != m)
    throw InputError(where, what + ", but SeedMagneticField writes type = " + type + " with K_m = " + number(seed_K) +
                                ", m = " + number(seed_m) + ": the grid's field would not be the equilibrium's; allowed: "
                                "SeedMagneticField::type toroidal (or poloidal_and_toroidal) with K_m = " + number(K_m) +
                                " and m = " + number(m));
}

}  // namespace remnant::rotstar
