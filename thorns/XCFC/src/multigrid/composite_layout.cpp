#include "composite_layout.hpp"

#include <stdexcept>
#include <string>

#include "composite_transfers.hpp"

namespace remnant::xcfc {
namespace {

long long key(const Tier& T, const Cell& c) {
  return c[0] / T.nb[0] + T.blocks[0] * (c[1] / T.nb[1] + T.blocks[1] * (c[2] / T.nb[2]));
}

GridShape patch_shape_of(const Tier& T, int t, const Cell& c) {
  GridShape s = T.shape;
  for (int d = 0; d < s.dimension; ++d) {
    s.n[d] = T.nb[d];
    s.lo[d] = T.shape.lo[d] + static_cast<double>(c[d]) * T.shape.dx[d];
    // On refined levels a periodic face's neighbour is across the wrap: an interface too (the
    // recipes wrap). The base level is one patch: it keeps its periodic faces.
    const bool wrap = t > 0 && s.boundary[d][0] == Boundary::periodic;
    if (c[d] > 0 || wrap) s.boundary[d][0] = Boundary::interface;
    if (c[d] + T.nb[d] < T.shape.n[d] || wrap) s.boundary[d][1] = Boundary::interface;
  }
  return s;
}

}  // namespace

int locate(const Tier& T, const Cell& I) {
  Cell c{};
  for (int d = 0; d < 3; ++d) c[d] = I[d] - I[d] % T.nb[d];
  const auto it = T.find.find(key(T, c));
  return it == T.find.end() ? -1 : it->second;
}

std::vector<Tier> build_tiers(const CompositeLayout& l, int nranks) {
  std::vector<Tier> tiers;
  const GridShape& b = l.base;
  const int L = l.finest();
  if (L > 0)
    for (int d = 0; d < b.dimension; ++d)
      if (l.patch_cells[d] < 2 || l.patch_cells[d] % 2 != 0 || b.n[d] % l.patch_cells[d] != 0)
        throw std::invalid_argument("CompositeMultigrid: patch cells must be even and divide the base cells in every used direction");
  tiers.resize(static_cast<std::size_t>(L) + 1);
  for (int t = 0; t <= L; ++t) {
    Tier& T = tiers[static_cast<std::size_t>(t)];
    T.shape = b;
    for (int d = 0; d < b.dimension; ++d) {
      T.shape.n[d] = b.n[d] << t;
      T.shape.dx[d] = b.dx[d] / (1 << t);
    }
    T.nb = t == 0 ? b.n : l.patch_cells;
    for (int d = 0; d < 3; ++d) {
      if (!b.used(d)) T.nb[d] = 1;
      T.blocks[d] = T.shape.n[d] / T.nb[d];
    }
    if (t == 0) T.corner.push_back({0, 0, 0});
    else
      for (const auto& c : l.patches[static_cast<std::size_t>(t - 1)]) T.corner.push_back({c[0], c[1], c[2]});
    for (std::size_t p = 0; p < T.corner.size(); ++p) {
      const Cell& c = T.corner[p];
      for (int d = 0; d < 3; ++d)
        if (c[d] % T.nb[d] != 0 || c[d] < 0 || c[d] + T.nb[d] > T.shape.n[d])
          throw std::invalid_argument("CompositeMultigrid: patch " + std::to_string(p) + " of level " + std::to_string(t) +
                                      " is not aligned with the patch size or leaves the domain");
      if (!T.find.emplace(key(T, c), static_cast<int>(p)).second)
        throw std::invalid_argument("CompositeMultigrid: level " + std::to_string(t) + " lists a patch twice");
      T.patches.emplace_back(patch_shape_of(T, t, c));
    }
    for (auto& P : T.patches) T.covered.emplace_back(P.cells(), 0);
    T.ubar.resize(T.patches.size());
    T.corr.resize(T.patches.size());
    T.scratch.resize(T.patches.size());
  }
  // Parents and covered cells.
  for (int t = 1; t <= L; ++t) {
    Tier &T = tiers[static_cast<std::size_t>(t)], &C = tiers[static_cast<std::size_t>(t - 1)];
    for (std::size_t p = 0; p < T.patches.size(); ++p) {
      Cell cc{};
      for (int d = 0; d < 3; ++d) cc[d] = b.used(d) ? T.corner[p][d] / 2 : 0;
      const int parent = locate(tiers[static_cast<std::size_t>(t - 1)], cc);
      if (parent < 0)
        throw std::invalid_argument("CompositeMultigrid: a patch of level " + std::to_string(t) + " is not nested in level " +
                                    std::to_string(t - 1));
      T.parent.push_back(parent);
      const Level& P = T.patches[p];
      for (int k = 0; k < P.shape.n[2]; ++k)
        for (int j = 0; j < P.shape.n[1]; ++j)
          for (int i = 0; i < P.shape.n[0]; ++i)
            C.covered[static_cast<std::size_t>(parent)][coarse_cell(T, C, p, i, j, k)] = 1;
      std::array<int, 3> wn{1, 1, 1};
      for (int d = 0; d < b.dimension; ++d) wn[d] = T.nb[d] / 2 + 2;
      T.window_n.push_back(wn);
      T.window_size.push_back(static_cast<std::size_t>(wn[0]) * wn[1] * wn[2]);
    }
  }
  // Line relaxation: 2D, and 3D cylindrical and spherical (3D Cartesian relaxes by points).
  if (b.dimension == 2 || (b.dimension == 3 && b.coordinates != CoordinateSystem::cartesian))
    for (int t = 1; t <= L; ++t) build_runs(tiers[static_cast<std::size_t>(t)]);
  for (int t = 1; t <= L; ++t) {
    Tier& T = tiers[static_cast<std::size_t>(t)];
    std::vector<std::vector<int>> singles;
    for (std::size_t p = 0; p < T.patches.size(); ++p) singles.push_back({static_cast<int>(p)});
    T.points = make_split(T, singles, nranks);
    for (int d = 0; d < 3; ++d) {
      std::vector<std::vector<int>> units;
      for (const auto& R : T.runs[static_cast<std::size_t>(d)]) units.push_back(R.patches);
      T.lines[static_cast<std::size_t>(d)] = make_split(T, units, nranks);
    }
  }
  return tiers;
}

}  // namespace remnant::xcfc
