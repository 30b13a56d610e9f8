#include "patches.hpp"

#include <algorithm>
#include <cmath>

#include "remnant/error.hpp"

namespace remnant::io {

Cut make_cut(const std::string& keyword, int dimension, const std::array<double, 3>& point) {
  Cut c;
  c.point = point;
  auto need = [&](int dims) {
    if (dimension < dims)
      throw RunError("IO::hdf5_output: '" + keyword + "' needs a grid of at least " + std::to_string(dims) +
                     " dimensions; this grid has " + std::to_string(dimension));
  };
  if (keyword == "volume") {
    c.name = "volume";
    for (int d = 0; d < dimension; ++d) c.axes.push_back(d);
  } else if (keyword.rfind("slice_", 0) == 0) {
    // Slices of a 2D grid would be the whole grid: they exist for 3D grids only.
    need(3);
    c.name = keyword.substr(6);
    for (char ch : c.name) c.axes.push_back(ch - 'x');
  } else if (keyword.rfind("line_", 0) == 0) {
    c.name = keyword.substr(5);
    c.axes.push_back(c.name[0] - 'x');
    need(c.axes[0] + 1);
  } else {
    throw RunError("IO::hdf5_output: unknown output '" + keyword + "'");
  }
  return c;
}

std::vector<Patch> extract_patches(std::span<Block* const> blocks, int dimension, const Cut& cut,
                                   const std::vector<VariableRef>& vars) {
  std::vector<Patch> out;
  for (const Block* bp : blocks) {
    Block& b = *const_cast<Block*>(bp);
    // Index range per grid direction: the whole interior along kept axes, one cell elsewhere.
    std::array<int, 3> first{0, 0, 0}, count{1, 1, 1};
    bool inside = true;
    Patch p;
    for (int d = 0; d < 3; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      const bool kept = std::find(cut.axes.begin(), cut.axes.end(), d) != cut.axes.end();
      if (kept) {
        count[ud] = b.n[ud];
      } else if (d < dimension) {
        const double rel = (cut.point[ud] - b.lo[ud]) / b.dx[ud];
        // Half-open blocks: a point on a shared face is cut from the upper block only.
        if (!(rel >= 0 && rel < b.n[ud])) inside = false;
        first[ud] = std::clamp(static_cast<int>(std::floor(rel)), 0, b.n[ud] - 1);
      }
      p.meta.centre3[ud] = b.x(d, first[ud]);
    }
    if (!inside) continue;
    p.meta.gid = b.gid;
    p.meta.level = b.level;
    p.meta.index = b.index;
    for (std::size_t a = 0; a < cut.axes.size(); ++a) {
      const auto d = static_cast<std::size_t>(cut.axes[a]);
      p.meta.n[a] = b.n[d];
      p.meta.lo[a] = b.lo[d];
      p.meta.dx[a] = b.dx[d];
    }
    for (const auto& v : vars) {
      const Field f = b.field(v.group, v.comp);
      std::vector<double> vals;
      vals.reserve(static_cast<std::size_t>(count[0]) * count[1] * count[2]);
      // Face groups: the mean of the lower and upper face of each cell along their direction.
      const std::ptrdiff_t up = v.average_direction < 0 ? 0 : v.average_direction == 0 ? 1 : v.average_direction == 1 ? f.sj : f.sk;
      for (int k = first[2]; k < first[2] + count[2]; ++k)
        for (int j = first[1]; j < first[1] + count[1]; ++j) {
          const double* row = &f(first[0], j, k);
          if (up == 0) {
            vals.insert(vals.end(), row, row + count[0]);
          } else {
            for (int i = 0; i < count[0]; ++i) vals.push_back(0.5 * (row[i] + row[i + up]));
          }
        }
      p.values.push_back(std::move(vals));
    }
    out.push_back(std::move(p));
  }
  std::sort(out.begin(), out.end(), [](const Patch& a, const Patch& b) { return a.meta.gid < b.meta.gid; });
  return out;
}

}  // namespace remnant::io
