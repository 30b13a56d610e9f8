// The distributed multigrid: manufactured problems solved with MPI_COMM_WORLD must give exactly the
// bits of the MPI_COMM_SELF solve (solution, residual history, V-cycle counts), while each rank
// relaxes only its share of the finest level's cells. Run on 2 ranks by the ctest XCFC.mpi2 (and on
// one rank by the plain test program). Both runs also compare the solution with the manufactured
// problem's closed form, so that the one-rank run checks more than the serial path against itself.
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "XCFC/multigrid/multigrid.hpp"
#include "XCFC/multigrid/composite_multigrid.hpp"
#include "manufactured.hpp"
#include "refined_layouts.hpp"
#include "same_bits.hpp"
#include "remnant/comm_counters.hpp"

namespace {

using namespace remnant;
using namespace remnant::xcfc;
using namespace remnant::xcfc::test;

struct Problem {
  ScalarEquation eq;
  std::vector<double> guess, exact;
  SolveSettings set;
};

// psi-type (nonlinear, Dirichlet, FMG start) or alpha psi-type (linear, Robin far field, warm start
// from 1), optionally with the m = 1 point term and odd parity of a vector component.
Problem make_problem(const GridShape& s, bool nonlinear, bool m1) {
  Problem p;
  // Axisymmetric grids need an axisymmetric bump for the closed form to solve their problem.
  const bool axisymmetric = s.coordinates != CoordinateSystem::cartesian && s.dimension < 3;
  const Bump bump{1.0, nonlinear ? 0.3 : -0.3, {0.5, axisymmetric ? 0.5 : 0.6, 0.7}, {0, 0, 0}};
  p.eq = manufactured_equation(s, bump, nonlinear, &p.exact);
  ScalarEquation& eq = p.eq;
  if (!nonlinear) {
    eq.dirichlet = nullptr;
    eq.far_value = 1.0;
  }
  if (m1) {
    eq.mode = AngularMode::axisymmetric_m1;
    for (auto& side : eq.parity) side = {-1, -1};
  }
  p.guess.assign(s.cells(), 1.0);
  p.set.tolerance = nonlinear ? 1e-10 : 1e-8;
  p.set.max_cycles = 40;
  p.set.full_multigrid = nonlinear;
  return p;
}

double max_error(const std::vector<double>& u, const std::vector<double>& exact) {
  double e = 0;
  for (std::size_t q = 0; q < u.size(); ++q) e = std::max(e, std::abs(u[q] - exact[q]));
  return e;
}

// max_err: bounds on max|u - exact| (psi-type, alpha-psi-type), about twice the measured errors
// (truncation; the alpha-psi type also the Robin far field of a bump that is not yet 1 + C/r there).
void check(const char* name, const GridShape& s, std::array<double, 2> max_err, bool m1 = false,
           MultigridStorage storage = MultigridStorage::replicated) {
  int nranks = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  Multigrid serial(s), parallel(s, MPI_COMM_WORLD, storage);
  if (nranks >= 2) EXPECT_GE(parallel.distributed_levels(), 1) << name << ": the finest level is not split";
  else EXPECT_EQ(parallel.distributed_levels(), 0) << name;
  for (const bool nonlinear : {true, false}) {
    const Problem p = make_problem(s, nonlinear, m1 && !nonlinear);
    std::vector<double> u1 = p.guess, uN = p.guess;
    const SolveStats a = serial.solve(p.eq, u1, p.set);
    const SolveStats b = parallel.solve(p.eq, uN, p.set);
    const char* kind = nonlinear ? "psi-type" : "alpha-psi-type";
    const double err = max_error(uN, p.exact);
    EXPECT_LT(err, max_err[nonlinear ? 0 : 1]) << name << " " << kind << ": off the closed-form solution";
    EXPECT_TRUE(a.converged) << name << " " << kind;
    EXPECT_GT(a.cycles, 1) << name << " " << kind;
    EXPECT_EQ(a.cycles, b.cycles) << name << " " << kind;
    EXPECT_TRUE(same_bits(u1, uN)) << name << " " << kind << ": solution differs from the one-rank solve";
    EXPECT_TRUE(same_bits(a.history, b.history)) << name << " " << kind << ": residual history differs";
    EXPECT_EQ(std::memcmp(&a.initial_residual, &b.initial_residual, sizeof(double)), 0) << name << " " << kind;
    EXPECT_EQ(std::memcmp(&a.scale, &b.scale, sizeof(double)), 0) << name << " " << kind;
    // The finest level's relaxation is a partition of the serial one: shares add up exactly, and
    // each rank's share is about 1/nranks.
    long long total = 0;
    MPI_Allreduce(&b.relaxed_cells, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(total, a.relaxed_cells) << name << " " << kind;
    const double share = double(b.relaxed_cells) / double(a.relaxed_cells);
    EXPECT_NEAR(share, 1.0 / nranks, 0.1) << name << " " << kind << ": this rank relaxed " << b.relaxed_cells << " of "
                                          << a.relaxed_cells << " fine cells";
    // 2D at the origin rank 0 also relaxes the shells' extra theta lines (8 passes per relaxation of
    // 2 sweeps): it takes fewer theta lines of the sweeps, so that the split is even (was 0.556).
    if (nranks == 2 && s.dimension == 2) EXPECT_NEAR(share, 0.5, 0.01) << name << " " << kind;
    // The rest of each rank's per-cell work is split as well: boundary ghosts (its slab or line
    // split only), line factors (the lines it relaxes), coarse equations (its coarse slab, the rest
    // gathered). The levels below the split are computed by every rank: the bounds on 2 ranks are
    // the measured shares (deterministic counts; 1.0 when every rank did all of it) plus a margin,
    // the ghosts' highest on 32 x 32 x 18 (8 of 18 planes, its coarse levels keep 9 planes).
    struct Share {
      const char* what;
      long long one, mine;
      double bound;  // measured: ghosts 0.50-0.83, factors 0.53, restriction 0.52-0.63
    };
    for (const Share& w : {Share{"ghosts filled", a.ghost_entries, b.ghost_entries, 0.85},
                           Share{"line cells factored", a.factored_cells, b.factored_cells, 0.6},
                           Share{"cells restricted", a.restricted_cells, b.restricted_cells, 0.65}}) {
      if (nranks == 1) EXPECT_EQ(w.one, w.mine) << name << " " << kind << ": " << w.what;
      else if (nranks == 2) EXPECT_LE(double(w.mine), w.bound * double(w.one)) << name << " " << kind << ": " << w.what << " by this rank";
    }
    EXPECT_GT(a.ghost_entries, 0) << name;
    EXPECT_GT(a.restricted_cells, 0) << name;
    if (!nonlinear && s.dimension == 2) EXPECT_GT(a.factored_cells, 0) << name;
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0)
      std::printf("%-28s %-15s per rank/one rank: ghosts %.3f, factored %.3f, restricted %.3f; stored bytes %lld (one rank %lld)\n",
                  name, kind, double(b.ghost_entries) / double(a.ghost_entries),
                  a.factored_cells ? double(b.factored_cells) / double(a.factored_cells) : 0.0,
                  double(b.restricted_cells) / double(a.restricted_cells), parallel.stored_bytes(), serial.stored_bytes());
    if (rank == 0)
      std::printf("%-28s %-15s V-cycles %2d  fine cells relaxed: one rank %lld, rank 0 of %d %lld (%.3f); max error %.2e\n",
                  name, kind, b.cycles, a.relaxed_cells, nranks, b.relaxed_cells, share, err);
  }
}

constexpr double pi = std::numbers::pi;
constexpr double kNoClosedForm = 1e300;
using B = Boundary;
using C = CoordinateSystem;

TEST(XCFCMultigridMPI, Cartesian3D) {
  check("cartesian 3D 32^3", make_shape(C::cartesian, 3, {32, 32, 32}, {0, 0, 0}, {3, 3, 3},
                                        {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}}),
        {1e-3, 1.5e-2});  // measured 4.5e-4, 7.1e-3
  // 18 planes: the coarsest split level (9 planes) is cut 4 + 5, the next level semi-coarsens.
  check("cartesian 3D 32x32x18", make_shape(C::cartesian, 3, {32, 32, 18}, {-2, -2, 0}, {2, 2, 3},
                                            {{{B::outer, B::outer}, {B::outer, B::outer}, {B::reflect, B::outer}}}),
        {2e-3, 0.1});  // measured 9.9e-4, 4.9e-2 (the Robin condition 2 from a bump of width 1.2)
}

