// RotatingStar_Initial: solve the model (once per parameter set: the initial regrid calls this on
// every new mesh), log and write its global quantities, then write prim (interior) and the metric
// (everywhere, ghosts included), v^phi and beta^phi turned into the grid's vector components.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>

#include "EOS/eos.hpp"
#include "RotatingStar/eos_slice.hpp"
#include "RotatingStar/first_law_check.hpp"
#include "check_field.hpp"
#include "RotatingStar/report.hpp"
#include "RotatingStar/rns_solver.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/context.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/domain.hpp"
#include "remnant/registrar.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::rotstar {
namespace {

std::unique_ptr<tov::ColdSlice> make_slice(const Context& ctx) {
  if (ctx.param<std::string>("RotatingStar", "eos_slice") == "polytrope")
    return tov::polytrope_slice(ctx.param<double>("RotatingStar", "poly_K"), ctx.param<double>("RotatingStar", "poly_gamma"),
                                ctx.param<double>("RotatingStar", "ye"));
  if (ctx.param<std::string>("RotatingStar", "eos_slice") == "piecewise_polytrope") {
    try {
      return piecewise_polytrope_slice(ctx.param<double>("RotatingStar", "poly_K"),
                                       ctx.param<std::vector<double>>("RotatingStar", "pwp_gammas"),
                                       ctx.param<std::vector<double>>("RotatingStar", "pwp_rho_bounds"),
                                       ctx.param<double>("RotatingStar", "ye"));
    } catch (const std::runtime_error& e) {
      throw RunError(std::string("RotatingStar::pwp_gammas, pwp_rho_bounds: ") + e.what());
    }
  }
  const auto* table = ctx.service<eos::EOS>("eos").tabulated();
  const std::string kind = ctx.param<std::string>("RotatingStar", "eos_slice");
  if (!table) throw RunError("RotatingStar::eos_slice = " + kind + " needs EOS::type = tabulated");
  const std::string bad = check_density_in_table(*table, ctx.param<double>("RotatingStar", "rho_central"));
  if (!bad.empty()) throw RunError("RotatingStar::rho_central: " + bad);
  const double T = ctx.param<double>("RotatingStar", "slice_T");
  try {
    return kind == "tabulated_beta" ? beta_slice(*table, T) : fixed_ye_slice(*table, ctx.param<double>("RotatingStar", "ye"), T);
  } catch (const std::runtime_error& e) {
    throw RunError(std::string("RotatingStar::eos_slice = ") + kind + ": " + e.what() + " (RotatingStar::slice_T, RotatingStar::ye)");
  }
}

RnsParameters read_parameters(const Context& ctx) {
  auto real = [&](const char* n) { return ctx.param<double>("RotatingStar", n); };
  auto integer = [&](const char* n) { return int(ctx.param<std::int64_t>("RotatingStar", n)); };
  RnsParameters p;
  p.rho_central = real("rho_central");
  p.law = ctx.param<std::string>("RotatingStar", "rotation_law") == "uniform" ? RotationLaw::uniform : RotationLaw::j_constant;
  p.omega = real("omega");
  p.axis_ratio = real("axis_ratio");
  p.A2 = real("A2");
  p.nr = integer("nr");
  p.n_theta = integer("n_theta");
  p.lmax = integer("lmax");
  p.r_out_factor = real("r_out_factor");
  p.tolerance = real("tolerance");
  p.field.K_m = real("K_m");
  p.field.m = real("m");
  return p;
}

// A table slice's departure from the first law in the star's core (first_law_check.hpp): logged,
// and a warning where the star's compressions would heat it.
void report_first_law(const Context& ctx, const tov::ColdSlice& slice, double rho_c) {
  const auto* table = ctx.service<eos::EOS>("eos").tabulated();
  const std::string kind = ctx.param<std::string>("RotatingStar", "eos_slice");
  if (!table || (kind != "tabulated_beta" && kind != "tabulated_fixed_ye")) return;
  const double T_param = ctx.param<double>("RotatingStar", "slice_T");
  const double T = T_param < 0 ? table->bounds().T_min : T_param;
  const FirstLawDeparture d = first_law_departure(*table, slice, T, 0.1 * rho_c, rho_c);
  char msg[512];
  std::snprintf(msg, sizeof msg,
                "RotatingStar: first law of the table %s in the star's core (rho_c/10 .. rho_c, T = %g MeV): "
                "|(deps/drho)_{T,Ye} rho^2/p - 1| mean %.3f, max %.3f at rho = %.4g",
                table->table().file.c_str(), T, d.mean, d.worst, d.rho_worst);
  ctx.info(msg);
  if (d.mean > kFirstLawWarnMean && ctx.rank() == 0) {
    char more[256];
    std::snprintf(more, sizeof more,
                  " (above %.2f): the interpolated table is not thermodynamically consistent there, so the star's "
                  "compressions and expansions move eps off the slice and heat the cold star, whose rho_c then drifts by "
                  "percents over milliseconds; use a finer table",
                  kFirstLawWarnMean);
    ctx.warn(std::string(msg) + more);
  }
}

struct Cached {
  std::unique_ptr<tov::ColdSlice> slice;
  std::unique_ptr<RotatingStarModel> model;
};

std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The models of this simulation, keyed by the resolved parameters of this thorn. They live with the
// simulation's context, not in a static: a table slice refers to the simulation's EOS, and a later
// simulation in the same process (tests) with other EOS parameters would otherwise get a model of
// the earlier EOS, whose table no longer exists.
using ModelCache = std::map<std::string, Cached>;

const RotatingStarModel& model_for(Context& ctx) {
  if (!ctx.has_service("RotatingStar::models")) ctx.publish("RotatingStar::models", std::make_shared<ModelCache>());
  ModelCache& cache = ctx.service<ModelCache>("RotatingStar::models");
  std::string key = ctx.param<std::string>("RotatingStar", "eos_slice") + ctx.param<std::string>("RotatingStar", "rotation_law");
  for (const char* n : {"poly_K", "poly_gamma", "ye", "slice_T", "rho_central", "omega", "axis_ratio", "A2", "r_out_factor", "tolerance", "K_m", "m"})
    key += " " + exact(ctx.param<double>("RotatingStar", n));
  for (const char* n : {"nr", "n_theta", "lmax"}) key += " " + std::to_string(ctx.param<std::int64_t>("RotatingStar", n));
  for (const char* n : {"pwp_gammas", "pwp_rho_bounds"})
    for (double v : ctx.param<std::vector<double>>("RotatingStar", n)) key += " " + std::string(n) + exact(v);
  auto it = cache.find(key);
  if (it != cache.end()) return *it->second.model;
  Cached c;
  c.slice = make_slice(ctx);
  try {
    c.model = std::make_unique<RotatingStarModel>(*c.slice, read_parameters(ctx));
  } catch (const RnsError& e) {
    throw RunError(std::string("RotatingStar: ") + e.what());
  }
  const auto rows = global_rows(c.model->globals());
  std::string line = "RotatingStar:";
  for (const auto& [name, v] : rows) {
    char buf[64];
    std::snprintf(buf, sizeof buf, " %s = %.8g", name.c_str(), v);
    line += buf;
  }
  ctx.info(line);
  report_first_law(ctx, *c.slice, c.model->globals().rho_max);
  if (ctx.rank() == 0) {
    std::ofstream out(ctx.out_dir() + "/rotating_star.tsv");
    for (std::size_t k = 0; k < rows.size(); ++k) out << rows[k].first << (k + 1 < rows.size() ? '\t' : '\n');
    out.precision(12);
    for (std::size_t k = 0; k < rows.size(); ++k) out << rows[k].second << (k + 1 < rows.size() ? '\t' : '\n');
  }
  return *cache.emplace(key, std::move(c)).first->second.model;
}

// A mirror plane through the rotation axis (Cartesian x = 0 or y = 0) reverses the rotation in
// the image half: v^phi and beta^phi would jump there and J would cancel. Only z = 0 mirrors a
// rotating star.
void check_rotation_symmetry(const Context& ctx, const RotatingStarModel& star) {
  if (star.globals().omega_c == 0 || ctx.grid().coordinates() != CoordinateSystem::cartesian || ctx.grid().dimension() < 2)
    return;
  const Domain d = ctx.grid().domain();
  for (int dir = 0; dir < 2; ++dir)
    for (int side = 0; side < 2; ++side)
      if (d.faces.boundary[dir][side] == Boundary::reflect)
        throw RunError(std::string("RotatingStar: Grid::boundary_") + (side == 0 ? "lower" : "upper") + "[" + std::to_string(dir) +
                       "] = reflect mirrors the star through a plane containing the rotation axis, which reverses its rotation; "
                       "a rotating star needs the whole (x, y) plane (outflow in x and y; reflect in z is allowed)");
}

void initial(Context& ctx) {
  const RotatingStarModel& star = model_for(ctx);
  check_rotation_symmetry(ctx, star);
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::Spacetime::metric metric(ctx, *b);
    const CoordinateSystem cs = b->coordinates;
    // The model at a grid point, and the grid components of the phi vector u^phi d_phi.
    auto evaluate = [&](const Point3& x) {
      const Point3 X = coords::to_cartesian(cs, x);
      const double r = std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
      return std::pair{star.at(r, r > 0 ? std::acos(std::clamp(X[2] / r, -1.0, 1.0)) : 0.0), X};
    };
    auto phi_vector = [&](const Point3& x, const Point3& X, double u) {
      return coords::vector_from_cartesian(cs, x, {-u * X[1], u * X[0], 0.0});
    };
    for (int k = -b->ng[2]; k < b->n[2] + b->ng[2]; ++k)
      for (int j = -b->ng[1]; j < b->n[1] + b->ng[1]; ++j)
        for (int i = -b->ng[0]; i < b->n[0] + b->ng[0]; ++i) {
          const Point3 x = cell_point(*b, i, j, k);
          const auto [p, X] = evaluate(x);
          metric.psi(i, j, k) = p.psi;
          metric.alpha(i, j, k) = p.alpha;
          const Point3 beta = phi_vector(x, X, p.beta_phi);
          for (int c = 0; c < 3; ++c) metric.beta(c, i, j, k) = beta[c];
        }
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 x = cell_point(*b, i, j, k);
      const auto [p, X] = evaluate(x);
      const Point3 v = phi_vector(x, X, p.vel_phi);
      prim.rho(i, j, k) = p.rho;
      for (int c = 0; c < 3; ++c) prim.vel(c, i, j, k) = v[c];
      prim.eps(i, j, k) = p.eps;
      prim.press(i, j, k) = p.press;
      prim.temperature(i, j, k) = 0.0;  // T follows from eps in HydroBase_InitialCons
      prim.Ye(i, j, k) = p.ye;
      prim.W(i, j, k) = p.W;
      prim.cs2(i, j, k) = 0.0;
    });
  }
}

}  // namespace
}  // namespace remnant::rotstar

REMNANT_REGISTER_THORN(RotatingStar) {
  reg.function("RotatingStar_CheckParameters", remnant::rotstar::check_field_parameters);
  reg.function("RotatingStar_Initial", remnant::rotstar::initial);
}
