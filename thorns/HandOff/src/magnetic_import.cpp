// HandOff_MagneticField: the 3D data's field on the grid's faces from a vector potential on its
// edges (see magnetic_import.hpp).
#include "magnetic_import.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/vector_potential.hpp"
#include "edge_table.hpp"
#include "face_flux.hpp"
#include "magnetic_source.hpp"
#include "potential_edges.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/vars/HandOff.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::handoff {
namespace {

// Zero-length edges integrate to 0 (as HydroBase/vector_potential.hpp's): along phi on an axis
// (R = 0, theta = 0 or pi), and along theta and phi at the origin.
bool zero_length_edge(const Block& b, int a, const int (&idx)[3]) {
  if (b.coordinates == CoordinateSystem::cylindrical) return a == 2 && b.face_coordinate(0, idx[0]) == 0.0;
  if (b.coordinates != CoordinateSystem::spherical) return false;
  if (a != 0 && b.face_coordinate(0, idx[0]) == 0.0) return true;
  const double theta = b.face_coordinate(1, idx[1]);
  return a == 2 && (theta == 0.0 || std::abs(theta - std::numbers::pi) < 1e-12);
}

// Every interior face of b (block-boundary faces included) gets the circulation of the table's
// edge integrals around it divided by its area (HydroBase's EdgeIntegrals::face_flux: the order
// (R, z, phi) is left-handed, so cylindrical circulations take a minus sign; in an unused direction
// the "upper" edge is the same stored edge).
void set_faces_from_table(const Block& b, EdgeTable& t, const std::array<Field, 3>& faces) {
  const double orientation = b.coordinates == CoordinateSystem::cylindrical ? -1.0 : 1.0;
  std::array<bool, 3> used{};
  for (int d = 0; d < 3; ++d) used[static_cast<std::size_t>(d)] = direction_used(b, d);
  auto edge = [&](int a, int i, int j, int k) {
    const int idx[3] = {i, j, k};
    return zero_length_edge(b, a, idx) ? 0.0 : t(a, i, j, k);
  };
  for (int d = 0; d < 3; ++d) {
    const Field& F = faces[static_cast<std::size_t>(d)];
    const int a = (d + 1) % 3, c = (d + 2) % 3;
    int top[3];
    for (int e = 0; e < 3; ++e) top[e] = b.n[static_cast<std::size_t>(e)] + (e == d && used[static_cast<std::size_t>(d)] ? 1 : 0);
    for (int k = 0; k < top[2]; ++k)
      for (int j = 0; j < top[1]; ++j)
        for (int i = 0; i < top[0]; ++i) {
          int pa[3] = {i, j, k}, pc[3] = {i, j, k};
          if (used[static_cast<std::size_t>(a)]) pa[a] += 1;
          if (used[static_cast<std::size_t>(c)]) pc[c] += 1;
          const double circulation = (edge(a, i, j, k) - edge(a, pc[0], pc[1], pc[2])) + (edge(c, pa[0], pa[1], pa[2]) - edge(c, i, j, k));
          const double area = b.face_area(d, i, j, k);
          F(i, j, k) = area > 0.0 ? orientation * circulation / area : 0.0;
        }
  }
}

// 2D: B^phi, the phi-averaged field averaged over each phi face (phi is unused: no divergence).
void toroidal_faces(const Block& b, const FluxQuadrature& q, const std::array<Field, 3>& faces) {
  const double phi_lo = b.face_coordinate(2, 0);
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) {
      const Point3 lo{b.face_coordinate(0, i), b.face_coordinate(1, j), 0}, hi{b.face_coordinate(0, i + 1), b.face_coordinate(1, j + 1), 0};
      const double area = b.face_area(2, i, j, 0);
      faces[2](i, j, 0) = area > 0 ? q.flux(2, phi_lo, lo, hi) / area : 0.0;
    }
}

}  // namespace

