// rho_max_point on the grid: the point value (include/Analysis/point_maximum.hpp) at the cell of
// the largest rho; block-local stencils, so no ghost zones are read.
#include <mpi.h>

#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "Analysis/collision_diagnostics.hpp"
#include "Analysis/point_maximum.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace remnant::analysis {
namespace {

struct Candidate {  // the largest cell average and the point value there; NaN points lose ties
  double raw, point;
  bool beats(const Candidate& o) const {
    if (raw != o.raw) return raw > o.raw;
    return !std::isnan(point) && (std::isnan(o.point) || point > o.point);
  }
};

}  // namespace

double rho_max_point(Context& ctx) {
  using Prim = vars::HydroBase::prim;
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string& coordinates = ctx.param<std::string>("Grid", "coordinates");
  const auto dim = static_cast<std::size_t>(ctx.param<std::int64_t>("Grid", "dimension"));
  const auto& xmin = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& blo = ctx.param<std::vector<std::string>>("Grid", "boundary_lower");
  const bool cylindrical = coordinates == "cylindrical";
  // Cartesian cells and cylindrical (R, z) cells: exact averages of 1, x, x^2 (spherical: not done).
  const bool supported = coordinates == "cartesian" || (cylindrical && dim == 2);
  Candidate mine{-std::numeric_limits<double>::infinity(), nan};
  for (Block* b : ctx.grid().local_blocks()) {
    const Prim prim(ctx, *b);
    std::array<int, 3> cell{0, 0, 0};
    double raw = prim.rho(0, 0, 0);
    for_interior(*b, [&](int i, int j, int k) {
      if (prim.rho(i, j, k) > raw) raw = prim.rho(i, j, k), cell = {i, j, k};
    });
    double point = nan;
    if (supported) {
      std::array<std::vector<double>, 3> faces;
      std::array<CellLine, 3> lines;
      for (std::size_t d = 0; d < dim; ++d) {
        const int di = static_cast<int>(d);
        for (int i = 0; i <= b->n[d]; ++i) faces[d].push_back(b->face_coordinate(di, i));
        // The lower neighbour of a cell on a reflection plane through 0 or on the axis is its mirror.
        const bool on_domain_edge = faces[d][0] == xmin[d];
        const bool symmetric = (blo[d] == "reflect" && xmin[d] == 0) || blo[d] == "axis";
        lines[d] = {cylindrical && d == 0 ? CellWeight::radial : CellWeight::uniform, faces[d], on_domain_edge && symmetric};
      }
      point = point_maximum_at(std::span<const CellLine>(lines.data(), dim), cell,
                               [&](int i, int j, int k) { return prim.rho(i, j, k); });
    }
    const Candidate c{raw, point};
    if (c.beats(mine)) mine = c;
  }
  // The winner by (raw, point): the same on every rank count.
  int nranks = 1;
  MPI_Comm comm = ctx.grid().comm();
  MPI_Comm_size(comm, &nranks);
  std::vector<double> all(2 * static_cast<std::size_t>(nranks));
  const double pair[2] = {mine.raw, mine.point};
  MPI_Allgather(pair, 2, MPI_DOUBLE, all.data(), 2, MPI_DOUBLE, comm);
  Candidate best{-std::numeric_limits<double>::infinity(), nan};
  for (std::size_t r = 0; r < static_cast<std::size_t>(nranks); ++r) {
    const Candidate c{all[2 * r], all[2 * r + 1]};
    if (c.beats(best)) best = c;
  }
  return best.point;
}

}  // namespace remnant::analysis
