#include "composite_tier.hpp"

#include <map>

namespace remnant::xcfc {

Tier::Split make_split(const Tier& T, std::vector<std::vector<int>> units, int nranks) {
  Tier::Split S;
  S.units = std::move(units);
  std::vector<std::size_t> cells(S.units.size(), 0);
  std::size_t total = 0;
  for (std::size_t u = 0; u < S.units.size(); ++u) {
    for (int p : S.units[u]) cells[u] += T.patches[static_cast<std::size_t>(p)].cells();
    total += cells[u];
  }
  S.first.assign(static_cast<std::size_t>(nranks) + 1, S.units.size());
  S.first[0] = 0;
  std::size_t u = 0, done = 0;
  for (int r = 1; r < nranks; ++r) {
    const std::size_t target = total * static_cast<std::size_t>(r) / static_cast<std::size_t>(nranks);
    while (u < S.units.size() && done + cells[u] / 2 < target) done += cells[u++];
    S.first[static_cast<std::size_t>(r)] = u;
  }
  S.counts.assign(static_cast<std::size_t>(nranks), 0);
  S.displs.assign(static_cast<std::size_t>(nranks), 0);
  for (int r = 0; r < nranks; ++r) {
    std::size_t n = 0;
    for (std::size_t v = S.first[static_cast<std::size_t>(r)]; v < S.first[static_cast<std::size_t>(r) + 1]; ++v) n += cells[v];
    S.counts[static_cast<std::size_t>(r)] = static_cast<int>(n);
    if (r > 0) S.displs[static_cast<std::size_t>(r)] = S.displs[static_cast<std::size_t>(r) - 1] + S.counts[static_cast<std::size_t>(r) - 1];
  }
  return S;
}

namespace {
// f(ghosted offset) for the interior cells of a patch in storage order; colour >= 0: only the cells
// with (i + j + k) % 2 == colour (those red_black_pass updates).
template <class F>
void for_exchanged_cells(const Level& P, int colour, F&& f) {
  if (colour < 0) {
    for_cells(P, full_range(P), [&](std::size_t, std::ptrdiff_t g) { f(static_cast<std::size_t>(g)); });
    return;
  }
  for (int k = 0; k < P.shape.n[2]; ++k)
    for (int j = 0; j < P.shape.n[1]; ++j) {
      const int i0 = (j + k + colour) & 1;
      auto g = static_cast<std::size_t>(P.at(i0, j, k));
      for (int i = i0; i < P.shape.n[0]; i += 2, g += 2) f(g);
    }
}
std::size_t exchanged_cells(const Level& P, int colour) {
  const std::size_t n = P.cells();
  if (colour < 0) return n;
  return n % 2 == 0 ? n / 2 : (colour == 0 ? (n + 1) / 2 : n / 2);  // a box starts at an even cell
}
}  // namespace

long long exchange_units(Tier& T, const Tier::Split& S, MPI_Comm comm, int rank, int nranks, int colour) {
  if (nranks == 1) return 0;
  // Buffers kept between calls (sized once, not zero-filled per pass), and only the partners'
  // units unpacked: a pass costs this rank its own cells to pack and the others' to unpack. After
  // a red-black pass of one colour only that colour's cells changed: only they are sent.
  const int* counts = S.counts.data();
  const int* displs = S.displs.data();
  if (colour >= 0) {
    auto& cc = S.colour_counts[static_cast<std::size_t>(colour & 1)];
    auto& cd = S.colour_displs[static_cast<std::size_t>(colour & 1)];
    if (cc.empty()) {  // once per split and colour
      cc.assign(static_cast<std::size_t>(nranks), 0);
      cd.assign(static_cast<std::size_t>(nranks), 0);
      for (int r = 0; r < nranks; ++r) {
        for (std::size_t u = S.first[static_cast<std::size_t>(r)]; u < S.first[static_cast<std::size_t>(r) + 1]; ++u)
          for (int p : S.units[u]) cc[static_cast<std::size_t>(r)] += static_cast<int>(exchanged_cells(T.patches[static_cast<std::size_t>(p)], colour));
        if (r > 0) cd[static_cast<std::size_t>(r)] = cd[static_cast<std::size_t>(r) - 1] + cc[static_cast<std::size_t>(r) - 1];
      }
    }
    counts = cc.data();
    displs = cd.data();
  }
  const auto total = static_cast<std::size_t>(displs[nranks - 1] + counts[nranks - 1]);
  if (T.exchange_buffer.size() < total) T.exchange_buffer.resize(total);
  double* all = T.exchange_buffer.data();
  const auto [u0, u1] = owned_units(S, rank);
  double* mine = all + displs[rank];
  for (std::size_t u = u0; u < u1; ++u)
    for (int p : S.units[u]) {
      const Level& P = T.patches[static_cast<std::size_t>(p)];
      for_exchanged_cells(P, colour, [&](std::size_t g) { *mine++ = P.u[g]; });
    }
  MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DOUBLE, all, counts, displs, MPI_DOUBLE, comm);
  for (int r = 0; r < nranks; ++r) {
    if (r == rank) continue;
    const double* at = all + displs[r];
    for (std::size_t u = S.first[static_cast<std::size_t>(r)]; u < S.first[static_cast<std::size_t>(r) + 1]; ++u)
      for (int p : S.units[u]) {
        Level& P = T.patches[static_cast<std::size_t>(p)];
        for_exchanged_cells(P, colour, [&](std::size_t g) { P.u[g] = *at++; });
      }
  }
  return static_cast<long long>(sizeof(double)) * static_cast<long long>(total - static_cast<std::size_t>(counts[rank]));
}

