#pragma once
// Cell-centred full-approximation-storage multigrid for one scalar equation in reference-metric form
//     Lap u = k u + s0 + s1 / u + s7 / u^7,       Lap u = (1/sqrt f) d_i (sqrt f f^ii d_i u),
// which covers the xCFC equations: psi (s1 = -2 pi E~, s7 = -A^2/8), alpha psi (k), and each
// Cartesian component of the vector Poisson problems (k from the angular mode, s0 the source).
// Finite volumes with exact cell volumes and face integrals of sqrt(f) f^dd: fluxes through the
// origin and the axis vanish, so regularity needs no special stencil. Red-black Gauss-Seidel with one
// local Newton step per cell, V-cycles on levels coarsened 2:1 per direction while the cell count is
// even (semi-coarsening once a direction is exhausted), full multigrid from the coarsest level,
// convergence on the L-infinity norm of the residual relative to the L-infinity norm of the sources.
// With a communicator of several ranks the cycles' work is split in slabs between the ranks
// (arrays complete on every rank, or with Storage::distributed only the own slabs of 3D levels; see
// README.md, "MPI and AMR"), bit-identical to one rank.
#include <mpi.h>

#include <functional>
#include <memory>
#include <vector>

#include "XCFC/multigrid/structured_grid.hpp"

namespace remnant::xcfc {

// Point term of a vector component written in Cartesian components under a symmetry:
// Lap V^A - m V^A / varpi^2 (axisymmetric m = 1 components x, y; varpi the cylindrical radius), or
// the radial component of a spherically symmetric field, Lap V - 2 V / r^2.
enum class AngularMode { none, axisymmetric_m1, spherical_l1 };

struct ScalarEquation {
  // Interior arrays on the finest level (empty: zero).
  std::vector<double> k, s0, s1, s7;
  AngularMode mode = AngularMode::none;
  Parities parity = kEven;
  // Outer faces: u -> far_value + C / r^falloff (Robin between the last cell and the ghost), or, when
  // set, Dirichlet values at the outer faces (manufactured solutions).
  double far_value = 0.0, falloff = 1.0;
  std::function<double(const Point3&)> dirichlet;
  bool nonlinear() const { return !s1.empty() || !s7.empty(); }
};

struct SolveSettings {
  double tolerance = 1e-6;  // on max|residual| / max|source terms|
  int max_cycles = 50;
  int pre_sweeps = 2, post_sweeps = 2, coarse_sweeps = 60;
  bool full_multigrid = false;  // FMG start instead of the warm start
  double scale_floor = 0.0;     // lower bound of the residual scale (see XcfcSolver)
  // 1D grids are one line: solve them by tridiagonal (Newton for nonlinear) line solves on the
  // finest level instead of V-cycles (exact for linear equations; each counts as one cycle).
  bool direct_1d = true;
};

struct SolveStats {
  int cycles = 0;
  double initial_residual = 0, residual = 0, scale = 0;  // max|r| before and after; max|sources|
  double factor = 0;         // geometric mean of the residual reduction per V-cycle
  std::vector<double> history;  // max|residual| after each V-cycle
  bool converged = false;
  // Cells relaxed by this rank (point updates plus cells of relaxed lines) on the finest level and
  // on all levels: the measure of how the work is split between ranks.
  long long relaxed_cells = 0, relaxed_cells_all = 0;
  // The rest of this rank's per-cell work on all levels: boundary ghosts filled, line cells
  // factored (Thomas factors of linear equations), fine cells restricted into the coarse equations.
  long long ghost_entries = 0, factored_cells = 0, restricted_cells = 0;
};

// Geometry of the finest level's cells in the ghosted layout (ghosted_index), computed once per
// grid: the Jacobian J[A][i] = dX^A / dx^i and the reference-metric diagonal f_ii at each cell's
// evaluation point. The vector transformations would otherwise call sin/cos per cell and solve.
// Cartesian grids have the same frame at every point: one entry each (issue 21, memory: 96 bytes
// per ghosted point otherwise).
struct CellFrames {
  std::vector<Matrix3> J;  // per ghosted point, or one for all
  std::vector<Point3> f;
  std::size_t points = 0;  // ghosted points
  const Matrix3& jacobian(std::size_t p) const { return J[J.size() == 1 ? 0 : p]; }
  const Point3& diagonal(std::size_t p) const { return f[f.size() == 1 ? 0 : p]; }
  // Frames at the `points` ghosted points of a grid in coordinates `c`: for_each_point(visit) calls
  // visit(p, x) with each point's index and coordinates (only the first counts on a Cartesian grid).
  template <class At>
  static CellFrames of(CoordinateSystem c, std::size_t points, At&& for_each_point) {
    CellFrames fr;
    fr.points = points;
    const bool constant = c == CoordinateSystem::cartesian;
    fr.J.assign(constant ? 1 : points, Matrix3{});
    fr.f.assign(constant ? 1 : points, Point3{1, 1, 1});
    bool done = false;
    for_each_point([&](std::size_t p, const Point3& x) {
      if (done) return;
      const std::size_t at = constant ? 0 : p;
      fr.J[at] = coords::jacobian(c, x);
      fr.f[at] = coords::metric_diagonal(c, x);
      done = constant;
    });
    return fr;
  }
};

// Where the levels' arrays live on several ranks: replicated (every rank holds every level whole,
// only the work is split) or distributed (3D levels split in slabs hold only the own slab and one
// halo plane each side; the first level below the split is agglomerated on every rank). The
// interface's arrays (u, the equation, frames) are whole on every rank in both.
enum class MultigridStorage { replicated, distributed };

class Multigrid {
 public:
  // comm: the ranks sharing the work (every rank calls solve with the same arguments).
  explicit Multigrid(const GridShape& shape, MPI_Comm comm = MPI_COMM_SELF,
                     MultigridStorage storage = MultigridStorage::replicated);
  ~Multigrid();
  Multigrid(Multigrid&&) noexcept;
  Multigrid& operator=(Multigrid&&) noexcept;