// Distributed storage (issue 21, goal 5): each rank stores only its slabs of the split levels, the
// level below them agglomerated; the same bits as one rank, the same split of the work.
TEST(XCFCMultigridMPI, Cartesian3DDistributedStorage) {
  const auto D = MultigridStorage::distributed;
  check("distributed 3D 32^3", make_shape(C::cartesian, 3, {32, 32, 32}, {0, 0, 0}, {3, 3, 3},
                                          {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}}),
        {1e-3, 1.5e-2}, false, D);
  check("distributed 3D 32x32x18", make_shape(C::cartesian, 3, {32, 32, 18}, {-2, -2, 0}, {2, 2, 3},
                                              {{{B::outer, B::outer}, {B::outer, B::outer}, {B::reflect, B::outer}}}),
        {2e-3, 0.1}, false, D);
  // 40 planes: the coarsest split level has 20, cut on even planes (the level below has 10).
  check("distributed 3D 24x24x40", make_shape(C::cartesian, 3, {24, 24, 40}, {0, 0, -3}, {3, 3, 3},
                                              {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::outer, B::outer}}}),
        {2e-3, 0.1}, false, D);
}

// Memory per rank: with distributed storage the levels' arrays on each of N ranks are about 1/N of
// one rank's (the slabs plus halo planes and the small agglomerated levels); replicated storage
// keeps them whole on every rank (ratio >= 1), which this test rejects on 2 ranks.
TEST(XCFCMultigridMPI, DistributedStorageBytesPerRank) {
  int nranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &nranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const GridShape s = make_shape(C::cartesian, 3, {32, 32, 32}, {0, 0, 0}, {3, 3, 3},
                                 {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}});
  Multigrid serial(s), replicated(s, MPI_COMM_WORLD), distributed(s, MPI_COMM_WORLD, MultigridStorage::distributed);
  const Problem p = make_problem(s, true, false);
  for (Multigrid* m : {&serial, &replicated, &distributed}) {
    std::vector<double> u = p.guess;
    ASSERT_TRUE(m->solve(p.eq, u, p.set).converged);  // every level's equation arrays allocated
  }
  const double one = double(serial.level_bytes()), rep = double(replicated.level_bytes()), dist = double(distributed.level_bytes());
  const double cells = double(s.cells());
  if (rank == 0)
    std::printf("32^3 multigrid levels, bytes per finest cell on rank 0 of %d: one rank %.1f, replicated %.1f, "
                "distributed %.1f (%.3f of one rank); with the finest level's cell frames %.1f, %.1f, %.1f\n",
                nranks, one / cells, rep / cells, dist / cells, dist / one, double(serial.stored_bytes()) / cells,
                double(replicated.stored_bytes()) / cells, double(distributed.stored_bytes()) / cells);
  if (nranks == 1) EXPECT_EQ(dist, one);
  // Measured on 2 ranks: 0.537 (the halo planes and the agglomerated 8^3 level below the split are
  // the excess over 1/2); replicated storage: 1.0. On 3 ranks the cuts fall on planes of the 8^3
  // level (2 + 3 + 3 of 8): up to 0.44.
  else EXPECT_LE(dist, (nranks == 2 ? 0.56 : 1.0 / nranks + 0.15) * one) << "levels' bytes on rank " << rank;
}

