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

void exchange_units(Tier& T, const Tier::Split& S, MPI_Comm comm, int rank, int nranks) {
  if (nranks == 1) return;
  std::vector<double> mine_buf, all(static_cast<std::size_t>(S.displs.back() + S.counts.back()));
  const auto [u0, u1] = owned_units(S, rank);
  for (std::size_t u = u0; u < u1; ++u)
    for (int p : S.units[u]) {
      const Level& P = T.patches[static_cast<std::size_t>(p)];
      for_cells(P, full_range(P), [&](std::size_t, std::ptrdiff_t g) { mine_buf.push_back(P.u[static_cast<std::size_t>(g)]); });
    }
  MPI_Allgatherv(mine_buf.data(), static_cast<int>(mine_buf.size()), MPI_DOUBLE, all.data(), S.counts.data(), S.displs.data(),
                 MPI_DOUBLE, comm);
  std::size_t at = 0;
  for (const auto& unit : S.units)
    for (int p : unit) {
      Level& P = T.patches[static_cast<std::size_t>(p)];
      for_cells(P, full_range(P), [&](std::size_t, std::ptrdiff_t g) { P.u[static_cast<std::size_t>(g)] = all[at++]; });
    }
}

void build_runs(Tier& T) {
  for (int d = 0; d < 2; ++d) {
    const int e = 1 - d;
    std::map<std::pair<long long, long long>, int> order;  // (transverse, along) block -> patch
    for (std::size_t p = 0; p < T.corner.size(); ++p)
      order[{T.corner[p][e] / T.nb[e], T.corner[p][d] / T.nb[d]}] = static_cast<int>(p);
    std::vector<int> run;
    long long row = -1, last = -2;
    auto close = [&] {
      if (run.empty()) return;
      GridShape s = T.patches[static_cast<std::size_t>(run.front())].shape;
      s.n[d] = T.nb[d] * static_cast<int>(run.size());
      s.boundary[d][1] = T.patches[static_cast<std::size_t>(run.back())].shape.boundary[d][1];
      T.runs[static_cast<std::size_t>(d)].push_back({run, Level(s)});
      run.clear();
    };
    for (const auto& [k, p] : order) {
      if (k.first != row || k.second != last + 1) close();
      row = k.first, last = k.second;
      run.push_back(p);
    }
    close();
  }
}

}  // namespace remnant::xcfc
