// Carpet octant data with a magnetic field (issue 19): the Einstein Toolkit's HydroBase::Bvec is a
// pseudo-vector (tensorparity = -1; ReflectionSymmetry fills a mirror's ghosts with the component
// normal to the mirror even and the others odd). The octant_symmetric field of the magnetised TOV
// star (poloidal and toroidal, each its own pseudo-vector image across x = 0, y = 0 and z = 0)
// written as an octant (ReflectionSymmetry in the parameter dump) and as the whole domain, handed
// to the same 3D Cartesian grid around the whole star: the octant unfolded by the default gives
// the whole data's face fields; unfolded as vel (HandOff::magnetic_parity = vector) it does not.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "magnetised_tov.hpp"
#include "remnant/context.hpp"

namespace {

using namespace remnant::handoff::testing;

// Every interior face value of the local blocks, in block order.
std::vector<double> faces(remnant::Context& ctx) {
  std::vector<double> v;
  const int g[3] = {ctx.var("HydroBase::Bface1"), ctx.var("HydroBase::Bface2"), ctx.var("HydroBase::Bface3")};
  for (remnant::Block* b : ctx.grid().local_blocks())
    for (int d = 0; d < 3; ++d) {
      const remnant::Field F = b->field(g[d], 0);
      remnant::for_interior(*b, [&](int i, int j, int k) { v.push_back(F(i, j, k)); });
    }
  return v;
}

// max |a - b| / max |b| over all ranks.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m[2] = {0, 0};
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    m[0] = std::max(m[0], std::abs(a[i] - b[i]));
    m[1] = std::max(m[1], std::abs(b[i]));
  }
  MPI_Allreduce(MPI_IN_PLACE, m, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return m[1] > 0 ? m[0] / m[1] : 1.0;
}

TEST(HandOffMirrorField, OctantUnfoldedAsPseudoVector) {
  const MagnetisedTov whole(MagnetisedTovOptions{kAt, false, {false, false, false}, true});
  const MagnetisedTov octant(MagnetisedTovOptions{kAt, false, {true, true, true}, true});
  const std::vector<std::string> grid = {"Grid::coordinates=cartesian", "Grid::dimension=3", "Grid::xmin=[-12,-12,-12]",
                                         "Grid::xmax=[12,12,12]", "Grid::ncells=[24,24,24]", "Grid::block_size=[12,12,12]",
                                         "Grid::boundary_lower=[outflow,outflow,outflow]"};
  std::vector<double> fw, fa, fv;
  const Result w = hand_off(whole, grid, [&](remnant::Context& ctx, Result&) { fw = faces(ctx); });
  const Result a = hand_off(octant, grid, [&](remnant::Context& ctx, Result&) { fa = faces(ctx); });
  const Result v = hand_off(octant, with(grid, {"HandOff::magnetic_parity=vector"}), [&](remnant::Context& ctx, Result&) {
    fv = faces(ctx);
  });
  ASSERT_EQ(fa.size(), fw.size());
  const double da = relative_difference(fa, fw), dv = relative_difference(fv, fw);
  std::printf("octant (pseudo-vector field) vs whole data: max |dBface| / max |Bface| = %.2e unfolded as axial vector (default), "
              "%.2e as vel; E_mag whole %.8e, octant %.8e (%.1e), as vel %.8e; divB %.1e\n", da, dv,
              w.report.imported.magnetic_energy, a.report.imported.magnetic_energy,
              a.report.imported.magnetic_energy / w.report.imported.magnetic_energy - 1, v.report.imported.magnetic_energy,
              a.report.divB_relative_max);
  EXPECT_LE(da, 1e-12);
  EXPECT_NEAR(a.report.imported.magnetic_energy / w.report.imported.magnetic_energy, 1.0, 1e-12);
  EXPECT_GT(dv, 1e-2);
  EXPECT_LE(a.report.divB_relative_max, 1e-13);
}

}  // namespace
