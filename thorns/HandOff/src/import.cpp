// HandOff_CheckParameters, HandOff_Initial, HandOff_ImportConserved: the paper's hand-off onto the
// grid's cells (section "Spacetime and matter hand-off"; Appendix for the transformations).
#include "import.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <vector>
#include <cmath>
#include <numbers>

#include "HandOff/handoff_state.hpp"
#include "HandOff/sampler.hpp"
#include "read_source.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/parameters.hpp"
#include "remnant/vars/HandOff.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/vector_potential.hpp"
#include "magnetic_import.hpp"
#include "magnetic_source.hpp"
#include "source_integrals.hpp"
#include "source_quantities.hpp"

namespace remnant::handoff {
namespace {

std::string num(double x) { return format_number(x, 10); }

Totals totals(const Integrals& i) {
  return {i.rest_mass, i.angular_momentum, i.energy, i.magnetic_energy, i.magnetic_energy_toroidal};
}

HandOffState& state(Context& ctx) {
  if (!ctx.has_service("HandOff::state")) ctx.publish<HandOffState>("HandOff::state", std::make_shared<HandOffState>());
  return ctx.service<HandOffState>("HandOff::state");
}

// Reads and prepares the 3D data once per run (the initial regrid runs `initial` again).
void load(Context& ctx, HandOffState& st) {
  if (st.source) return;
  st.target = TargetDomain::from_parameters(ctx.params());
  st.source = read_source(ctx, st.notes);
  const SourceData& src = *st.source;
  ctx.info("HandOff: " + src.format + " data, iteration " + std::to_string(src.iteration) + ", time " + num(src.time) + ", " +
           std::to_string(src.levels.size()) + " refinement level(s), finest spacing " + num(src.finest_spacing()) +
           (src.reflection[0] || src.reflection[1] || src.reflection[2]
                ? std::string(", unfolded across") + (src.reflection[0] ? " x=0" : "") + (src.reflection[1] ? " y=0" : "") +
                      (src.reflection[2] ? " z=0" : "")
                : std::string("")));
  ctx.info("HandOff: onto the grid " + st.target.describe());
  for (const auto& n : st.notes) ctx.info("HandOff: note: " + n);
  // Matter: points denser than the data's atmosphere (HandOff::atmosphere_density; automatic: the
  // grid's Atmosphere::rho_thr or twice the data's floor, the larger).
  double atmosphere_rho = ctx.param<double>("HandOff", "atmosphere_density");
  const double rho_min = smallest_density(src);
  if (atmosphere_rho < 0) {
    const bool thr = ctx.params().find("Atmosphere", "rho_thr") != nullptr;
    atmosphere_rho = std::max(thr ? ctx.param<double>("Atmosphere", "rho_thr") : 0.0, 2 * rho_min);
  }
  // Without the data's 3-metric the densitised variables lack sqrt(gamma): XCFC then iterates psi
  // with the data's primitives (from_primitives); with it the conserved variables are imported.
  const Parameters& p = ctx.params();
  const bool from_primitives = p.find("XCFC", "initial_metric") && ctx.param<std::string>("XCFC", "initial_metric") == "from_primitives";
  if (from_primitives && src.has_metric)
    throw InputError(p.origin("XCFC", "initial_metric"),
                     "HandOff imports densitised conserved variables: XCFC::initial_metric must be from_conserved (is from_primitives, "
                     "allowed only for data without ADMBase::gxx..gzz; " +
                         (src.file_of.count("gxx") ? src.file_of.at("gxx") : src.file_of.begin()->second) + " has them)");
  if (from_primitives)
    ctx.info("HandOff: XCFC::initial_metric = from_primitives: the data's rho, eps and v are kept and psi is iterated with them; "
             "the grid's rest mass is then int psi^6 rho W dV (the data give no sqrt(gamma) to conserve)");
  else if (!src.has_metric)
    ctx.info("HandOff: note: without ADMBase::gxx..gzz the imported D = rho W lacks sqrt(gamma): rho after the metric solve is "
             "rho / psi^6 (XCFC::initial_metric = from_primitives keeps the data's rho)");
  const SourceIntegrals I = integrate_source(src, st.target, atmosphere_rho);
  auto& r = st.report;
  r.source_all = totals(I.all), r.source_covered = totals(I.covered), r.source_grid = totals(I.grid);
  r.atmosphere_rho = atmosphere_rho;
  r.source_matter_rest_mass = I.all.matter_rest_mass;
  r.outside_fraction = I.outside_fraction();
  r.has_metric = src.has_metric;
  r.has_lapse = src.has_lapse;
  ctx.info("HandOff: the data's smallest rho " + num(rho_min) + "; matter (rho > " + num(atmosphere_rho) +
           ", HandOff::atmosphere_density) holds " + num(I.all.matter_rest_mass) + " of the 3D rest mass " +
           num(I.all.rest_mass) + ", of it outside the grid: " + num(r.outside_fraction));
  const double limit = ctx.param<double>("HandOff", "max_outside_fraction");
  if (r.outside_fraction > limit)
    throw RunError("HandOff: " + num(100 * r.outside_fraction) + " % of the 3D rest mass of the matter (rho > " + num(atmosphere_rho) +
                   ", HandOff::atmosphere_density; M0 = " + num(I.all.matter_rest_mass) + ") lies outside the grid " +
                   st.target.describe() + "; the grid cuts the star: enlarge Grid::xmax (or "
                   "raise HandOff::max_outside_fraction = " + num(limit) + ")");
}

struct CellSample {
  double cons[6] = {0, 0, 0, 0, 0, 0};
  double rho = 0, eps = 0, vel[3] = {0, 0, 0}, gamma13 = 0, alp = 0;
  int hits = 0, samples = 1;
};

// The cell's values: the volume-weighted mean (weights sqrt(f)) of n per direction samples at the
// midpoints of equal sub-intervals of the cell, which approximates the cell average a
// finite-volume grid holds to O(dx^2 / n^2); on 2D grids each sample is itself the mean over phi of
// nphi samples on its ring. Conserved variables count samples without data as vacuum, primitives
// and the metric are means over the samples that have data.
CellSample sample_cell(const Sampler& s, const TargetDomain& t, const Block& b, int i, int j, int k, int n, int nphi) {
  const CoordinateSystem cs = b.coordinates;
  const std::array<int, 3> ijk{i, j, k};
  std::array<std::vector<double>, 3> pos, wt;  // sample coordinates and weights per direction
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    if (d == 2 && t.averages_over_phi()) {
      for (int m = 0; m < nphi; ++m) pos[ud].push_back((m + 0.5) * 2 * std::numbers::pi / nphi), wt[ud].push_back(1.0);
    } else if (direction_used(b, d) && n > 1) {
      for (int m = 0; m < n; ++m) {
        const double x = b.face_coordinate(d, ijk[ud]) + (m + 0.5) / n * b.dx[ud];
        pos[ud].push_back(x), wt[ud].push_back(coords::volume_factor(cs, d, x));
      }
    } else {
      pos[ud].push_back(b.centroid(d, ijk[ud])), wt[ud].push_back(1.0);
    }
  }
  CellSample c;
  c.samples = static_cast<int>(pos[0].size() * pos[1].size() * pos[2].size());
  double v[14], total = 0, hit = 0;
  for (std::size_t c2 = 0; c2 < pos[2].size(); ++c2)
    for (std::size_t c1 = 0; c1 < pos[1].size(); ++c1)
      for (std::size_t c0 = 0; c0 < pos[0].size(); ++c0) {
        const Point3 xs{pos[0][c0], pos[1][c1], pos[2][c2]};
        const double w = wt[0][c0] * wt[1][c1] * wt[2][c2];
        total += w;
        if (!s.sample(coords::to_cartesian(cs, xs), v)) continue;
        ++c.hits;
        hit += w;
        const Point3 S = coords::covector_from_cartesian(cs, xs, {v[1], v[2], v[3]});
        const Point3 vel = coords::vector_from_cartesian(cs, xs, {v[9], v[10], v[11]});
        c.cons[0] += w * v[0], c.cons[4] += w * v[4], c.cons[5] += w * v[5];
        for (int a = 0; a < 3; ++a) c.cons[1 + a] += w * S[static_cast<std::size_t>(a)], c.vel[a] += w * vel[static_cast<std::size_t>(a)];
        c.rho += w * v[6], c.eps += w * v[7], c.gamma13 += w * v[12], c.alp += w * v[13];
      }
  for (double& q : c.cons) q /= total;
  if (c.hits > 0) {
    c.rho /= hit, c.eps /= hit, c.gamma13 /= hit, c.alp /= hit;
    for (double& q : c.vel) q /= hit;
  }
  return c;
}

// The first-guess velocity as a physical state (v^2 < 1 with the cell's psi^4): averages over phi
// and the cubic interpolation of v^i where fast ejecta meet the atmosphere can reach v^2 >= 1
// (HydroBase_InitialCons then writes NaN). Only the guess is capped (at W = 10): the imported
// conserved variables decide the recovered velocity.
void cap_guess_velocity(CoordinateSystem cs, const Point3& x, double psi4, double (&vel)[3]) {
  constexpr double kMaxV2 = 0.99;
  const Point3 f = coords::metric_diagonal(cs, x);
  double v2 = 0;
  for (std::size_t a = 0; a < 3; ++a) v2 += psi4 * f[a] * vel[a] * vel[a];
  if (!(v2 > kMaxV2)) return;
  const double scale = std::sqrt(kMaxV2 / v2);
  for (double& v : vel) v *= scale;
}

}  // namespace

