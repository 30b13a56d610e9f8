#pragma once
// The composite FAS multigrid's state (see include/XCFC/multigrid/composite_multigrid.hpp): the
// tiers of patches, the base solver and the ghost recipes. Split by concern:
// composite_multigrid.cpp (set-up, recipes, equation coefficients, the public interface),
// composite_cycle.cpp (ghost filling, relaxation, residuals, interpolation, the composite V-cycle).
#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "XCFC/multigrid/composite_multigrid.hpp"
#include "composite_layout.hpp"
#include "composite_recipes.hpp"
#include "composite_tier.hpp"
#include "composite_transfers.hpp"
#include "level.hpp"
#include "remnant/comm_counters.hpp"

namespace remnant::xcfc {

struct CompositeMultigrid::Impl {
  CompositeLayout layout;
  std::vector<Tier> tiers;
  Multigrid base;
  std::map<std::pair<double, bool>, Recipes> recipes;
  ScalarEquation base_eq;  // boundary data plus the base coefficients (fine ones restricted)
  std::vector<double> base_u, base_f;
  std::vector<std::pair<int, int>> part_of;  // (tier, patch) of each part
  std::vector<PartGeometry> geometry;
  CellShare share, ghosted_share;  // the pointwise work's split over interior and ghosted cells

  MPI_Comm comm;
  int rank = 0, nranks = 1;
  long long relaxed_finest = 0, relaxed_all = 0;  // cells relaxed by this rank in the current solve
  void count(int t, long long n) {
    comm::count_work("mg_tier_relax", t, n);
    relaxed_all += n;
    if (t + 1 == static_cast<int>(tiers.size())) relaxed_finest += n;
  }

  // The tiers of a layout, the base solver, the parts and their cell frames.
  Impl(const CompositeLayout& l, MPI_Comm c, MultigridStorage storage);
  std::size_t part_index(int t, std::size_t p) const {
    std::size_t i = p;
    for (int s = 0; s < t; ++s) i += tiers[static_cast<std::size_t>(s)].patches.size();
    return i;
  }
  bool refined() const { return tiers.size() > 1; }
  // 3D cylindrical and spherical: patches relax along runs in all three directions (cyclic around
  // whole phi rings) and the origin's complete shells as planes, as the base level does.
  bool curvilinear_3d() const { return layout.base.dimension == 3 && layout.base.coordinates != CoordinateSystem::cartesian; }

  Tier::Split split(const Tier& T, std::vector<std::vector<int>> units) const { return make_split(T, std::move(units), nranks); }
  std::pair<std::size_t, std::size_t> mine(const Tier::Split& S) const { return owned_units(S, rank); }
  void exchange(Tier& T, const Tier::Split& S, int colour = -1) {
    const long long bytes = exchange_units(T, S, comm, rank, nranks, colour);
    if (nranks > 1) comm::count("mg_tier_exchange", comm::Pattern::allgather, static_cast<int>(&T - tiers.data()), 1, bytes);
  }

  int locate(int t, const Cell& I) const { return xcfc::locate(tiers[static_cast<std::size_t>(t)], I); }

  std::size_t coarse_cell(int t, std::size_t p, int i, int j, int k) const {
    return xcfc::coarse_cell(tiers[static_cast<std::size_t>(t)], tiers[static_cast<std::size_t>(t - 1)], p, i, j, k);
  }
  bool used(int d) const { return layout.base.used(d); }

  // ---- recipes -----------------------------------------------------------------------------------
  // Appends the terms of the value at cell I of tier t (any cell within reach of the domain).
  void expand(int t, Cell I, double w, unsigned mask, double falloff, bool dirichlet, std::vector<Term>& out) const;

  const Recipes& recipes_for(const ScalarEquation& eq);

  // ---- equation set-up --------------------------------------------------------------------------
  static void add_mode_term(Level& L, AngularMode mode);

  template <class Fine, class Coarse>
  void restrict_tier(int t, Fine&& fine, Coarse&& coarse, std::size_t p0 = 0, std::size_t p1 = SIZE_MAX) const {
    xcfc::restrict_tier(tiers[static_cast<std::size_t>(t)], tiers[static_cast<std::size_t>(t - 1)], fine, coarse, p0, p1);
  }
  void restrict_point_values(int t, std::size_t p0 = 0, std::size_t p1 = SIZE_MAX) {
    xcfc::restrict_point_values(tiers[static_cast<std::size_t>(t)], tiers[static_cast<std::size_t>(t - 1)], p0, p1);
  }

