// X^i and A^ij between solves (XCFC::update_every), without a V-cycle. A vector solve with no
// cycles would also set up both equations and their residuals, and A^ij from X^i costs Christoffel
// symbols (sin, cos) per cell: once per solve interval here, a linear combination per update.
#include "update_between_solves.hpp"

#include "cadence.hpp"
#include "remnant/vars/XCFC.hpp"
#include "runtime.hpp"

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
      const Point3& f = g.frames().diagonal(p);
      for (int d = 0; d < g.shape.dimension; ++d)
        st.X[d].part[n][q] -= 0.25 * (gc[p + stride[d]] - gc[p - stride[d]]) / (2 * g.shape.dx[d] * f[d]);
    });
  }
  compute_A(st);
}

namespace {

using Potentials = vars::XCFC::potentials;
constexpr int kPair[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};

// A^ij of the X potentials stored in `group` (no extrapolation).
std::array<CompositeField, 6> A_of(const GridBridge& br, XcfcSolver& sv, int group) {
  XcfcState tmp;
  for (int a = 0; a < 3; ++a) tmp.X_potentials.B[a] = br.gather(group, Potentials::idx::XB + a);
  tmp.X_potentials.chi = br.gather(group, Potentials::idx::Xchi);
  sv.vector_potential_from_warm_start(tmp);
  return tmp.A;
}

}  // namespace

void load_update_A(Context& ctx, const GridBridge& br, XcfcSolver& sv, XcfcState& st) {
  Runtime& rt = runtime(ctx);
  Runtime::UpdateA& c = rt.update_A;
  if (c.solves != rt.solves) {
    c.last = A_of(br, sv, ctx.var("XCFC::potentials"));
    c.two = rt.solve_history >= 2 && rt.t_solve_last > rt.t_solve_before;
    if (c.two) c.before = A_of(br, sv, ctx.var("XCFC::potentials_before"));
    c.solves = rt.solves;
  }
  const std::optional<double> weight = c.two ? solve_extrapolation_weight(ctx) : std::nullopt;
  const double w = weight && *weight > 0 ? *weight : 0.0;
  CompositeMultigrid& mg = sv.multigrid();
  st.A = c.last;
  st.A2 = mg.field();
  for (int n = 0; n < mg.parts(); ++n) {
    const PartGeometry& g = mg.part(n);
    for_part_cells(g, [&](std::size_t q, std::size_t p, int, int, int) {
      const Point3& f = g.frames().diagonal(p);
      double A2 = 0;
      for (int a = 0; a < 3; ++a)
        for (int b = a; b < 3; ++b) {
          double& v = st.A[kPair[a][b]].part[n][q];
          if (w > 0) v += w * (v - c.before[kPair[a][b]].part[n][q]);
          A2 += (a == b ? 1.0 : 2.0) * f[a] * f[b] * v * v;
        }
      st.A2.part[n][q] = A2;
    });
  }
}

}  // namespace remnant::xcfc