void check_parameters(Context& ctx) {
  const Parameters& p = ctx.params();
  if (ctx.param<std::vector<std::string>>("HandOff", "files").empty())
    throw InputError(p.origin("HandOff", "files"), "HandOff::files is empty: name the 3D data files (paths or globs)");
  // from_primitives only for data without a 3-metric (checked when they are read).
  if (p.find("XCFC", "initial_metric") && ctx.param<std::string>("XCFC", "initial_metric") != "from_conserved" &&
      ctx.param<std::string>("XCFC", "initial_metric") != "from_primitives")
    throw InputError(p.origin("XCFC", "initial_metric"),
                     "HandOff imports densitised conserved variables: XCFC::initial_metric must be from_conserved (is " +
                         ctx.param<std::string>("XCFC", "initial_metric") + ")");
  TargetDomain::from_parameters(p);  // a grid HandOff cannot fill is an input error now
  check_centre_on_mirrors(p, reflection_parameter(p));  // the files' own mirrors: when they are read
}

void initial(Context& ctx) {
  HandOffState& st = state(ctx);
  load(ctx, st);
  const SourceData& src = *st.source;
  const TargetDomain& t = st.target;
  std::vector<std::string> fields = conserved_fields();
  for (const auto& f : primitive_fields()) fields.push_back(f);
  // Sample order: Dt St0 St1 St2 taut DYet | rho eps Ye vel0 vel1 vel2 gamma13 alp (sample_cell).
  const Sampler sampler(src, fields);
  const auto phi_param = static_cast<int>(ctx.param<std::int64_t>("HandOff", "phi_samples"));
  const auto per_direction = static_cast<int>(ctx.param<std::int64_t>("HandOff", "cell_samples"));
  const double ye_default = ctx.param<double>("HandOff", "ye");
  const double h = src.finest_spacing();
  auto& r = st.report;
  long long cells = 0, empty = 0, partial = 0;
  int max_phi = 1;
  double mass = 0;
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::Spacetime::metric metric(ctx, *b);
    const vars::HandOff::imported imp(ctx, *b);
    const vars::HandOff::source_at_cells sm(ctx, *b);
    const CoordinateSystem cs = b->coordinates;
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 x = cell_point(*b, i, j, k);
      // Samples on the ring: about one per 3D spacing there (the finest level at phi = 0).
      const double ring = cs == CoordinateSystem::cylindrical ? x[0] : x[0] * std::sin(x[1]);
      const double h_ring = t.averages_over_phi() ? sampler.spacing_at(coords::to_cartesian(cs, {x[0], x[1], 0.0})) : h;
      const int nphi = phi_param > 0 ? phi_param : std::clamp(static_cast<int>(std::ceil(2 * std::numbers::pi * ring / h_ring)), 8, 4096);
      const CellSample c = sample_cell(sampler, t, *b, i, j, k, per_direction, nphi);
      max_phi = std::max(max_phi, c.samples);
      ++cells;
      empty += c.hits == 0;
      partial += c.hits > 0 && c.hits < c.samples;
      imp.D(i, j, k) = c.cons[0];
      for (int a = 0; a < 3; ++a) imp.S(a, i, j, k) = c.cons[1 + a];
      imp.tau(i, j, k) = c.cons[4];
      imp.DYe(i, j, k) = c.cons[5];
      mass += c.cons[0] * b->cell_volume(i, j, k);
      sm.rho(i, j, k) = c.hits ? c.rho : 0.0;
      sm.gamma13(i, j, k) = c.hits ? c.gamma13 : 0.0;
      sm.alpha(i, j, k) = c.hits ? c.alp : 0.0;
      sm.covered(i, j, k) = static_cast<double>(c.hits) / c.samples;
      // Primitives and metric: the first guess; XCFC re-solves the metric from the conserved
      // variables and HydroBase recovers the primitives with it.
      prim.rho(i, j, k) = c.rho;
      double vel[3] = {c.vel[0], c.vel[1], c.vel[2]};
      cap_guess_velocity(cs, x, c.hits && c.gamma13 > 0 ? c.gamma13 : 1.0, vel);
      for (int a = 0; a < 3; ++a) prim.vel(a, i, j, k) = vel[a];
      prim.eps(i, j, k) = c.eps;
      prim.Ye(i, j, k) = c.cons[0] > 0 ? c.cons[5] / c.cons[0] : ye_default;
      prim.press(i, j, k) = 0.0, prim.temperature(i, j, k) = 0.0, prim.W(i, j, k) = 1.0, prim.cs2(i, j, k) = 0.0;
      metric.psi(i, j, k) = c.hits && c.gamma13 > 0 ? std::pow(c.gamma13, 0.25) : 1.0;
      metric.alpha(i, j, k) = c.hits && c.alp > 0 ? c.alp : 1.0;
      for (int a = 0; a < 3; ++a) metric.beta(a, i, j, k) = 0.0;
    });
  }
  double local[2] = {mass, static_cast<double>(max_phi)}, global[2];
  MPI_Allreduce(&local[0], &global[0], 1, MPI_DOUBLE, MPI_SUM, ctx.comm());
  MPI_Allreduce(&local[1], &global[1], 1, MPI_DOUBLE, MPI_MAX, ctx.comm());
  long long counts[3] = {cells, empty, partial}, all[3];
  MPI_Allreduce(counts, all, 3, MPI_LONG_LONG, MPI_SUM, ctx.comm());
  r.raw_rest_mass = global[0];
  r.max_phi_samples = static_cast<int>(global[1]);
  r.cells = all[0], r.cells_without_data = all[1], r.cells_partly_covered = all[2];
  r.normalisation = ctx.param<bool>("HandOff", "normalise_rest_mass") && r.raw_rest_mass > 0
                        ? r.source_grid.rest_mass / r.raw_rest_mass : 1.0;
  // One factor for all conserved variables keeps their ratios (velocities, specific energy).
  double sums[3] = {0, 0, 0}, total[3];
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HandOff::imported imp(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      for (int c = 0; c < vars::HandOff::imported::ncomp; ++c) imp(c, i, j, k) *= r.normalisation;
      const double V = b->cell_volume(i, j, k);
      sums[0] += V * imp.D(i, j, k);
      sums[2] += V * (imp.tau(i, j, k) + imp.D(i, j, k));
      if (b->coordinates == CoordinateSystem::cartesian) {
        const Point3 x = cell_point(*b, i, j, k);
        sums[1] += V * (x[0] * imp.S(1, i, j, k) - x[1] * imp.S(0, i, j, k));
      } else {
        sums[1] += V * imp.S(2, i, j, k);  // S_phi
      }
    });
  }
  MPI_Allreduce(sums, total, 3, MPI_DOUBLE, MPI_SUM, ctx.comm());
  r.imported.rest_mass = total[0], r.imported.angular_momentum = total[1], r.imported.energy = total[2];
  ctx.info("HandOff: " + std::to_string(r.cells) + " cells, " + std::to_string(r.cells_without_data) + " without data, " +
           std::to_string(r.cells_partly_covered) + " partly covered; up to " + std::to_string(r.max_phi_samples) +
           " samples per cell; rest mass of the interpolated D " + num(r.raw_rest_mass) + ", 3D rest mass on the grid " +
           num(r.source_grid.rest_mass) + ": conserved variables scaled by " + num(r.normalisation));
}