  void set_equation(const CompositeEquation& eq);

  // ---- operations on a tier ---------------------------------------------------------------------
  // mine: only the patches of this rank's units of that split (the ghosts its relaxation reads; a
  // recipe reads interior values only, so the filled ghosts have the bits of a whole fill).
  void fill(int t, const ScalarEquation& eq, const std::array<double, 64>& par, const Tier::Split* mine = nullptr);
  // The parents (patches of tier t - 1) of this rank's patches of tier t >= 1, as a split whose units
  // (one patch each) are all this rank's: for fill.
  const Tier::Split& own_parents(int t);
  std::vector<Tier::Split> parents_of_own;  // per tier, built on first use
  // A split whose units are `patches`, all owned by this rank (fill of just these patches).
  Tier::Split only_these(const std::vector<int>& patches) const;
  long long ghosts_filled = 0;  // by this rank in the current solve (recipes evaluated)
  std::vector<std::vector<const double*>> fill_arrays;  // fill's u of each (tier, patch)

  // Relaxation of a tier's patches: red-black points (1D, 3D Cartesian) or zebra lines along runs of
  // patches in every direction (2D, 3D cylindrical and spherical; a row split into patches is one
  // line), ghosts refilled before each pass and held during it, both colours of a pass solved on
  // the run's copy. Each rank relaxes its units (patches or runs) and the results are exchanged: a
  // unit reads only ghosts and its own cells, so the bits do not depend on the number of ranks.
  // (Exact line solves of whole 1D patches with held ends would leave kinks at the patch ends that
  // the coarse correction removes slowly: points converge at 0.1-0.2 per cycle instead.)
  void relax(int t, const ScalarEquation& eq, const std::array<double, 64>& par, int sweeps);

  // Zebra lines along the runs of each direction, then (3D spherical) the origin's complete shells
  // as planes; every rank does the shells (they are few, and the tier is complete on every rank
  // after the line passes).
  void relax_lines(int t, const ScalarEquation& eq, const std::array<double, 64>& par, int sweeps);

  // This rank's patches of tier t >= 1: those of its units in the point split (single patches dealt
  // out in contiguous chunks, so a range of patch indices). All of them on one rank.
  std::pair<std::size_t, std::size_t> own_patches(int t) const { return mine(tiers[static_cast<std::size_t>(t)].points); }
  // Restriction split by fine patch: each rank restricts its own patches of tier t into their
  // footprints in tier t - 1 (the ghosts of its patches filled first), then the footprints' u (and
  // with `residual` their restricted residual r) go to every rank (MPI_Allgatherv), so tier t - 1 is
  // whole again: the same values, computed once instead of by every rank.
  void restrict_own_patches(int t, const ScalarEquation& eq, const std::array<double, 64>& par, bool residual);
  void exchange_footprints(int t, bool residual);
  // The values under the footprints in tier t - 1 of every patch of tier t, from the rank owning
  // the patch (point split) to every rank: values(parent, i, j, k, value) calls value(double&)
  // `per` times for each footprint cell (interior indices of the parent patch).
  template <class Values>
  void exchange_footprint_values(int t, int per, Values&& values) const;

  // Interpolates (quadratic, from the coarse window) `source` of tier t - 1 into the patches [p0, p1)
  // of tier t (all by default): added to u (a correction) or replacing it.
  template <class Field>
  void interpolate_up(int t, const ScalarEquation& eq, const std::array<double, 64>& par, bool correction, Field&& source,
                      std::size_t p0 = 0, std::size_t p1 = SIZE_MAX);

  // ---- the composite V-cycle --------------------------------------------------------------------
  void vcycle(const ScalarEquation& eq, const std::array<double, 64>& par, const SolveSettings& s);

  // Max |r| and max source scale over the leaf cells.
  // Over the leaf cells: max |r|, max of the source terms, and max of |r| less each cell's round-off
  // floor (256 ulp of its largest operator term: next to the spherical origin the coefficients are
  // large, and one global floor from the largest of them would stop the solve early elsewhere).
  struct LeafResidual {
    double max = 0, scale = 0, above_floor = 0;
  };
  LeafResidual leaf_residual(const ScalarEquation& eq, const std::array<double, 64>& par);
  // This rank's planes of the base level for leaf_residual (the whole level on one rank or in 1D).
  Range base_share(const Level& B) const;

  void load(const CompositeField& u, bool nonlinear);
  void store(CompositeField& u) const;
  ScalarEquation base_equation(const CompositeEquation& eq) const;

