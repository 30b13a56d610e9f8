#pragma once
// The vector potential's edge integrals on one block's frame (HandOff's magnetic import): the
// level's face coordinates, a block's cells in its level's global indices, and the table of edge
// integrals in HydroBase/vector_potential.hpp's indexing.
#include <array>
#include <cstdint>
#include <vector>

namespace remnant::handoff {

// Face coordinate of the level's global face index g in direction d: the Block's own expression.
struct LevelFaces {
  std::array<double, 3> domain_lo{}, dx{};
  double operator()(int d, std::int64_t g) const {
    const auto ud = static_cast<std::size_t>(d);
    return g == 0 ? domain_lo[ud] : domain_lo[ud] + static_cast<double>(g) * dx[ud];
  }
};

// The cells of one block (a local one, or a finer leaf next to it) in its level's global indices:
// the frame the edge tables are built on.
struct Frame {
  std::array<std::int64_t, 3> first{};  // global index of the first cell (0 in unused directions)
  std::array<int, 3> n{1, 1, 1};
  std::array<bool, 3> used{};
  LevelFaces F;            // the level's face coordinates
  std::array<std::int64_t, 3> cells{1, 1, 1};  // the level's cells per direction (1 where unused)
  double phi_hi = 0;         // 2D: the upper phi face
};

// Edge integrals of the potential, per direction, in vector_potential.hpp's indexing (cell along
// the edge, faces across it; one index in unused directions).
struct EdgeTable {
  std::array<std::array<int, 3>, 3> extent{};
  std::array<std::vector<double>, 3> value;
  explicit EdgeTable(const Frame& f) {
    for (int a = 0; a < 3; ++a) {
      for (int d = 0; d < 3; ++d) {
        const auto ud = static_cast<std::size_t>(d);
        extent[static_cast<std::size_t>(a)][ud] = d == a || !f.used[ud] ? f.n[ud] : f.n[ud] + 1;
      }
      const auto& e = extent[static_cast<std::size_t>(a)];
      value[static_cast<std::size_t>(a)].assign(static_cast<std::size_t>(e[0]) * static_cast<std::size_t>(e[1]) * static_cast<std::size_t>(e[2]), 0.0);
    }
  }
  double& operator()(int a, int i, int j, int k) {
    const auto& e = extent[static_cast<std::size_t>(a)];
    return value[static_cast<std::size_t>(a)][static_cast<std::size_t>(i + e[0] * (j + e[1] * k))];
  }
  bool contains(int a, const std::array<std::int64_t, 3>& p) const {
    for (std::size_t d = 0; d < 3; ++d)
      if (p[d] < 0 || p[d] >= extent[static_cast<std::size_t>(a)][d]) return false;
    return true;
  }
};

}  // namespace remnant::handoff