void import_conserved(Context& ctx) {
  double atmosphere = 0;
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HandOff::imported imp(ctx, *b);
    const vars::HydroBase::cons cons(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      if (!(imp.D(i, j, k) > 0)) {  // no matter in the data: the atmosphere HydroBase_InitialCons set
        atmosphere += cons.D(i, j, k) * b->cell_volume(i, j, k);
        return;
      }
      for (int c = 0; c < vars::HydroBase::cons::ncomp; ++c) cons(c, i, j, k) = imp(c, i, j, k);
    });
  }
  double total = 0;
  MPI_Allreduce(&atmosphere, &total, 1, MPI_DOUBLE, MPI_SUM, ctx.comm());
  state(ctx).report.atmosphere_initial_mass = total;
}

void magnetic_field(Context& ctx) {
  HandOffState& st = state(ctx);
  import_magnetic_field(ctx, st);
  auto& r = st.report;
  r.magnetic = st.source->has("Bt[0]") && !ctx.param<bool>("HandOff", "ignore_magnetic_field");
  const MagneticEnergy e = grid_magnetic_energy(ctx, false);
  r.imported.magnetic_energy = e.total, r.imported.magnetic_energy_toroidal = e.toroidal;
  // The net flux out of a cell against the largest sum of |face flux| of a cell: round-off when
  // the faces are circulations.
  const hydrobase::FieldGroups g = hydrobase::FieldGroups::of(ctx);
  double m[2] = {0, 0};  // max |net flux|, max sum |flux|
  for (Block* b : ctx.grid().local_blocks()) {
    const std::array<Field, 3> faces{b->field(g.bface[0], 0), b->field(g.bface[1], 0), b->field(g.bface[2], 0)};
    for_interior(*b, [&](int i, int j, int k) {
      double magnitude = 0;
      const double V = b->cell_volume(i, j, k);
      const double d = hydrobase::cell_divergence(*b, faces, i, j, k, &magnitude);
      m[0] = std::max(m[0], std::abs(d) * V), m[1] = std::max(m[1], magnitude * V);
    });
  }
  MPI_Allreduce(MPI_IN_PLACE, m, 2, MPI_DOUBLE, MPI_MAX, ctx.comm());
  const double div = m[1] > 0 ? m[0] / m[1] : 0.0;
  r.divB_relative_max = div;
  if (r.magnetic)
    ctx.info("HandOff: magnetic field imported: E_mag 3D on the grid " + num(r.source_grid.magnetic_energy) + " (toroidal " +
             num(r.source_grid.magnetic_energy_toroidal) + "), on the grid's faces " + num(e.total) + " (toroidal " +
             num(e.toroidal) + "); max |div B| / face fluxes " + num(div));
}

void magnetic_report(Context& ctx) {
  auto& r = state(ctx).report;
  const MagneticEnergy e = grid_magnetic_energy(ctx, true);
  r.after.magnetic_energy = e.total, r.after.magnetic_energy_toroidal = e.toroidal;
}

}  // namespace remnant::handoff
