#pragma once
// Composite (AMR) FAS multigrid for the scalar equation of multigrid.hpp on a block forest: the
// base level covers the domain (and is solved by Multigrid, whose coarse levels lie below it); each
// refined level l = 1..L is a set of patches, the blocks of level l that are leaves or ancestors of
// leaves, so that level l covers every region refined to l or finer. The composite solution lives on
// the leaf cells; a covered cell holds the volume-weighted restriction of its children.
//
// V-cycle (multi-level adaptive technique, FAS): from the finest level down, relax, restrict the
// solution and the residual into the covered cells of the next coarser level, whose right-hand side
// there becomes A(restricted u) + restricted residual; one base V-cycle; then up again, adding the
// interpolated coarse correction and relaxing. Patch ghosts come from neighbouring patches of the
// same level, from the physical boundary conditions, or by tensor-product quadratic interpolation of
// the next coarser level (error O(h^3), so the interface cells' truncation error is O(h) and the
// solution stays second order). Every rank holds all patches and computes them redundantly; the
// base level's work is split between the ranks (bit-identical to one rank).
#include <mpi.h>

#include <array>
#include <memory>
#include <vector>

#include "XCFC/multigrid.hpp"

namespace remnant::xcfc {

struct CompositeLayout {
  GridShape base;                          // level 0: the whole domain
  std::array<int, 3> patch_cells{1, 1, 1};  // cells per patch and direction (the Grid's block size)
  // patches[l - 1]: lower cell index (on level l, whose cell counts are base.n * 2^l in the used
  // directions) of each patch of level l. Must be multiples of patch_cells, nested in level l - 1's
  // patches, and with 2:1 balance including corners (every level l - 1 block touching a level l
  // patch belongs to level l - 1), as the Grid's forests are.
  std::vector<std::vector<std::array<int, 3>>> patches;
  int finest() const { return static_cast<int>(patches.size()); }
};

// Interior arrays of a composite field: the base level, then [level - 1][patch].
struct CompositeField {
  std::vector<double> base;
  std::vector<std::vector<std::vector<double>>> patch;
};

// The equation's boundary data (parity, far_value, falloff, dirichlet, mode; its arrays unused) and
// its coefficients as composite fields (an empty base array: zero, or absent for s1 and s7).
struct CompositeEquation {
  ScalarEquation boundary;
  CompositeField k, s0, s1, s7;
  bool nonlinear() const { return !s1.base.empty() || !s7.base.empty(); }
};

class CompositeMultigrid {
 public:
  // Throws std::invalid_argument for a layout that breaks the rules above.
  explicit CompositeMultigrid(const CompositeLayout& layout, MPI_Comm comm = MPI_COMM_SELF);
  ~CompositeMultigrid();
  CompositeMultigrid(CompositeMultigrid&&) noexcept;
  CompositeMultigrid& operator=(CompositeMultigrid&&) noexcept;

  const CompositeLayout& layout() const;
  // The level-l whole-domain shape (l = 0: base) and the shape of one patch (its cells' geometry).
  GridShape level_shape(int level) const;
  GridShape patch_shape(int level, int patch) const;
  // Whether interior cell q of a patch (level >= 1) or of the base (level 0, patch 0) is covered
  // by a finer patch (not a leaf).
  bool covered(int level, int patch, std::size_t q) const;
  // A composite field of zeros (or `value`) with every array sized.
  CompositeField field(double value = 0.0) const;

  // Solves in place (u: warm start, all levels). Convergence on max |residual| over the leaf cells
  // relative to the max of the source terms there; full_multigrid: the base problem (with the fine
  // coefficients restricted) solved first and interpolated up instead of the warm start.
  SolveStats solve(const CompositeEquation& eq, CompositeField& u, const SolveSettings& s);
  // Max-norm residual of the composite equation over the leaf cells.
  double residual_norm(const CompositeEquation& eq, const CompositeField& u);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace remnant::xcfc