  const GridShape& shape() const;
  int levels() const;
  int distributed_levels() const;  // leading levels whose work is split between the ranks
  // Solves that reused the line factors of a geometry-only equation (k zero, linear) from an
  // earlier solve instead of refactoring.
  long long reused_factorisations() const;
  // Bytes this rank has received in the exchanges of the distributed levels since construction.
  long long received_bytes() const;
  // Bytes of the arrays this rank holds for the hierarchy (capacity of the level arrays).
  long long stored_bytes() const;
  // The part of stored_bytes() held by the levels alone (without the finest level's cell frames).
  long long level_bytes() const;
  // Solves in place: u holds the initial guess (warm start) and returns the solution.
  SolveStats solve(const ScalarEquation& eq, std::vector<double>& u, const SolveSettings& s);
  // Max-norm residual of the finest-level discrete equation.
  double residual_norm(const ScalarEquation& eq, const std::vector<double>& u);
  // The interior array with one ghost layer in used directions, filled with the equation's
  // boundary conditions (for derivatives); index with ghosted_index.
  std::vector<double> with_ghosts(const ScalarEquation& eq, const std::vector<double>& u) const;
  std::ptrdiff_t ghosted_index(int i, int j, int k) const;
  std::array<std::ptrdiff_t, 3> ghosted_strides() const;
  const CellFrames& frames() const;

  // The base level of a composite (AMR) solve: prepare() takes the equation, cycle() does one FAS
  // V-cycle of A(u) = f (A(u) = Lap u - k u - s0 - s1/u - s7/u^7; interior arrays, complete on every
  // rank) from u, in place. 1D grids take one direct line solve instead (SolveSettings::direct_1d).
  void prepare(const ScalarEquation& eq);
  void cycle(const ScalarEquation& eq, std::vector<double>& u, const std::vector<double>& f, const SolveSettings& s);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace remnant::xcfc