void build_runs(Tier& T) {
  for (int d = 0; d < T.shape.dimension; ++d) {
    const int e1 = (d + 1) % 3, e2 = (d + 2) % 3;
    std::map<std::array<long long, 3>, int> order;  // (transverse blocks, along block) -> patch (unused: 0)
    for (std::size_t p = 0; p < T.corner.size(); ++p)
      order[{T.corner[p][e1] / T.nb[e1], T.corner[p][e2] / T.nb[e2], T.corner[p][d] / T.nb[d]}] = static_cast<int>(p);
    std::vector<int> run;
    std::array<long long, 2> row{-1, -1};
    long long last = -2;
    auto close = [&] {
      if (run.empty()) return;
      GridShape s = T.patches[static_cast<std::size_t>(run.front())].shape;
      s.n[d] = T.nb[d] * static_cast<int>(run.size());
      s.boundary[d][1] = T.patches[static_cast<std::size_t>(run.back())].shape.boundary[d][1];
      // The whole ring of a periodic direction: its lines close on themselves.
      if (T.shape.boundary[d][0] == Boundary::periodic && static_cast<long long>(run.size()) == T.blocks[d])
        s.boundary[d] = {Boundary::periodic, Boundary::periodic};
      Tier::Run R{run, Level(s), {}};
      for (std::size_t m = 0; m < run.size(); ++m) {
        std::array<int, 3> o{0, 0, 0};
        o[d] = static_cast<int>(m) * T.nb[d];
        R.offset.push_back(o);
      }
      T.runs[static_cast<std::size_t>(d)].push_back(std::move(R));
      run.clear();
    };
    for (const auto& [k, p] : order) {
      if (k[0] != row[0] || k[1] != row[1] || k[2] != last + 1) close();
      row = {k[0], k[1]}, last = k[2];
      run.push_back(p);
    }
    close();
  }
  // Origin shells: the radial block layers from r = 0 on that hold every (theta, phi) block.
  const GridShape& ts = T.shape;
  if (ts.coordinates != CoordinateSystem::spherical || ts.boundary[0][0] != Boundary::origin ||
      ts.boundary[2][0] != Boundary::periodic)
    return;
  const long long per_layer = T.blocks[1] * T.blocks[2];
  std::map<long long, std::vector<int>> layers;
  for (std::size_t p = 0; p < T.corner.size(); ++p) layers[T.corner[p][0] / T.nb[0]].push_back(static_cast<int>(p));
  std::vector<int> patches;
  std::vector<std::array<int, 3>> offsets;
  long long complete = 0;
  for (const auto& [layer, ps] : layers) {
    if (layer != complete || static_cast<long long>(ps.size()) != per_layer) break;
    for (int p : ps) {
      patches.push_back(p);
      const Cell& c = T.corner[static_cast<std::size_t>(p)];
      offsets.push_back({static_cast<int>(c[0]), static_cast<int>(c[1]), static_cast<int>(c[2])});
    }
    ++complete;
  }
  if (complete == 0) return;
  GridShape s = ts;
  s.n[0] = static_cast<int>(complete) * T.nb[0];
  s.boundary[0][1] = s.n[0] < ts.n[0] ? Boundary::interface : ts.boundary[0][1];
  T.shell.push_back({std::move(patches), Level(s), std::move(offsets)});
}

}  // namespace remnant::xcfc
