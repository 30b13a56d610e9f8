#pragma once
// The FAS multigrid's state (see include/XCFC/multigrid/multigrid.hpp): the level hierarchy, the
// MPI split of the work and the steps of a cycle. Split by concern: multigrid.cpp (hierarchy,
// equation coefficients, the public interface), multigrid_smoothing.cpp (point, line and shell
// relaxation), multigrid_cycles.cpp (residuals, coarse solve, V-cycle, full multigrid).
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "XCFC/multigrid/multigrid.hpp"
#include "boundary_ghosts.hpp"
#include "factor_cache.hpp"
#include "level.hpp"
#include "remnant/comm_counters.hpp"
#include "work_partition.hpp"

namespace remnant::xcfc {

struct Multigrid::Impl {
  std::vector<Level> levels;
  CellFrames frames;
  WorkPartition work;
  long long relaxed_fine = 0, relaxed_all = 0;  // this rank's relaxed cells in the current solve
  long long ghost_entries = 0, factored_cells = 0, restricted_cells = 0;  // and its other cell work

  // The level hierarchy of a grid, the restriction weights and the MPI split.
  Impl(const GridShape& shape, MPI_Comm c, MultigridStorage storage);
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void count(std::size_t l, long long n) {
    comm::count_work("mg_base_relax", static_cast<int>(l), n);
    relaxed_all += n;
    if (l == 0) relaxed_fine += n;
  }

  // Ghost boxes of level l (the whole level when it is not split): the owned slab with its halo
  // planes, or the owned columns [c0, c1) with their neighbours (the lines across the slabs).
  GhostBox rows_box(std::size_t l) const;
  void count_fill(const Level& L, const ScalarEquation& eq, std::vector<double>& a, bool homogeneous,
                  const GhostBox& box = GhostBox{}) {
    ghost_entries += static_cast<long long>(fill_ghosts(L, eq, a, homogeneous, box));
  }
  GhostBox columns_box(std::size_t l, int c0, int c1) const;

  // r = f - A(u) on the owned cells; returns max|r| over all ranks (a max is exact in any order).
  double residual(std::size_t l, const ScalarEquation& eq);

  // Max of the source terms' magnitudes at u: the scale of the residual.
  double source_scale(std::size_t l) const;

  // Red-black Gauss-Seidel, one Newton step per cell. A colour's cells read only the other colour:
  // with the halo planes exchanged between colours, the owned slab is updated as in one rank.
  void smooth(std::size_t l, const ScalarEquation& eq, int sweeps);

  // One zebra pass. Distributed 2D levels: lines across the slabs (d = s) are local to the slab and
  // need the halo rows between colours; lines along s cross the slabs, so they are solved whole,
  // split by i, after a transpose from slabs to columns (MPI_Alltoallv), with the neighbouring
  // lines exchanged between colours, and transposed back to the slabs.
  // Lines t < limit only: the local relaxation next to the origin.
  void smooth_lines(std::size_t l, const ScalarEquation& eq, int d, int limit = std::numeric_limits<int>::max());

  // Local relaxation next to the spherical origin (Brandt): the large coefficients there leave the
  // largest residual after a red-black sweep, which otherwise dominates the L-infinity stopping
  // test for V-cycles after the rest of the grid has converged.
  void relax_origin(std::size_t l, const ScalarEquation& eq);
  // 2D spherical: `passes` zebra passes of the theta lines of the innermost `shells` radial cells.
  void relax_origin_shells(std::size_t l, const ScalarEquation& eq, int shells, int passes);

  // 3D cylindrical and spherical levels: zebra lines along d. Every rank holds the whole level and
  // does the rest of the cycle itself; on large levels the lines of each colour are dealt out in
  // contiguous index ranges and the solved lines gathered by every rank (MPI_Allgatherv), so that
  // each line is solved from the same inputs as on one rank: the same bits.
  void smooth_lines_3d(std::size_t l, const ScalarEquation& eq, int d);
  std::vector<double> line_send, line_recv;  // 3D line exchange buffers
  struct LineSplit {
    std::vector<int> counts, displs;  // MPI_Allgatherv layout of the solved lines
  };
  std::vector<std::array<std::array<LineSplit, 2>, 3>> line_splits;  // [level][direction][colour]

  // Point red-black smoothing in 1D and 3D Cartesian, alternating line smoothing in 2D and on 3D
  // cylindrical and spherical levels (strong phi coupling at the axis, angular at the origin).
  void relax(std::size_t l, const ScalarEquation& eq, int sweeps);

  // ---- cycles ------------------------------------------------------------------------------------
  // Coarsest level: relaxation to 1e-8 of the initial residual. A 1D level is one line, solved
  // exactly (linear) or by Newton line solves, so it needs no point sweeps at all.
  void coarse_solve(std::size_t l, const ScalarEquation& eq, int max_sweeps);

  void vcycle(std::size_t l, const ScalarEquation& eq, const SolveSettings& s);

  void full_multigrid(const ScalarEquation& eq, const SolveSettings& s);

  // k = the equation's k plus the geometric point term of its angular mode, which is rediscretised
  // on each level, not restricted.
  static void add_mode_term(Level& L, AngularMode mode);

  // Equation coefficients: set_fine_equation on the finest level (all a residual needs);
  // set_coarse_equations on the coarse levels, line ends and line factors everywhere, only once a
  // cycle is needed (a warm start that already meets the tolerance costs one residual);
  // `fine_only` (1D line solves): line ends and factors of level 0 alone.
  void set_fine_equation(const ScalarEquation& eq);
  void set_coarse_equations(const ScalarEquation& eq, bool fine_only = false);
  // Thomas factors of the lines this rank relaxes on level l (all lines of an undistributed level).
  long long factor_own_lines(std::size_t l);
  // 2D spherical: the innermost radial cells whose theta lines get the extra local relaxation.
  static int origin_shells(const Level& L);
  static constexpr int kOriginPasses = 8;  // zebra passes over them per relaxation
  enum class Ready { none, fine, all };
  Ready equations_ready = Ready::none;
  FactorCache factor_cache;  // line factors of geometry-only equations, kept between solves

  // max |a| over a ghosted array of level l, each rank reading its own planes (the same value).
  double max_abs_owned(std::size_t l, const std::vector<double>& a) const;

  // Between the interface's whole interior arrays and level 0 (its window when distributed).
  void load(const std::vector<double>& u);
  void store(std::vector<double>& u) const;
  // The finest level's solution into u, complete on every rank.
  void store_complete(std::vector<double>& u);
  // The window of level 0's interior cells out of a whole interior array.
  void copy_window(const std::vector<double>& whole, std::vector<double>& out) const;
};

}  // namespace remnant::xcfc
