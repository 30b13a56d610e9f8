// HandOff_Report: the hand-off in numbers, after the metric solve and the primitive recovery.
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "HandOff/handoff_state.hpp"
#include "import.hpp"
#include "profiles.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/vars/HandOff.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::handoff {
namespace {

std::string line(const char* key, double v, const char* what) {
  char b[512];
  std::snprintf(b, sizeof b, "%-28s %.15g   # %s", key, v, what);
  return b;
}

}  // namespace

void report(Context& ctx) {
  auto& r = ctx.service<HandOffState>("HandOff::state").report;
  // The grid's integrals now, and the densest cell (its centre values).
  double sums[4] = {0, 0, 0, 0}, rho_max = 0;
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::cons cons(ctx, *b);
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::HydroBase::mass_budget budget(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double V = b->cell_volume(i, j, k);
      sums[0] += V * cons.D(i, j, k);
      sums[2] += V * (cons.tau(i, j, k) + cons.D(i, j, k));
      sums[3] += V * budget.source(i, j, k);
      if (b->coordinates == CoordinateSystem::cartesian) {
        const Point3 x = cell_point(*b, i, j, k);
        sums[1] += V * (x[0] * cons.S(1, i, j, k) - x[1] * cons.S(0, i, j, k));
      } else {
        sums[1] += V * cons.S(2, i, j, k);
      }
      rho_max = std::max(rho_max, prim.rho(i, j, k));
    });
  }
  double total[4], rho_max_all = 0;
  MPI_Allreduce(sums, total, 4, MPI_DOUBLE, MPI_SUM, ctx.comm());
  MPI_Allreduce(&rho_max, &rho_max_all, 1, MPI_DOUBLE, MPI_MAX, ctx.comm());
  r.after.rest_mass = total[0], r.after.angular_momentum = total[1], r.after.energy = total[2];
  r.atmosphere_mass = total[3];
  // psi^4 vs gamma^(1/3) and alpha vs the 3D lapse in fully covered cells inside the matter
  // (rho > 1e-3 rho_max): largest and D-weighted mean relative differences; values at the densest cell.
  double mx[2] = {0, 0}, wsum[3] = {0, 0, 0};
  struct {
    double rho;
    int rank;
  } mine{0, ctx.rank()}, top{};
  double centre[4] = {0, 0, 0, 0};
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::HydroBase::cons cons(ctx, *b);
    const vars::Spacetime::metric metric(ctx, *b);
    const vars::HandOff::source_at_cells sm(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const double psi4 = std::pow(metric.psi(i, j, k), 4);
      if (prim.rho(i, j, k) > mine.rho) {
        mine.rho = prim.rho(i, j, k);
        centre[0] = psi4, centre[1] = sm.gamma13(i, j, k), centre[2] = metric.alpha(i, j, k), centre[3] = sm.alpha(i, j, k);
      }
      if (sm.covered(i, j, k) < 1 || !(prim.rho(i, j, k) > 1e-3 * rho_max_all)) return;
      const double dpsi = std::abs(psi4 / sm.gamma13(i, j, k) - 1), dal = std::abs(metric.alpha(i, j, k) / sm.alpha(i, j, k) - 1);
      const double w = cons.D(i, j, k) * b->cell_volume(i, j, k);
      mx[0] = std::max(mx[0], dpsi), mx[1] = std::max(mx[1], dal);
      wsum[0] += w * dpsi, wsum[1] += w * dal, wsum[2] += w;
    });
  }
  double mx_all[2], wsum_all[3];
  MPI_Allreduce(mx, mx_all, 2, MPI_DOUBLE, MPI_MAX, ctx.comm());
  MPI_Allreduce(wsum, wsum_all, 3, MPI_DOUBLE, MPI_SUM, ctx.comm());
  MPI_Allreduce(&mine, &top, 1, MPI_DOUBLE_INT, MPI_MAXLOC, ctx.comm());
  MPI_Bcast(centre, 4, MPI_DOUBLE, top.rank, ctx.comm());
  r.psi4_max_rel = mx_all[0], r.alpha_max_rel = mx_all[1];
  r.psi4_mean_rel = wsum_all[2] > 0 ? wsum_all[0] / wsum_all[2] : 0;
  r.alpha_mean_rel = wsum_all[2] > 0 ? wsum_all[1] / wsum_all[2] : 0;
  r.rho_c = top.rho, r.psi4_c = centre[0], r.gamma13_c = centre[1], r.alpha_c = centre[2], r.alpha3d_c = centre[3];
  r.after_done = true;

  std::vector<std::string> lines = {
      "# HandOff report: 3D data -> grid (integrals densitised by sqrt(gamma); J about the z axis; E = tau + D)",
      line("source_rest_mass", r.source_all.rest_mass, "3D: all data"),
      line("source_rest_mass_covered", r.source_covered.rest_mass, "3D: inside the grid unfolded by its mirrors"),
      line("source_matter_rest_mass", r.source_matter_rest_mass, "3D: points with rho > atmosphere_rho (all data)"),
      line("atmosphere_rho", r.atmosphere_rho, "the data's atmosphere: at or below it a point is not matter"),
      line("outside_fraction", r.outside_fraction, "3D rest mass of the matter outside the (unfolded) grid / all matter"),
      line("source_rest_mass_grid", r.source_grid.rest_mass, "3D: inside the grid itself (what the grid holds)"),
      line("source_angular_momentum_grid", r.source_grid.angular_momentum, "3D J inside the grid"),
      line("source_energy_grid", r.source_grid.energy, "3D E inside the grid"),
      line("interpolated_rest_mass", r.raw_rest_mass, "grid: the interpolated D"),
      line("normalisation", r.normalisation, "factor applied to the imported conserved variables"),
      line("imported_rest_mass", r.imported.rest_mass, "grid: imported D (= source_rest_mass_grid)"),
      line("imported_angular_momentum", r.imported.angular_momentum, "grid: imported S_phi"),
      line("imported_energy", r.imported.energy, "grid: imported tau + D"),
      line("rest_mass", r.after.rest_mass, "grid after the metric solve and the recovery"),
      line("angular_momentum", r.after.angular_momentum, "grid after"),
      line("energy", r.after.energy, "grid after"),
      line("atmosphere_rest_mass_empty", r.atmosphere_initial_mass, "the atmosphere's D in cells the data leave empty"),
      line("atmosphere_rest_mass", r.atmosphere_mass, "D added by the atmosphere and error policy since the import"),
      line("rest_mass_change", r.imported.rest_mass > 0 ? r.after.rest_mass / r.source_grid.rest_mass - 1 : 0, "after / 3D on the grid - 1"),
      line("angular_momentum_change", r.source_grid.angular_momentum != 0 ? r.after.angular_momentum / r.source_grid.angular_momentum - 1 : 0, "after / 3D on the grid - 1"),
      line("energy_change", r.source_grid.energy != 0 ? r.after.energy / r.source_grid.energy - 1 : 0, "after / 3D on the grid - 1"),
      line("cells_without_data", static_cast<double>(r.cells_without_data), "grid cells no 3D point reaches (atmosphere)"),
      line("rho_max", r.rho_c, "grid after"),
  };
  if (r.has_metric) {
    lines.push_back(line("psi4_vs_gamma13_max", r.psi4_max_rel, "max |psi^4 / gamma^(1/3) - 1| where rho > 1e-3 rho_max"));
    lines.push_back(line("psi4_vs_gamma13_mean", r.psi4_mean_rel, "D-weighted mean of the same"));
    lines.push_back(line("psi4_centre", r.psi4_c, "psi^4 at the densest cell"));
    lines.push_back(line("gamma13_centre", r.gamma13_c, "3D gamma^(1/3) there"));
  }
  if (r.has_lapse) {
    lines.push_back(line("alpha_vs_3d_max", r.alpha_max_rel, "max |alpha / alpha_3D - 1| where rho > 1e-3 rho_max"));
    lines.push_back(line("alpha_vs_3d_mean", r.alpha_mean_rel, "D-weighted mean of the same"));
    lines.push_back(line("alpha_centre", r.alpha_c, "alpha at the densest cell"));
    lines.push_back(line("alpha_3d_centre", r.alpha3d_c, "3D lapse there"));
  }
  if (r.magnetic) {
    const auto ratio = [](double a, double b) { return b != 0 ? a / b - 1 : 0.0; };
    lines.push_back(line("source_magnetic_energy", r.source_all.magnetic_energy, "3D: (1/2) sum sqrt(gamma) B^2 dV, all data"));
    lines.push_back(line("source_magnetic_energy_grid", r.source_grid.magnetic_energy, "3D inside the grid"));
    lines.push_back(line("source_magnetic_energy_tor_grid", r.source_grid.magnetic_energy_toroidal, "3D toroidal part (B_phi-hat^2) inside the grid"));
    lines.push_back(line("imported_magnetic_energy", r.imported.magnetic_energy, "grid: the imported faces with the 3D gamma^(1/3)"));
    lines.push_back(line("imported_magnetic_energy_tor", r.imported.magnetic_energy_toroidal, "grid: toroidal part"));
    lines.push_back(line("magnetic_energy", r.after.magnetic_energy, "grid with the solved psi"));
    lines.push_back(line("magnetic_energy_tor", r.after.magnetic_energy_toroidal, "grid with the solved psi: toroidal part"));
    lines.push_back(line("magnetic_energy_change", ratio(r.imported.magnetic_energy, r.source_grid.magnetic_energy), "imported / 3D on the grid - 1"));
    lines.push_back(line("divB_relative_max", r.divB_relative_max, "max over cells |net flux| / max over cells sum |face flux|"));
  }
  for (const auto& l : lines) ctx.info("HandOff: " + l);
  write_profiles(ctx, ctx.out_dir() + "/handoff_profiles.tsv");
  if (ctx.rank() == 0) {
    const std::string path = ctx.out_dir() + "/handoff_report.txt";
    std::ofstream out(path);
    for (const auto& l : lines) out << l << "\n";
    if (!out) throw RunError("HandOff: cannot write " + path);
  }
}

}  // namespace remnant::handoff
