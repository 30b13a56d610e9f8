#include "Analysis/magnetic_diagnostics.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "HydroBase/magnetic_units.hpp"
#include "HydroBase/vector_potential.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::analysis {

namespace {

// |psi^6 B| in the flat metric at a cell (the neighbourhood scale of divB_max).
double densitised_magnitude(const Block& b, const std::array<Field, 3>& faces, int i, int j, int k) {
  const Point3 v = hydrobase::cell_orthonormal_densitised_field(b, faces, i, j, k);
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

double densitised_field_max(const Block& b, const std::array<Field, 3>& faces) {
  double m = 0;
  for_interior(b, [&](int i, int j, int k) { m = std::max(m, densitised_magnitude(b, faces, i, j, k)); });
  return m;
}

MagneticBlockMaxima magnetic_block_pass(const Block& b, const std::array<Field, 3>& faces, Field psi,
                                        const std::array<Field, 3>& densities, double scale_floor) {
  MagneticBlockMaxima s;
  const CoordinateSystem c = b.coordinates;
  bool used[3];
  for (int d = 0; d < 3; ++d) used[d] = direction_used(b, d);
  for_interior(b, [&](int i, int j, int k) {
    const Point3 x = cell_point(b, i, j, k);
    const Point3 f = coords::metric_diagonal(c, x);
    // The cell's smallest width and the largest |B| around it.
    double h = std::numeric_limits<double>::infinity();
    double nb = std::max(scale_floor, densitised_magnitude(b, faces, i, j, k));
    for (int d = 0; d < 3; ++d) {
      if (!used[d]) continue;
      h = std::min(h, std::sqrt(f[static_cast<std::size_t>(d)]) * b.dx[static_cast<std::size_t>(d)]);
      const int o[3] = {d == 0, d == 1, d == 2};
      nb = std::max({nb, densitised_magnitude(b, faces, i - o[0], j - o[1], k - o[2]),
                     densitised_magnitude(b, faces, i + o[0], j + o[1], k + o[2])});
    }
    const double div = hydrobase::cell_divergence(b, faces, i, j, k);
    if (nb > 0 && std::isfinite(h)) s.div_scaled = std::max(s.div_scaled, std::abs(div) * h / nb);
    // Energies with the CFC measure psi^6 sqrt(f) d^3x; B^2 = gamma_ij B^i B^j = |v|^2 / psi^8 with v
    // the orthonormal components of psi^6 B in the flat metric.
    const double psi2 = psi(i, j, k) * psi(i, j, k), psi4 = psi2 * psi2, psi6 = psi4 * psi2, psi8 = psi4 * psi4;
    const Point3 v = hydrobase::cell_orthonormal_densitised_field(b, faces, i, j, k);
    const double B2 = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / psi8;
    double Btor2 = 0;
    if (c == CoordinateSystem::cartesian) {
      // Cylindrical split: B_phi-hat = (-y B^x + x B^y) / varpi.
      const double w2 = x[0] * x[0] + x[1] * x[1];
      if (w2 > 0) {
        const double bphi = -x[1] * v[0] + x[0] * v[1];
        Btor2 = bphi * bphi / w2 / psi8;
      }
    } else {
      Btor2 = v[2] * v[2] / psi8;
    }
    densities[0](i, j, k) = 0.5 * psi6 * B2;
    densities[1](i, j, k) = 0.5 * psi6 * std::max(B2 - Btor2, 0.0);
    densities[2](i, j, k) = 0.5 * psi6 * Btor2;
    s.B = std::max(s.B, std::sqrt(B2));
  });
  return s;
}

bool magnetic_run(const Context& ctx) {
  return ctx.params().find("HydroBase", "magnetic_field") &&
         ctx.param<std::string>("HydroBase", "magnetic_field") == "evolved";
}

MagneticDiagnostics magnetic_diagnostics(Context& ctx) {
  const int face[3] = {ctx.var("HydroBase::Bface1"), ctx.var("HydroBase::Bface2"), ctx.var("HydroBase::Bface3")};
  const int density = ctx.var("Analysis::magnetic_energy_density");
  for (int g : face) ctx.check_access(g);
  ctx.check_access(density);
  using Metric = vars::Spacetime::metric;
  double field_max = 0;
  for (Block* b : ctx.grid().local_blocks())
    field_max = std::max(field_max, densitised_field_max(*b, {b->field(face[0], 0), b->field(face[1], 0), b->field(face[2], 0)}));
  MPI_Allreduce(MPI_IN_PLACE, &field_max, 1, MPI_DOUBLE, MPI_MAX, ctx.grid().comm());
  double maxima[2] = {0, 0};  // divB scaled, B_max
  for (Block* b : ctx.grid().local_blocks()) {
    const std::array<Field, 3> F{b->field(face[0], 0), b->field(face[1], 0), b->field(face[2], 0)};
    const std::array<Field, 3> E{b->field(density, 0), b->field(density, 1), b->field(density, 2)};
    const MagneticBlockMaxima s = magnetic_block_pass(*b, F, Metric(ctx, *b).field(Metric::idx::psi), E, kDivBScaleFloor * field_max);
    maxima[0] = std::max(maxima[0], s.div_scaled);
    maxima[1] = std::max(maxima[1], s.B);
  }
  MPI_Allreduce(MPI_IN_PLACE, maxima, 2, MPI_DOUBLE, MPI_MAX, ctx.grid().comm());
  MagneticDiagnostics d;
  d.iteration = ctx.iteration();
  d.divB_max = maxima[0];
  d.B_max_gauss = hydrobase::gauss_from_code(maxima[1]);
  // The grid's volume integrals: the same bits on any rank count.
  d.E_mag = ctx.grid().reduce(density, 0, ReductionKind::volume_integral);
  d.E_mag_pol = ctx.grid().reduce(density, 1, ReductionKind::volume_integral);
  d.E_mag_tor = ctx.grid().reduce(density, 2, ReductionKind::volume_integral);
  return d;
}

}  // namespace remnant::analysis