TEST(XCFCMultigridMPI, Spherical2D) {
  check("spherical 2D 128x64", make_shape(C::spherical, 2, {128, 64, 1}, {0, 0, 0}, {5, pi / 2, 2 * pi},
                                          {{{B::origin, B::outer}, {B::axis, B::reflect}, {B::outer, B::outer}}}),
        {4e-4, 4e-4});  // measured 1.8e-4, 1.9e-4
  // Both hemispheres: the origin's mirror cell lies at theta index n1-1-j, on the other rank.
  check("spherical 2D 96x48 (0..pi)", make_shape(C::spherical, 2, {96, 48, 1}, {0, 0, 0}, {5, pi, 2 * pi},
                                                 {{{B::origin, B::outer}, {B::axis, B::axis}, {B::outer, B::outer}}}),
        {6e-4, kNoClosedForm}, true);  // measured 3.0e-4; the m = 1 odd problem has no closed form here
}

}  // namespace

// Composite (refined) grids: patches relaxed by their owning rank and exchanged after each pass; the
// composite solve with MPI_COMM_WORLD must give the bits of the MPI_COMM_SELF one.
namespace {

// max_err as in check(), over the leaf cells.
void check_composite(const char* name, const GridShape& base, std::array<int, 3> patch, const std::vector<Box>& boxes,
                     std::array<double, 2> max_err) {
  const CompositeLayout lay = nested_layout(base, patch, boxes);
  ASSERT_EQ(lay.finest(), static_cast<int>(boxes.size())) << name;
  CompositeMultigrid serial(lay), parallel(lay, MPI_COMM_WORLD);
  for (const bool nonlinear : {true, false}) {
    const bool axisymmetric = base.coordinates != CoordinateSystem::cartesian && base.dimension < 3;
    const Bump bump{1.0, nonlinear ? 0.3 : -0.3, {0.5, axisymmetric ? 0.5 : 0.6, 0.7}, {0, 0, 0}};
    CompositeEquation eq;
    eq.s0 = serial.field();
    if (nonlinear) eq.s1 = serial.field(), eq.s7 = serial.field();
    else eq.k = serial.field();
    for (int n = 0; n < serial.parts(); ++n) {
      const GridShape& s = serial.part(n).shape;
      for_cells(s, [&](std::size_t q, int i, int j, int k) {
        const Point3 X = coords::to_cartesian(s.coordinates, s.point(i, j, k));
        const double u = bump(X), lap = bump.laplacian(X), w = std::exp(-0.3 * (X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
        if (nonlinear) {
          eq.s1.part[n][q] = -0.2 * w, eq.s7.part[n][q] = -0.05 * w;
          eq.s0.part[n][q] = lap + 0.2 * w / u + 0.05 * w / std::pow(u, 7);
        } else {
          eq.k.part[n][q] = 0.3 * w;
          eq.s0.part[n][q] = lap - 0.3 * w * u;
        }
      });
    }
    eq.boundary.far_value = 1.0;
    SolveSettings set;
    set.tolerance = 1e-9;
    set.full_multigrid = nonlinear;
    CompositeField a = serial.field(1.0), b = serial.field(1.0);
    comm::reset();
    const SolveStats sa = serial.solve(eq, a, set), sb = parallel.solve(eq, b, set);
    const comm::Tally tier_exchange = [&] {
      const auto it = comm::tallies().find(comm::Key{"mg_tier_exchange", static_cast<int>(boxes.size())});
      return it == comm::tallies().end() ? comm::Tally{} : it->second;
    }();
    EXPECT_TRUE(sa.converged) << name;
    EXPECT_EQ(sa.cycles, sb.cycles) << name;
    EXPECT_TRUE(same_bits(sa.history, sb.history)) << name;
    for (int n = 0; n < serial.parts(); ++n) EXPECT_TRUE(same_bits(a.part[n], b.part[n])) << name << " part " << n;
    double err = 0;
    for (int n = 0; n < serial.parts(); ++n) {
      const GridShape& s = serial.part(n).shape;
      for_cells(s, [&](std::size_t q, int i, int j, int k) {
        if (!serial.covered(n, q)) err = std::max(err, std::abs(b.part[n][q] - bump(coords::to_cartesian(s.coordinates, s.point(i, j, k)))));
      });
    }
    EXPECT_LT(err, max_err[nonlinear ? 0 : 1]) << name << ": off the closed-form solution";
    // The finest level's relaxation is split: the ranks' counts add up to the serial one.
    int rank = 0, nranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    long long mine = sb.relaxed_cells, total = 0;
    MPI_Allreduce(&mine, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(total, sa.relaxed_cells) << name;
    EXPECT_GT(sa.relaxed_cells, 0) << name;
    if (nranks == 2) EXPECT_NEAR(double(mine) / double(total), 0.5, 0.1) << name;
    // The patch ghosts are filled for this rank's units only: before each relaxation pass, and for
    // the residuals and restrictions (each rank restricts its own patches into the coarse covered
    // cells, the leaf residual is reduced from each rank's patches, the coarse right-hand side
    // fills only the parents of its own patches): measured 0.48-0.49 of one rank's on 2 ranks
    // (0.51-0.52 when every rank filled the whole coarser tier for the right-hand side, 0.65-0.66
    // when the residuals and transfers filled every patch).
    EXPECT_GT(sa.ghost_entries, 0) << name;
    if (nranks == 1) EXPECT_EQ(sa.ghost_entries, sb.ghost_entries) << name;
    if (nranks == 2) EXPECT_LE(double(sb.ghost_entries), 0.50 * double(sa.ghost_entries)) << name;
    if (rank == 0) std::printf("composite %-14s patch ghosts filled by rank 0 / one rank: %.3f\n", name, double(sb.ghost_entries) / double(sa.ghost_entries));
    // Point relaxation (3D Cartesian): after a red-black pass only that colour's cells are
    // gathered, so the finest tier's exchanges carry on average well under the other rank's half of
    // the tier (measured 0.278; 0.500 when every pass sent whole patches).
    if (nranks == 2 && base.dimension == 3 && base.coordinates == CoordinateSystem::cartesian) {
      long long tier_cells = 0;
      for (int n = 0; n < parallel.parts(); ++n)
        if (parallel.part(n).level == static_cast<int>(boxes.size())) tier_cells += static_cast<long long>(parallel.part(n).shape.cells());
      ASSERT_GT(tier_exchange.calls, 0) << name;
      const double per_call = double(tier_exchange.bytes) / double(tier_exchange.calls) / (8.0 * double(tier_cells));
      EXPECT_LT(per_call, 0.4) << name;
      if (rank == 0) std::printf("composite %-14s finest tier gathered per exchange by rank 0: %.3f of the tier\n", name, per_call);
    }
    if (rank == 0)
      std::printf("composite %-14s %s: %d parts, %d V-cycles, bits equal to one rank; finest level relaxed by rank 0: %.3f; "
                  "max error %.2e\n",
                  name, nonlinear ? "psi-type " : "alpsi-type", serial.parts(), sa.cycles, double(mine) / double(total), err);
  }
}

}  // namespace

TEST(XCFCMultigridMPI, CompositeSpherical2D) {
  using B = Boundary;
  const GridShape s = make_shape(CoordinateSystem::spherical, 2, {64, 16, 1}, {0, 0, 0}, {8, std::numbers::pi / 2, 2 * std::numbers::pi},
                                 {{{B::origin, B::outer}, {B::axis, B::reflect}, {B::outer, B::outer}}});
  check_composite("spherical 2D", s, {8, 8, 1}, {{{{0, 3}, {0, 2}, {0, 7}}}, {{{0, 1.5}, {0, 2}, {0, 7}}}},
                  {4e-4, 4e-4});  // measured 1.7e-4, 1.8e-4
}

TEST(XCFCMultigridMPI, CompositeCartesian3D) {
  using B = Boundary;
  const GridShape s = make_shape(CoordinateSystem::cartesian, 3, {16, 16, 16}, {0, 0, 0}, {4, 4, 4},
                                 {{{B::reflect, B::outer}, {B::reflect, B::outer}, {B::reflect, B::outer}}});
  check_composite("cartesian 3D", s, {4, 4, 4}, {{{{0, 2}, {0, 2}, {0, 2}}}, {{{0, 1}, {0, 1}, {0, 1}}}},
                  {1.5e-3, 1.5e-3});  // measured 6.4e-4, 6.8e-4
}
