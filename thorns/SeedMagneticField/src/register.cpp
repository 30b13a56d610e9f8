// SeedMagneticField_Initial: the star's field on the faces (HydroBase::Bface1..3) and at cell
// centres (HydroBase::Bvec). See README.md for the laws, the normalisation and the checks.
#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/magnetic_units.hpp"
#include "HydroBase/vector_potential.hpp"
#include "check_parameters.hpp"
#include "hydrostatic_balance.hpp"
#include "seed_field.hpp"
#include "toroidal_potential.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/context.hpp"
#include "remnant/registrar.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"
#include "TOV/cold_slice.hpp"
#include "TOV/tov_solver.hpp"

namespace remnant::seed {
namespace {

using Prim = vars::HydroBase::prim;
using Metric = vars::Spacetime::metric;

struct FaceGroups {
  int face[3];
  int bvec;
  explicit FaceGroups(Context& ctx)
      : face{ctx.var("HydroBase::Bface1"), ctx.var("HydroBase::Bface2"), ctx.var("HydroBase::Bface3")},
        bvec(ctx.var("HydroBase::Bvec")) {
    for (int g : face) ctx.check_access(g);
    ctx.check_access(bvec);
  }
  std::array<Field, 3> faces(Block& b) const { return {b.field(face[0], 0), b.field(face[1], 0), b.field(face[2], 0)}; }
};

StarFields star_fields(Context& ctx, Block& b) {
  const Prim prim(ctx, b);
  const Metric metric(ctx, b);
  return {prim.field(Prim::idx::rho), prim.field(Prim::idx::eps), prim.field(Prim::idx::press),
          metric.field(Metric::idx::alpha), metric.field(Metric::idx::psi)};
}

double global_max(Context& ctx, double local) {
  double g = 0.0;
  MPI_Allreduce(&local, &g, 1, MPI_DOUBLE, MPI_MAX, ctx.grid().comm());
  return g;
}

double max_field_strength(Context& ctx, const FaceGroups& g) {
  double local = 0.0;
  for (Block* b : ctx.grid().local_blocks()) {
    const auto F = g.faces(*b);
    const Field psi = Metric(ctx, *b).field(Metric::idx::psi);
    for_interior(*b, [&](int i, int j, int k) { local = std::max(local, field_strength(*b, F, psi, i, j, k)); });
  }
  return global_max(ctx, local);
}

// max of b^2 / rho over the cells that are not atmosphere (rho >= rho_floor).
double max_magnetisation(Context& ctx, double rho_floor) {
  double local = 0.0;
  const int bvec = ctx.var("HydroBase::Bvec");
  for (Block* b : ctx.grid().local_blocks()) {
    const Prim prim(ctx, *b);
    const Field psi = Metric(ctx, *b).field(Metric::idx::psi);
    for_interior(*b, [&](int i, int j, int k) {
      const double rho = prim.rho(i, j, k);
      if (!(rho >= rho_floor) || rho <= 0.0) return;
      const Point3 f = coords::metric_diagonal(b->coordinates, cell_point(*b, i, j, k));
      const double psi4 = std::pow(psi(i, j, k), 4);
      double B2 = 0, Bv = 0, v2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double B = b->field(bvec, d)(i, j, k), v = prim.vel(d, i, j, k), g = psi4 * f[static_cast<std::size_t>(d)];
        B2 += g * B * B, Bv += g * B * v, v2 += g * v * v;
      }
      // b^2 = B^2 / W^2 + (B_i v^i)^2 for the Eulerian field B and velocity v.
      const double b2 = B2 * (1.0 - v2) + Bv * Bv;
      local = std::max(local, b2 / rho);
    });
  }
  return global_max(ctx, local);
}

// SeedMagneticField::balance = hydrostatic: the TOV star's fluid perturbed so that it balances the
// poloidal field's Lorentz force (hydrostatic_balance.hpp); the faces stay as seeded.
// SeedMagneticField_Balance (scheduled after SeedMagneticField_Initial when balance = hydrostatic):
// the seeded law (A_b, p_cut) comes from the service that SeedMagneticField_Initial published.
void balance_star(Context& ctx) {
  const PoloidalLaw& pol = ctx.service<PoloidalLaw>("SeedMagneticField::poloidal_law");
  const auto slice = tov::polytrope_slice(ctx.param<double>("TOV", "poly_K"), ctx.param<double>("TOV", "poly_gamma"),
                                          ctx.param<double>("TOV", "ye"));
  const tov::TovStar star(*slice, ctx.param<double>("TOV", "rho_central"),
                          static_cast<int>(ctx.param<std::int64_t>("TOV", "samples")));
  const HydrostaticBalance balance(star, pol);
  const double gamma = ctx.param<double>("EOS", "gamma");
  BalanceChange local;
  for (Block* b : ctx.grid().local_blocks()) {
    const Prim prim(ctx, *b);
    const BalanceChange c = apply_balance(*b, balance, prim.field(Prim::idx::rho), prim.field(Prim::idx::eps),
                                          prim.field(Prim::idx::press), gamma);
    local.max_dp_over_p = std::max(local.max_dp_over_p, c.max_dp_over_p);
    local.max_drho_over_rho = std::max(local.max_drho_over_rho, c.max_drho_over_rho);
  }
  char line[256];
  std::snprintf(line, sizeof line,
                "SeedMagneticField: hydrostatic balance of the poloidal field inside r = %.5f: max |dp/p| = %.3e, "
                "max |drho/rho| = %.3e",
                balance.field_radius(), global_max(ctx, local.max_dp_over_p), global_max(ctx, local.max_drho_over_rho));
  ctx.info(line);
}

void initial(Context& ctx) {
  GridDriver& grid = ctx.grid();
  const FaceGroups groups(ctx);
  const std::string type = ctx.param<std::string>("SeedMagneticField", "type");
  const bool poloidal = type != "toroidal", toroidal = type != "poloidal";
  const int quadrature = static_cast<int>(ctx.param<std::int64_t>("SeedMagneticField", "quadrature_points"));
  const bool axisymmetric_2d = grid.dimension() == 2;
  const ToroidalLaw tor{ctx.param<double>("SeedMagneticField", "K_m"), ctx.param<double>("SeedMagneticField", "m"),
                        ctx.param<double>("SeedMagneticField", "rho_cut")};
  for (Block* b : grid.local_blocks())
    for (int g : groups.face) std::fill(b->data(g), b->data(g) + b->size(g), 0.0);

  char line[320];
  PoloidalLaw pol;
  if (poloidal) {
    const int prim_id = Prim::id(ctx);
    ctx.check_access(prim_id);
    const double p_max = grid.reduce(prim_id, Prim::idx::press, ReductionKind::maximum);
    pol.p_cut = ctx.param<double>("SeedMagneticField", "p_cut_fraction") * p_max;
    pol.n_s = ctx.param<double>("SeedMagneticField", "n_s");
    for (Block* b : grid.local_blocks()) set_poloidal_faces(*b, pol, star_fields(ctx, *b).press, groups.faces(*b), quadrature);
    const double unit_max = max_field_strength(ctx, groups);
    if (!(unit_max > 0.0))
      throw InputError(ctx.params().user_origin({{"SeedMagneticField", "p_cut_fraction"}}),
                       "SeedMagneticField: the poloidal potential vanishes on the whole grid (no cell has p > p_cut = " +
                           format_number(pol.p_cut) + " = SeedMagneticField::p_cut_fraction * p_max, p_max = " +
                           format_number(p_max) + "); lower p_cut_fraction or resolve the star");
    const double target = hydrobase::code_from_gauss(ctx.param<double>("SeedMagneticField", "B_max_gauss"));
    pol.A_b = target / unit_max;
    for (Block* b : grid.local_blocks())
      for (int g : groups.face)
        for (std::size_t p = 0; p < b->size(g); ++p) b->data(g)[p] *= pol.A_b;
    std::snprintf(line, sizeof line,
                  "SeedMagneticField: poloidal A_phi = A_b varpi^2 max(p - p_cut, 0)^%g, p_max = %.6e, p_cut = %.6e, "
                  "A_b = %.6e (B_max = %.4e G)",
                  pol.n_s, p_max, pol.p_cut, pol.A_b, ctx.param<double>("SeedMagneticField", "B_max_gauss"));
    ctx.info(line);
    ctx.publish("SeedMagneticField::poloidal_law", std::make_shared<PoloidalLaw>(pol));
  }
  if (toroidal) {
    if (axisymmetric_2d) {
      for (Block* b : grid.local_blocks()) add_toroidal_phi_faces(*b, tor, star_fields(ctx, *b), groups.faces(*b)[2]);
    } else {
      // 3D: the curl of A_z(varpi, z) e_z (toroidal_potential.hpp).
      const Block* cached = nullptr;
      StarFields fields{};
      const ToroidalPotentialTable table(grid, [&](Block& b, int i, int j, int k) {
        if (cached != &b) fields = star_fields(ctx, b), cached = &b;
        return toroidal_densitised_bphi(b, tor, fields, i, j, k);
      });
      for (Block* b : grid.local_blocks()) {
        const CoordinateSystem c = b->coordinates;
        // Face fluxes are linear in A: adding them to the poloidal faces keeps div B at round-off.
        const hydrobase::EdgeIntegrals tor_edges(*b, table.potential(c), quadrature);
        const auto F = groups.faces(*b);
        for (int d = 0; d < 3; ++d) {
          const int top[3] = {b->n[0] + (d == 0), b->n[1] + (d == 1), b->n[2] + (d == 2)};
          for (int k = 0; k < top[2]; ++k)
            for (int j = 0; j < top[1]; ++j)
              for (int i = 0; i < top[0]; ++i) {
                const double area = b->face_area(d, i, j, k);
                if (area > 0.0) F[static_cast<std::size_t>(d)](i, j, k) += tor_edges.face_flux(d, i, j, k) / area;
              }
        }
      }
    }
    std::snprintf(line, sizeof line, "SeedMagneticField: toroidal B = %g (alpha^2 varpi^2 rho h)^%g / (alpha varpi) where rho > %g",
                  tor.K_m, tor.m, tor.rho_cut);
    ctx.info(line);
  }
  // Bvec as HydroBase defines it (area-weighted face means / psi^6).
  const hydrobase::FieldGroups field_groups = hydrobase::FieldGroups::of(ctx);
  for (Block* b : grid.local_blocks()) hydrobase::cell_centred_field(field_groups, *b);
  const double b_max = max_field_strength(ctx, groups);
  const Parameters& p = ctx.params();
  const double rho_floor = p.find("Atmosphere", "rho_thr") ? ctx.param<double>("Atmosphere", "rho_thr") : 0.0;
  const double sigma = max_magnetisation(ctx, rho_floor);
  std::snprintf(line, sizeof line, "SeedMagneticField: max |B| = %.6e (%.4e G), max b^2/rho in the star = %.4e", b_max,
                hydrobase::gauss_from_code(b_max), sigma);
  ctx.info(line);
  if (p.find(kMagnetisationCapThorn, kMagnetisationCapName)) {
    const double cap = ctx.param<double>(kMagnetisationCapThorn, kMagnetisationCapName);
    if (sigma > cap)
      throw InputError(p.user_origin({{"SeedMagneticField", poloidal ? "B_max_gauss" : "K_m"},
                                       {kMagnetisationCapThorn, kMagnetisationCapName}}),
                       std::string("SeedMagneticField: the seeded field reaches b^2/rho = ") + format_number(sigma) +
                           " in the star, above the atmosphere's cap " + kMagnetisationCapThorn + "::" + kMagnetisationCapName +
                           " = " + format_number(cap) + "; lower SeedMagneticField::" + (poloidal ? "B_max_gauss" : "K_m") +
                           " (or raise the cap)");
  }
}

}  // namespace
}  // namespace remnant::seed

REMNANT_REGISTER_THORN(SeedMagneticField) {
  reg.function("SeedMagneticField_CheckParameters", remnant::seed::check_parameters);
  reg.function("SeedMagneticField_Initial", remnant::seed::initial);
  reg.function("SeedMagneticField_Balance", remnant::seed::balance_star);
}
