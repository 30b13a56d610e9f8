// X^i and A^ij between solves (XCFC::update_every): from the vector potentials the warm start
// holds (extrapolated in time from the last two solves), without a V-cycle. A full vector solve
// with no cycles would also set up both equations and their residuals, which cost about half the
// X solve of a step on the 2D migration grid.
#include "XCFC/xcfc_system.hpp"

namespace remnant::xcfc {

void XcfcSolver::vector_potential_from_warm_start(XcfcState& st) {
  const VectorField B_up = to_coordinate_components(mg_, st.X_potentials.B);
  // X^i = B^i - f^ii d_i chi / 4 (centred differences), as solve_vector_poisson ends.
  const CompositeField gchi = mg_.with_ghosts(chi_equation(), st.X_potentials.chi);
  st.X = B_up;
  for (int n = 0; n < mg_.parts(); ++n) {
    const PartGeometry& g = mg_.part(n);
    const auto& stride = g.strides;
    const auto& gc = gchi.part[n];
    for_part_cells(g, [&](std::size_t q, std::size_t p, int, int, int) {
      const Point3& f = g.frames().f[p];
      for (int d = 0; d < g.shape.dimension; ++d)
        st.X[d].part[n][q] -= 0.25 * (gc[p + stride[d]] - gc[p - stride[d]]) / (2 * g.shape.dx[d] * f[d]);
    });
  }
  compute_A(st);
}

}  // namespace remnant::xcfc