  // Covered cells hold the restriction of the finer solution (finest first).
  void restrict_solution(const ScalarEquation& eq, const std::array<double, 64>& par);
};

template <class Values>
void CompositeMultigrid::Impl::exchange_footprint_values(int t, int per, Values&& values) const {
  if (nranks == 1) return;
  const Tier& T = tiers[static_cast<std::size_t>(t)];
  const Tier& C = tiers[static_cast<std::size_t>(t - 1)];
  const Tier::Split& S = T.points;
  auto visit = [&](std::size_t u, auto&& value) {
    const Footprint fp = footprint(T, C, static_cast<std::size_t>(S.units[u][0]));
    for (int k = fp.lo[2]; k < fp.lo[2] + fp.n[2]; ++k)
      for (int j = fp.lo[1]; j < fp.lo[1] + fp.n[1]; ++j)
        for (int i = fp.lo[0]; i < fp.lo[0] + fp.n[0]; ++i) values(fp.parent, i, j, k, value);
  };
  const auto R = static_cast<std::size_t>(nranks);
  std::vector<int> counts(R, 0), displs(R, 0);
  for (std::size_t r = 0; r < R; ++r) {
    for (std::size_t u = S.first[r]; u < S.first[r + 1]; ++u) {
      const Footprint fp = footprint(T, C, static_cast<std::size_t>(S.units[u][0]));
      counts[r] += per * fp.n[0] * fp.n[1] * fp.n[2];
    }
    if (r > 0) displs[r] = displs[r - 1] + counts[r - 1];
  }
  std::vector<double> own, all(static_cast<std::size_t>(displs.back() + counts.back()));
  const auto [u0, u1] = mine(S);
  for (std::size_t u = u0; u < u1; ++u) visit(u, [&](double& x) { own.push_back(x); });
  MPI_Allgatherv(own.data(), static_cast<int>(own.size()), MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm);
  comm::count("mg_footprint_exchange", comm::Pattern::allgather, t, 1, static_cast<long long>(sizeof(double) * (all.size() - own.size())));
  for (std::size_t r = 0; r < R; ++r) {
    if (static_cast<int>(r) == rank) continue;
    auto at = static_cast<std::size_t>(displs[r]);
    for (std::size_t u = S.first[r]; u < S.first[r + 1]; ++u) visit(u, [&](double& x) { x = all[at++]; });
  }
}

// (A template: used by the cycle and by with_ghosts.)
template <class Field>
void CompositeMultigrid::Impl::interpolate_up(int t, const ScalarEquation& eq, const std::array<double, 64>& par, bool correction, Field&& source,
                                              std::size_t p0, std::size_t p1) {
  Tier& T = tiers[static_cast<std::size_t>(t)];
  const Recipes& R = recipes_for(eq);
  std::vector<double> win;
  for (std::size_t p = p0; p < std::min(p1, T.patches.size()); ++p) {
    Level& P = T.patches[p];
    win.assign(T.window_size[p], 0.0);
    for (const Recipe& r : R.window[static_cast<std::size_t>(t)][p]) win[r.target] = evaluate(R, r, par, eq, correction, source);
    const auto& wn = T.window_n[p];
    for (int k = 0; k < P.shape.n[2]; ++k)
      for (int j = 0; j < P.shape.n[1]; ++j)
        for (int i = 0; i < P.shape.n[0]; ++i) {
          const std::array<int, 3> f{i, j, k};
          std::array<std::array<double, 3>, 3> wq{};
          std::array<int, 3> c{}, lo{}, hi{};
          for (int d = 0; d < 3; ++d) {
            if (used(d)) c[d] = f[d] / 2 + 1, wq[d] = quadratic((f[d] & 1) ? 0.25 : -0.25), lo[d] = 0, hi[d] = 3;
            else c[d] = 0, wq[d] = {0, 1, 0}, lo[d] = 1, hi[d] = 2;
          }
          double v = 0;
          for (int z = lo[2]; z < hi[2]; ++z)
            for (int y = lo[1]; y < hi[1]; ++y)
              for (int x = lo[0]; x < hi[0]; ++x)
                v += wq[0][x] * wq[1][y] * wq[2][z] *
                     win[static_cast<std::size_t>((c[0] + x - 1) + wn[0] * ((c[1] + y - 1) + wn[1] * (c[2] + z - 1)))];
          double& u = P.u[static_cast<std::size_t>(P.at(i, j, k))];
          u = correction ? u + v : v;
        }
  }
}

}  // namespace remnant::xcfc
