#include "toroidal_potential.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::seed {

ToroidalPotentialTable::ToroidalPotentialTable(GridDriver& grid,
                                               const std::function<double(Block&, int, int, int)>& q) {
  MPI_Comm comm = grid.comm();
  const CoordinateSystem c = grid.coordinates();
  // Extent of the cell centres in (varpi, z) and the finest non-angular spacing.
  constexpr double inf = std::numeric_limits<double>::infinity();
  double w_max = 0.0, z_min = inf, z_max = -inf, h = inf;
  for (Block* b : grid.local_blocks()) {
    for (int d = 0; d < 3; ++d)
      if (direction_used(*b, d) && !coords::is_angle(c, d)) h = std::min(h, b->dx[static_cast<std::size_t>(d)]);
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 X = coords::to_cartesian(c, cell_point(*b, i, j, k));
      w_max = std::max(w_max, std::hypot(X[0], X[1]));
      z_min = std::min(z_min, X[2]);
      z_max = std::max(z_max, X[2]);
    });
  }
  double local[4] = {w_max, -z_min, z_max, -h}, global[4];
  MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_MAX, comm);
  h_ = -global[3];
  z0_ = -global[1] - h_;
  nw_ = static_cast<int>(std::ceil(global[0] / h_)) + 2;
  nz_ = static_cast<int>(std::ceil((global[2] - z0_) / h_)) + 2;
  // Volume-weighted means of q per bin.
  const auto bins = static_cast<std::size_t>(nw_) * static_cast<std::size_t>(nz_);
  std::vector<double> sums(2 * bins, 0.0);
  for (Block* b : grid.local_blocks())
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 X = coords::to_cartesian(c, cell_point(*b, i, j, k));
      const int m = std::clamp(static_cast<int>(std::hypot(X[0], X[1]) / h_), 0, nw_ - 1);
      const int l = std::clamp(static_cast<int>((X[2] - z0_) / h_), 0, nz_ - 1);
      const std::size_t p = static_cast<std::size_t>(l) * static_cast<std::size_t>(nw_) + static_cast<std::size_t>(m);
      const double v = b->cell_volume(i, j, k);
      sums[p] += v * q(*b, i, j, k);
      sums[bins + p] += v;
    });
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, comm);
  // Integrate -varpi q along varpi (midpoint rule per bin); empty bins take the mean of their
  // nearest filled neighbours in the row (0 beyond the last one).
  a_.assign(static_cast<std::size_t>(nw_ + 1) * static_cast<std::size_t>(nz_), 0.0);
  for (int l = 0; l < nz_; ++l) {
    const std::size_t row = static_cast<std::size_t>(l) * static_cast<std::size_t>(nw_);
    std::vector<double> qm(static_cast<std::size_t>(nw_), 0.0);
    std::vector<bool> filled(static_cast<std::size_t>(nw_), false);
    for (int m = 0; m < nw_; ++m) {
      const auto um = static_cast<std::size_t>(m);
      if (sums[bins + row + um] > 0) qm[um] = sums[row + um] / sums[bins + row + um], filled[um] = true;
    }
    for (int m = 0; m < nw_; ++m) {
      const auto um = static_cast<std::size_t>(m);
      if (filled[um]) continue;
      int lo = m - 1, hi = m + 1;
      while (lo >= 0 && !filled[static_cast<std::size_t>(lo)]) --lo;
      while (hi < nw_ && !filled[static_cast<std::size_t>(hi)]) ++hi;
      if (lo >= 0 && hi < nw_)
        qm[um] = qm[static_cast<std::size_t>(lo)] +
                 (qm[static_cast<std::size_t>(hi)] - qm[static_cast<std::size_t>(lo)]) * (m - lo) / static_cast<double>(hi - lo);
      else if (hi < nw_)
        qm[um] = qm[static_cast<std::size_t>(hi)];
    }
    const std::size_t arow = static_cast<std::size_t>(l) * static_cast<std::size_t>(nw_ + 1);
    for (int m = 0; m < nw_; ++m) {
      const double w = (m + 0.5) * h_;
      a_[arow + static_cast<std::size_t>(m + 1)] = a_[arow + static_cast<std::size_t>(m)] - w * qm[static_cast<std::size_t>(m)] * h_;
    }
  }
}

double ToroidalPotentialTable::a_z(double varpi, double z) const {
  const double s = std::clamp(varpi / h_, 0.0, static_cast<double>(nw_));
  const int m = std::min(static_cast<int>(s), nw_ - 1);
  const double tw = s - m;
  const double r = std::clamp((z - z0_) / h_ - 0.5, 0.0, static_cast<double>(nz_ - 1));
  const int l = std::min(static_cast<int>(r), std::max(nz_ - 2, 0));
  const double tz = nz_ > 1 ? r - l : 0.0;
  auto at = [&](int ll, int mm) { return a_[static_cast<std::size_t>(ll) * static_cast<std::size_t>(nw_ + 1) + static_cast<std::size_t>(mm)]; };
  const int l1 = std::min(l + 1, nz_ - 1);
  const double lo = (1 - tw) * at(l, m) + tw * at(l, m + 1), hi = (1 - tw) * at(l1, m) + tw * at(l1, m + 1);
  return (1 - tz) * lo + tz * hi;
}

hydrobase::CovariantPotential ToroidalPotentialTable::potential(CoordinateSystem c) const {
  return [this, c](const Point3& x) {
    const Point3 X = coords::to_cartesian(c, x);
    return coords::covector_from_cartesian(c, x, {0.0, 0.0, a_z(std::hypot(X[0], X[1]), X[2])});
  };
}

}  // namespace remnant::seed
