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
// solution stays second order). Every rank holds all patches; the relaxation, residuals and
// transfers are split by patch and the base level's work by slabs (bit-identical to one rank).
#include <mpi.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <memory>
#include <vector>

#include "XCFC/multigrid/cell_share.hpp"
#include "XCFC/multigrid/multigrid.hpp"

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

// Interior arrays of a composite field, one per part: part 0 is the base level, then the patches
// of level 1, level 2, ... in the layout's order.
struct CompositeField {
  std::vector<std::vector<double>> part;
  bool empty() const { return part.empty(); }
};

// The equation's boundary data (parity, far_value, falloff, dirichlet, mode; its arrays unused) and
// its coefficients as composite fields (no parts: zero, or absent for s1 and s7).
struct CompositeEquation {
  ScalarEquation boundary;
  CompositeField k, s0, s1, s7;
  bool nonlinear() const { return !s1.empty() || !s7.empty(); }
};

// Geometry of one part in the ghosted layout (one ghost layer in used directions): per cell the
// Jacobian dX^A/dx^i and the reference-metric diagonal at the evaluation point.
struct PartGeometry {
  GridShape shape;
  int level = 0;
  std::array<std::ptrdiff_t, 3> strides{1, 0, 0};
  std::array<int, 3> ghosts{0, 0, 0};
  const CellFrames& frames() const { return shared ? *shared : own; }
  CellFrames own;                      // patches
  const CellFrames* shared = nullptr;  // the base level: Multigrid's
  std::ptrdiff_t at(int i, int j, int k) const {
    return (i + ghosts[0]) + (j + ghosts[1]) * strides[1] + (k + ghosts[2]) * strides[2];
  }
};

// Interior cells of a part: f(q, p, i, j, k) with q the interior and p the ghosted index.
template <class F>
inline void for_part_cells(const PartGeometry& g, F&& f) {
  const GridShape& s = g.shape;
  std::size_t q = 0;
  for (int k = 0; k < s.n[2]; ++k)
    for (int j = 0; j < s.n[1]; ++j)
      for (int i = 0; i < s.n[0]; ++i) f(q++, static_cast<std::size_t>(g.at(i, j, k)), i, j, k);
}

// Interior cells [begin, end) of a part (storage order), with the same arguments as for_part_cells:
// row by row, the ghosted index stepping with i (its stride is 1).
template <class F>
inline void for_part_cells(const PartGeometry& g, std::size_t begin, std::size_t end, F&& f) {
  const GridShape& s = g.shape;
  const auto n0 = static_cast<std::size_t>(s.n[0]), n1 = static_cast<std::size_t>(s.n[1]);
  for (std::size_t q = begin; q < end;) {
    int i = static_cast<int>(q % n0);
    const int j = static_cast<int>((q / n0) % n1), k = static_cast<int>(q / (n0 * n1));
    const std::size_t row_end = std::min(end, q + (n0 - static_cast<std::size_t>(i)));
    auto p = static_cast<std::size_t>(g.at(i, j, k));
    for (; q < row_end; ++q, ++i, ++p) f(q, p, i, j, k);
  }
}

class CompositeMultigrid {
 public:
  // Throws std::invalid_argument for a layout that breaks the rules above.
  // storage: the base grid's (Multigrid's) level storage on several ranks.
  explicit CompositeMultigrid(const CompositeLayout& layout, MPI_Comm comm = MPI_COMM_SELF,
                              MultigridStorage storage = MultigridStorage::replicated);
  // A uniform grid: the base level only (every solve is Multigrid's, bit for bit).
  explicit CompositeMultigrid(const GridShape& shape, MPI_Comm comm = MPI_COMM_SELF,
                              MultigridStorage storage = MultigridStorage::replicated);
  ~CompositeMultigrid();
  CompositeMultigrid(CompositeMultigrid&&) noexcept;
  CompositeMultigrid& operator=(CompositeMultigrid&&) noexcept;

  const CompositeLayout& layout() const;
  const GridShape& base_shape() const { return layout().base; }
  Multigrid& base();
  // The parts (base, then patches level by level) and their geometry.
  int parts() const;
  const PartGeometry& part(int i) const;
  // Whether interior cell q of part i is covered by a finer patch (not a leaf).
  bool covered(int i, std::size_t q) const;
  // A composite field of `value` with every part sized.
  CompositeField field(double value = 0.0) const;
  // The split of pointwise work over the interior (or ghosted, PartGeometry::at) cells of all parts
  // between the ranks, and the fields made complete again after it (cell_share.hpp).
  const CellShare& share(bool ghosted = false) const;
  MPI_Comm comm() const;
  void complete(std::initializer_list<CompositeField*> fields, bool ghosted = false) const;
  // Covered cells take the volume-weighted mean of their children (finest level first).
  void fill_covered(CompositeField& f) const;
  // Ghosted copies of the parts (PartGeometry::at) with the ghosts filled from the equation's
  // boundary data, neighbours and coarser levels; covered cells first take the finer values.
  // share_only: the ghosts only of the parts that this rank's shares (share(), share(true)) reach,
  // the others' left as they are (for loops over this rank's share; the interiors are all set).
  CompositeField with_ghosts(const ScalarEquation& boundary, const CompositeField& u, bool share_only = false);

  // Solves in place (u: warm start, all levels). Convergence on max |residual| over the leaf cells
  // relative to the max of the source terms there; full_multigrid: the base problem (with the fine
  // coefficients restricted) solved first and interpolated up instead of the warm start.
  SolveStats solve(const CompositeEquation& eq, CompositeField& u, const SolveSettings& s);
  // Max-norm residual of the composite equation over the leaf cells.
  double residual_norm(const CompositeEquation& eq, const CompositeField& u);
  // Bytes held by the ghost recipes built so far (one set per boundary signature; memory
  // accounting, issue 21 goal 7).
  std::size_t recipe_bytes() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace remnant::xcfc

namespace remnant::xcfc {

// This rank's share (CompositeMultigrid::share) of the interior cells of part n, with the arguments
// of for_part_cells; counted in the share. The caller completes the fields it wrote.
template <class F>
inline void for_share_cells(const CompositeMultigrid& mg, int n, F&& f) {
  const auto [b, e] = mg.share().range(n);
  mg.share().count(e - b);
  for_part_cells(mg.part(n), b, e, f);
}

}  // namespace remnant::xcfc
