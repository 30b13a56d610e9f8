#include "check_parameters.hpp"

#include <algorithm>
#include <vector>

namespace remnant::seed {

namespace {

// At a reflect plane B must continue as the seeded field does: a poloidal field about z is minus its
// pseudo-vector mirror image across planes containing the axis (x = 0, y = 0) and its mirror image
// across the equator; a toroidal field the other way round. Grid::axial_vector_reflection must say
// so for every direction with a reflect face; a mixed field has no reflection symmetry at all.
void check_symmetry(Context& ctx, const std::string& type, const std::string& coords, std::int64_t dim) {
  const Parameters& p = ctx.params();
  const auto& lower = ctx.param<std::vector<std::string>>("Grid", "boundary_lower");
  const auto& upper = ctx.param<std::vector<std::string>>("Grid", "boundary_upper");
  const std::vector<std::string> axial = p.find("Grid", "axial_vector_reflection")
                                             ? ctx.param<std::vector<std::string>>("Grid", "axial_vector_reflection")
                                             : std::vector<std::string>{"mirror", "mirror", "mirror"};
  for (int d = 0; d < static_cast<int>(dim) && d < 3; ++d) {
    const auto i = static_cast<std::size_t>(d);
    if (lower[i] != "reflect" && upper[i] != "reflect") continue;
    const bool equator = coords != "cartesian" || d == 2;  // curvilinear reflect planes are z = const
    const std::string face = lower[i] == "reflect" ? "boundary_lower" : "boundary_upper";
    const std::string plane = (equator ? "the equatorial plane" : (d == 0 ? "the plane x = 0" : "the plane y = 0")) +
                              std::string(" (Grid::") + face + "[" + std::to_string(d) + "] = reflect)";
    if (type == "poloidal_and_toroidal")
      throw InputError(p.user_origin({{"Grid", face.c_str()}, {"SeedMagneticField", "type"}}),
                       "SeedMagneticField::type = poloidal_and_toroidal with a reflect boundary at " + plane +
                           ": the poloidal and toroidal parts have opposite parities there, "
                           "so no Grid::axial_vector_reflection fits; cover the whole star (no reflect boundary)");
    const bool poloidal = type == "poloidal";
    const std::string want = (poloidal != equator) ? "opposite" : "mirror";
    if (axial[i] != want)
      throw InputError(p.user_origin({{"Grid", "axial_vector_reflection"}, {"SeedMagneticField", "type"}}),
                       "SeedMagneticField::type = " + type + " with a reflect boundary at " + plane +
                           " needs Grid::axial_vector_reflection[" + std::to_string(d) + "] = " + want + " (got " + axial[i] +
                           "): a " + type + " field about z is " + (want == "opposite" ? "minus its" : "its") +
                           " pseudo-vector mirror image there");
  }
}

// balance = hydrostatic perturbs the static TOV star against a poloidal field's force, with the
// ideal gas relation e = rho + p / (Gamma - 1) (hydrostatic_balance.hpp).
void check_balance(Context& ctx, const std::string& type) {
  const Parameters& p = ctx.params();
  if (ctx.param<std::string>("SeedMagneticField", "balance") != "hydrostatic") return;
  const auto where = [&](const char* thorn, const char* name) {
    return p.user_origin({{"SeedMagneticField", "balance"}, {thorn, name}});
  };
  if (type != "poloidal")
    throw InputError(where("SeedMagneticField", "type"),
                     "SeedMagneticField::balance = hydrostatic balances a poloidal field's Lorentz force only, but "
                     "SeedMagneticField::type = " + type + "; use type: poloidal or balance: none");
  const auto& active = ctx.active_thorns();
  if (std::find(active.begin(), active.end(), "TOV") == active.end())
    throw InputError(p.user_origin({{"SeedMagneticField", "balance"}}),
                     "SeedMagneticField::balance = hydrostatic needs the static spherical star of the TOV thorn "
                     "(TOV is not in active_thorns); use balance: none for other initial data");
  if (ctx.param<std::string>("TOV", "eos_slice") != "polytrope")
    throw InputError(where("TOV", "eos_slice"),
                     "SeedMagneticField::balance = hydrostatic needs TOV::eos_slice = polytrope (got " +
                         ctx.param<std::string>("TOV", "eos_slice") + ")");
  const std::string eos = p.find("EOS", "type") ? ctx.param<std::string>("EOS", "type") : "none";
  if (eos != "ideal_gas")
    throw InputError(where("EOS", "type"),
                     "SeedMagneticField::balance = hydrostatic sets rho and eps from p and e + p with the ideal gas "
                     "law and needs EOS::type = ideal_gas (got " + eos + ")");
}

}  // namespace

void check_parameters(Context& ctx) {
  const Parameters& p = ctx.params();
  const std::string mode = p.find("HydroBase", "magnetic_field") ? ctx.param<std::string>("HydroBase", "magnetic_field") : "none";
  if (mode != "evolved")
    throw InputError(p.user_origin({{"HydroBase", "magnetic_field"}, {"SeedMagneticField", "type"}}),
                     "SeedMagneticField is active but HydroBase::magnetic_field = " + mode +
                         ": the run has no magnetic field to seed; set HydroBase::magnetic_field: evolved or remove "
                         "SeedMagneticField from active_thorns");
  const std::string type = ctx.param<std::string>("SeedMagneticField", "type");
  const bool poloidal = type != "toroidal";
  check_balance(ctx, type);
  const double fraction = ctx.param<double>("SeedMagneticField", "p_cut_fraction");
  if (poloidal && !(fraction < 1.0))
    throw InputError(p.user_origin({{"SeedMagneticField", "p_cut_fraction"}}),
                     "SeedMagneticField::p_cut_fraction = " + format_number(fraction) +
                         " puts p_cut at or above the maximum pressure p_max, so the poloidal potential "
                         "A_phi = A_b varpi^2 max(p - p_cut, 0)^n_s vanishes everywhere; allowed: [0, 1)");
  if (p.find("Grid", "coordinates")) {
    const std::string coords = ctx.param<std::string>("Grid", "coordinates");
    const auto dim = ctx.param<std::int64_t>("Grid", "dimension");
    check_symmetry(ctx, type, coords, dim);
    const bool axisymmetric_2d = dim == 2 && coords != "cartesian";
    if (dim != 3 && !axisymmetric_2d)
      throw InputError(p.user_origin({{"Grid", "dimension"}, {"Grid", "coordinates"}, {"SeedMagneticField", "type"}}),
                       "SeedMagneticField needs the star's axis on the grid: Grid::dimension = " + std::to_string(dim) +
                           " with Grid::coordinates = " + coords +
                           " has none; allowed: dimension 2 with cylindrical or spherical coordinates, or dimension 3");
  }
}

}  // namespace remnant::seed
