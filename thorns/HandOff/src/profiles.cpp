#include "profiles.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "HandOff/target_domain.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/vars/HandOff.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::handoff {
namespace {
constexpr int kColumns = 11;  // line, coordinate along it, x, y, z, rho_3d, rho, gamma13_3d, psi4, alpha_3d, alpha
}

int write_profiles(Context& ctx, const std::string& path) {
  const TargetDomain t = TargetDomain::from_parameters(ctx.params());
  const int dim = t.dimension;
  std::vector<double> rows;
  for (Block* b : ctx.grid().local_blocks()) {
    const vars::HydroBase::prim prim(ctx, *b);
    const vars::Spacetime::metric metric(ctx, *b);
    const vars::HandOff::source_at_cells src(ctx, *b);
    auto first = [&](int d, int i) { return d >= dim || std::abs(b->face_coordinate(d, i) - t.lo[static_cast<std::size_t>(d)]) < 1e-9 * (1 + std::abs(t.lo[static_cast<std::size_t>(d)])); };
    for_interior(*b, [&](int i, int j, int k) {
      for (int l = 0; l < 2; ++l) {
        if (!(l == 0 ? first(1, j) && first(2, k) : first(0, i) && first(2, k))) continue;
        const Point3 x = cell_point(*b, i, j, k);
        Point3 xc = x;
        if (t.averages_over_phi()) xc[2] = 0;  // the (x, z) half-plane of the phi-average
        const Point3 X = coords::to_cartesian(b->coordinates, xc);
        const double v[kColumns] = {static_cast<double>(l), x[static_cast<std::size_t>(l)], X[0], X[1], X[2],
                                    src.rho(i, j, k), prim.rho(i, j, k), src.gamma13(i, j, k),
                                    std::pow(metric.psi(i, j, k), 4), src.alpha(i, j, k), metric.alpha(i, j, k)};
        rows.insert(rows.end(), v, v + kColumns);
      }
    });
  }
  int n = static_cast<int>(rows.size()), nranks = ctx.nranks();
  std::vector<int> counts(static_cast<std::size_t>(nranks)), displs(static_cast<std::size_t>(nranks), 0);
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, ctx.comm());
  for (int r = 1; r < nranks; ++r) displs[static_cast<std::size_t>(r)] = displs[static_cast<std::size_t>(r - 1)] + counts[static_cast<std::size_t>(r - 1)];
  std::vector<double> all(ctx.rank() == 0 ? static_cast<std::size_t>(displs.back() + counts.back()) : 0);
  MPI_Gatherv(rows.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, ctx.comm());
  const int nrows = static_cast<int>(all.size()) / kColumns;
  if (ctx.rank() != 0) return 0;
  std::vector<int> order(static_cast<std::size_t>(nrows));
  for (int r = 0; r < nrows; ++r) order[static_cast<std::size_t>(r)] = r;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double* A = &all[static_cast<std::size_t>(a * kColumns)];
    const double* B = &all[static_cast<std::size_t>(b * kColumns)];
    return A[0] != B[0] ? A[0] < B[0] : A[1] < B[1];
  });
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw RunError("HandOff: cannot write " + path);
  std::fprintf(f, "# line\tcoordinate\tx\ty\tz\trho_3d\trho\tgamma13_3d\tpsi4\talpha_3d\talpha\n");
  for (int r : order) {
    const double* v = &all[static_cast<std::size_t>(r * kColumns)];
    std::fprintf(f, "%d", static_cast<int>(v[0]));
    for (int c = 1; c < kColumns; ++c) std::fprintf(f, "\t%.10g", v[c]);
    std::fprintf(f, "\n");
  }
  if (std::fclose(f) != 0) throw RunError("HandOff: cannot write " + path);
  return nrows;
}

}  // namespace remnant::handoff
