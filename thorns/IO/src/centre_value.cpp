#include "centre_value.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace remnant::io {

CellChoice nearest_cell(const Block& b, const std::array<double, 3>& point, int dimension) {
  CellChoice c;
  c.level = b.level;
  c.gid = b.gid;
  c.contains = 1;
  for (int d = 0; d < dimension; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    const double rel = (point[ud] - b.lo[ud]) / b.dx[ud];
    // Half-open [lo, hi) blocks so that a point on a shared face belongs to one block only.
    if (!(rel >= 0 && rel < b.n[ud])) c.contains = 0;
    int i = static_cast<int>(std::floor(rel));
    i = std::clamp(i, 0, b.n[ud] - 1);
    c.cell[ud] = i;
    const double diff = b.x(d, i) - point[ud];
    c.distance2 += diff * diff;
  }
  return c;
}

bool better(const CellChoice& a, const CellChoice& b) {
  if (a.contains != b.contains) return a.contains > b.contains;
  if (a.contains && a.level != b.level) return a.level > b.level;
  if (a.distance2 != b.distance2) return a.distance2 < b.distance2;
  return a.gid < b.gid;
}

double value_at_point(GridDriver& grid, int group, int comp, const std::array<double, 3>& point) {
  struct Candidate {
    double distance2, value;
    std::int64_t gid;
    int contains, level;
  };
  Candidate mine{std::numeric_limits<double>::infinity(), 0, std::numeric_limits<std::int64_t>::max(), 0, -1};
  CellChoice best;
  bool have = false;
  for (Block* b : grid.local_blocks()) {
    const CellChoice c = nearest_cell(*b, point, grid.dimension());
    if (!have || better(c, best)) {
      best = c;
      have = true;
      mine = {c.distance2, b->field(group, comp)(c.cell[0], c.cell[1], c.cell[2]), c.gid, c.contains, c.level};
    }
  }
  int nranks = 1;
  MPI_Comm_size(grid.comm(), &nranks);
  std::vector<Candidate> all(static_cast<std::size_t>(nranks));
  MPI_Allgather(&mine, sizeof mine, MPI_BYTE, all.data(), sizeof mine, MPI_BYTE, grid.comm());
  const Candidate* win = nullptr;
  for (const auto& c : all) {
    if (c.level < 0) continue;  // a rank without blocks
    if (!win) { win = &c; continue; }
    const CellChoice a{c.contains, c.level, c.distance2, c.gid, {}}, b{win->contains, win->level, win->distance2, win->gid, {}};
    if (better(a, b)) win = &c;
  }
  return win ? win->value : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace remnant::io