void import_magnetic_field(Context& ctx, const HandOffState& st) {
  const hydrobase::FieldGroups groups = hydrobase::FieldGroups::of(ctx);
  const TargetDomain& t = st.target;
  const bool data = st.source->has("Bt[0]") && !ctx.param<bool>("HandOff", "ignore_magnetic_field");
  const auto xmin = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto xmax = ctx.param<std::vector<double>>("Grid", "xmax");
  const double closure = ctx.param<double>("HandOff", "flux_closure_tolerance");
  if (data && t.averages_over_phi() && xmin[t.coordinates == CoordinateSystem::cylindrical ? 0 : 1] != 0.0)
    throw RunError("HandOff: the data's magnetic field is imported through the poloidal flux function from the axis: "
                   "the 2D grid must start at the axis (Grid::xmin = " + std::to_string(xmin[0]) + ", " + std::to_string(xmin[1]) + ")");
  std::unique_ptr<FluxQuadrature> q;
  std::unique_ptr<EdgeBuilder> builder;
  std::vector<BlockKey> leaves;
  if (data) {
    q = std::make_unique<FluxQuadrature>(*st.source, t.coordinates, t.averages_over_phi(),
                                         static_cast<int>(ctx.param<std::int64_t>("HandOff", "phi_samples")));
    builder = std::make_unique<EdgeBuilder>(EdgeBuilder{*q, t.coordinates, t.averages_over_phi(), closure});
    for (std::size_t d = 0; d < 3; ++d) builder->xmin[d] = xmin[d], builder->xmax[d] = xmax[d];
    const auto lower = ctx.param<std::vector<std::string>>("Grid", "boundary_lower");
    for (std::size_t d = 0; d < 3; ++d) builder->periodic[d] = d < lower.size() && lower[d] == "periodic";
    leaves = ctx.grid().all_blocks();
  }
  for (Block* b : ctx.grid().local_blocks()) {
    const std::array<Field, 3> faces{b->field(groups.bface[0], 0), b->field(groups.bface[1], 0), b->field(groups.bface[2], 0)};
    if (!data) {
      for (int g : groups.bface) std::fill(b->data(g), b->data(g) + b->size(g), 0.0);
    } else {
      const Frame fb = builder->frame(*b, BlockKey{b->level, b->index});
      EdgeTable edges = builder->edges(fb);
      match_finer_leaves(*b, fb, *builder, leaves, edges);
      set_faces_from_table(*b, edges, faces);
      if (t.averages_over_phi()) toroidal_faces(*b, *q, faces);
    }
    hydrobase::cell_centred_field(groups, *b);
  }
}

MagneticEnergy grid_magnetic_energy(Context& ctx, bool solved_psi) {
  const hydrobase::FieldGroups groups = hydrobase::FieldGroups::of(ctx);
  double sums[2] = {0, 0};
  for (Block* b : ctx.grid().local_blocks()) {
    const std::array<Field, 3> faces{b->field(groups.bface[0], 0), b->field(groups.bface[1], 0), b->field(groups.bface[2], 0)};
    const vars::Spacetime::metric metric(ctx, *b);
    const vars::HandOff::source_at_cells sm(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      // psi^6 B^2 = |v|^2 / psi^2 with v the orthonormal components of psi^6 B (Analysis).
      const double psi2 = solved_psi ? metric.psi(i, j, k) * metric.psi(i, j, k)
                                     : (sm.gamma13(i, j, k) > 0 ? std::sqrt(sm.gamma13(i, j, k)) : 1.0);
      const Point3 v = hydrobase::cell_orthonormal_densitised_field(*b, faces, i, j, k);
      double tor2 = v[2] * v[2];
      if (b->coordinates == CoordinateSystem::cartesian) {
        const Point3 x = cell_point(*b, i, j, k);
        const double w2 = x[0] * x[0] + x[1] * x[1], bphi = -x[1] * v[0] + x[0] * v[1];
        tor2 = w2 > 0 ? bphi * bphi / w2 : 0.0;
      }
      const double V = b->cell_volume(i, j, k) / psi2;
      sums[0] += 0.5 * V * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      sums[1] += 0.5 * V * tor2;
    });
  }
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, ctx.comm());
  return {sums[0], sums[1]};
}

}  // namespace remnant::handoff
