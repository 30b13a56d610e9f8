#include "reduction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "remnant/comm_counters.hpp"

namespace remnant::grid {

namespace {

// Accumulates op over the interior, row by row (contiguous in i).
template <class Op>
double accumulate_interior(const Block& b, const Field& f, double init, Op op) {
  double acc = init;
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j) {
      const double* row = f.origin + j * f.sj + k * f.sk;
      for (int i = 0; i < b.n[0]; ++i) acc = op(acc, row[i]);
    }
  return acc;
}

// Sum of op(u) * dV over the interior of a curvilinear block (dV varies per cell).
template <class Op>
double weighted_interior(const Block& b, const Field& f, Op op) {
  const double* w0 = b.volume_weights(0);
  const double* w1 = b.volume_weights(1);
  const double* w2 = b.volume_weights(2);
  double acc = 0;
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j) {
      const double* row = f.origin + j * f.sj + k * f.sk;
      const double w12 = w1[j] * w2[k];
      for (int i = 0; i < b.n[0]; ++i) acc += op(row[i]) * (w0[i] * w12);
    }
  return acc;
}

}  // namespace

BlockPartial block_partial(Block& b, int group, int comp, ReductionKind kind) {
  const Field f = b.field(group, comp);
  BlockPartial p;
  auto id = [](double u) { return u; };
  auto absolute = [](double u) { return std::abs(u); };
  auto square = [](double u) { return u * u; };
  if (b.coordinates != CoordinateSystem::cartesian) {
    p.volume = weighted_interior(b, f, [](double) { return 1.0; });
    switch (kind) {
      case ReductionKind::volume_integral: p.value = weighted_interior(b, f, id); return p;
      case ReductionKind::norm1: p.value = weighted_interior(b, f, absolute); return p;
      case ReductionKind::norm2: p.value = weighted_interior(b, f, square); return p;
      default: break;
    }
  }
  // dV is the same for every cell of a Cartesian block.
  const double dv = b.cell_volume();
  const double cells = static_cast<double>(b.n[0]) * b.n[1] * b.n[2];
  if (b.coordinates == CoordinateSystem::cartesian) p.volume = cells * dv;
  switch (kind) {
    case ReductionKind::minimum:
      p.value = accumulate_interior(b, f, std::numeric_limits<double>::infinity(),
                                    [](double a, double u) { return u < a || std::isnan(u) ? u : a; });
      break;
    case ReductionKind::maximum:
      p.value = accumulate_interior(b, f, -std::numeric_limits<double>::infinity(),
                                    [](double a, double u) { return u > a || std::isnan(u) ? u : a; });
      break;
    case ReductionKind::sum:
      p.value = accumulate_interior(b, f, 0.0, [](double a, double u) { return a + u; });
      break;
    case ReductionKind::volume_integral:
      p.value = dv * accumulate_interior(b, f, 0.0, [](double a, double u) { return a + u; });
      break;
    case ReductionKind::norm1:
      p.value = dv * accumulate_interior(b, f, 0.0, [](double a, double u) { return a + std::abs(u); });
      break;
    case ReductionKind::norm2:
      p.value = dv * accumulate_interior(b, f, 0.0, [](double a, double u) { return a + u * u; });
      break;
  }
  return p;
}

double combine(std::span<const BlockPartial> partials, ReductionKind kind) {
  double value = 0, volume = 0;
  if (kind == ReductionKind::minimum) value = std::numeric_limits<double>::infinity();
  if (kind == ReductionKind::maximum) value = -std::numeric_limits<double>::infinity();
  for (const BlockPartial& p : partials) {
    volume += p.volume;
    // NaN wins in min and max, so that a broken cell is never hidden by a reduction.
    if (kind == ReductionKind::minimum) value = p.value < value || std::isnan(p.value) ? p.value : value;
    else if (kind == ReductionKind::maximum) value = p.value > value || std::isnan(p.value) ? p.value : value;
    else value += p.value;
  }
  switch (kind) {
    case ReductionKind::norm1: return value / volume;
    case ReductionKind::norm2: return std::sqrt(value / volume);
    default: return value;
  }
}

double reduce_blocks(std::span<Block* const> blocks, const Forest& layout, int group, int comp,
                     ReductionKind kind, MPI_Comm comm) {
  std::vector<BlockPartial> mine;
  mine.reserve(blocks.size());
  for (Block* b : blocks) mine.push_back(block_partial(*b, group, comp, kind));

  // Each rank holds a contiguous gid range, so rank order is gid order.
  static_assert(sizeof(BlockPartial) == 2 * sizeof(double));
  const int nranks = layout.nranks();
  std::vector<int> counts(static_cast<std::size_t>(nranks)), displs(static_cast<std::size_t>(nranks));
  for (int r = 0; r < nranks; ++r) {
    counts[static_cast<std::size_t>(r)] = static_cast<int>(2 * layout.block_count(r));
    displs[static_cast<std::size_t>(r)] = static_cast<int>(2 * layout.first_gid(r));
  }
  std::vector<BlockPartial> all(static_cast<std::size_t>(layout.total_blocks()));
  MPI_Allgatherv(mine.data(), static_cast<int>(2 * mine.size()), MPI_DOUBLE, all.data(),
                 counts.data(), displs.data(), MPI_DOUBLE, comm);
  comm::count("grid_reduction", comm::Pattern::allgather, -1, 1,
              static_cast<long long>(sizeof(BlockPartial) * (all.size() - mine.size())));
  return combine(all, kind);
}

}  // namespace remnant::grid
