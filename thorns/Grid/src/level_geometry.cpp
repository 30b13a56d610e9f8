#include "level_geometry.hpp"

#include "remnant/grid.hpp"

namespace remnant::grid {

LevelGeometry::LevelGeometry(const GridConfig& c, int max_level) {
  levels_.resize(static_cast<std::size_t>(max_level + 1));
  VariableRegistry none;
  for (int l = 0; l <= max_level; ++l) {
    // One block spanning the level with a wide ghost layer gives exactly the blocks' bits.
    std::array<int, 3> n{}, ng{};
    std::array<double, 3> dx{};
    for (std::size_t d = 0; d < 3; ++d) {
      const bool used = static_cast<int>(d) < c.dimension;
      const double dx0 = (c.xmax[d] - c.xmin[d]) / static_cast<double>(c.ncells[d]);
      dx[d] = used ? dx0 / static_cast<double>(std::int64_t{1} << l) : dx0;
      n[d] = used ? static_cast<int>(c.ncells[d] << l) : 1;
      ng[d] = used ? 2 * c.ghost_zones + 4 : 0;
    }
    Block b(0, l, {0, 0, 0}, n, ng, c.xmin, dx, none);
    b.set_geometry(c.coordinates, c.xmin);
    for (int d = 0; d < 3; ++d) {
      auto& dir = levels_[static_cast<std::size_t>(l)][static_cast<std::size_t>(d)];
      const auto ud = static_cast<std::size_t>(d);
      dir.dx = dx[ud];
      dir.first = -ng[ud];
      for (int i = -ng[ud]; i < n[ud] + ng[ud]; ++i) {
        dir.centroid.push_back(b.centroid(d, i));
        dir.weight.push_back(b.volume_weight(d, i));
      }
    }
  }
}

}  // namespace remnant::grid
