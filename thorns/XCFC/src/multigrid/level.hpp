#pragma once
// One multigrid level: geometry coefficients of the finite-volume Laplacian and work arrays.
#include <array>
#include <cstddef>
#include <vector>

#include "XCFC/multigrid/multigrid.hpp"

namespace remnant::xcfc {

struct Level {
  GridShape shape;
  std::array<int, 3> g{0, 0, 0};                 // ghost layers (1 in used directions)
  std::array<std::ptrdiff_t, 3> st{1, 0, 0};      // strides of ghosted arrays
  std::size_t ghosted_size = 0;
  std::array<int, 3> ratio{1, 1, 1};              // coarsening to the next level, per direction
  std::vector<double> volume;                     // exact cell volumes (interior)
  // Coefficients of u at the lower and upper neighbour in direction d: face integral of
  // sqrt(f) f^dd / (dx_d * volume).
  std::array<std::vector<double>, 3> a_lo, a_hi;
  std::vector<double> diagonal;                   // sum of the a's
  std::array<std::vector<double>, 3> mode_k;      // point coefficient of each AngularMode (empty: zero)
  double max_diagonal = 0;                        // scale of the round-off floor of the residual
  // Robin fall-off factors (r_inner / r_ghost)^p of the outer-face ghosts for p = 1 and 2, per
  // [direction][side], indexed t1 + n[e1] * t2 over the face (e1, e2 = d+1, d+2 mod 3): geometry
  // only, so computed once instead of per ghost fill.
  std::array<std::array<std::vector<double>, 2>, 3> robin1, robin2;
  // Face ghosts per [direction][side], indexed like robin1: the ghost's index, the adjacent interior
  // cell's and the mirror cell's (the source of a symmetry ghost), all in ghosted arrays.
  struct GhostFace {
    std::vector<std::ptrdiff_t> ghost, inner, mirror;
  };
  std::array<std::array<GhostFace, 2>, 3> ghost_faces;
  std::vector<double> restrict_volume;            // sum of the fine volumes restricted into each cell
  std::vector<double> line_di, line_rhs;  // line-relaxation work (4 interleaved lines)
  std::vector<double> line_scratch;       // 3D line relaxation: six arrays of the longest line
  std::vector<double> line_z, line_cyclic;  // 3D cyclic phi lines of linear equations (factors)
  std::vector<double> shell_scratch;      // inner-shell plane relaxation work
  std::vector<double> dft_cos, dft_sin;   // its DFT table along phi, [m][k]
  // Line relaxation (1D and 2D): the line end ghost is c0 + c1 * u_end with c1 from the
  // equation's boundary kind (Robin ratio, -1 Dirichlet, parity, 0 for a held ghost), per
  // [direction][side] and line (index along the transverse direction). For linear equations the
  // tridiagonal line matrices are fixed, so their Thomas factors are kept per cell and direction:
  // line_w the elimination multiplier, line_inv the inverse pivot.
  std::array<std::array<std::vector<double>, 2>, 3> end_c1;
  std::array<std::vector<double>, 3> line_w, line_inv;
  bool factored = false;

  // Equation on this level (interior arrays) and work arrays.
  std::vector<double> k, s0, s1, s7, f, r;
  std::vector<double> k_eq;                       // k without the angular-mode term (restricted)
  std::vector<double> u, ubar;                    // ghosted

  // Distributed storage (Multigrid::Storage::distributed): the arrays hold only a window of planes
  // along the last used direction, the owned cells [lo, hi) and one halo plane on each side in
  // ghosted arrays; at() and cell() take global indices and return offsets into the window
  // (bases 0 and whole sizes when the level is stored whole).
  std::ptrdiff_t gbase = 0;         // ghosted offset of the window's first entry
  std::size_t cbase = 0;            // interior index of the window's first cell
  std::size_t stored_ghosted = 0;   // entries of a ghosted array as stored
  std::size_t stored_cells = 0;     // entries of an interior array as stored

  explicit Level(const GridShape& s);
  // Keeps only the window of planes [lo, hi) along the last used direction (and the halo planes in
  // ghosted arrays) of every per-cell array; max_diagonal and the face lists stay global.
  void set_window(int lo, int hi);
  bool windowed() const { return stored_cells != cells(); }
  std::size_t stored_bytes() const;  // capacity of all arrays
  std::size_t cells() const { return shape.cells(); }  // of the whole level
  std::ptrdiff_t global_at(int i, int j, int k) const { return (i + g[0]) + (j + g[1]) * st[1] + (k + g[2]) * st[2]; }
  std::ptrdiff_t at(int i, int j, int k) const { return global_at(i, j, k) - gbase; }
  std::ptrdiff_t at_cell(std::size_t q) const {  // ghosted offset of interior cell q
    const auto n0 = static_cast<std::size_t>(shape.n[0]), n1 = static_cast<std::size_t>(shape.n[1]);
    return at(static_cast<int>(q % n0), static_cast<int>((q / n0) % n1), static_cast<int>(q / (n0 * n1)));
  }
  std::size_t cell(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(shape.n[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(shape.n[1]) * k) -
           cbase;
  }
};

}  // namespace remnant::xcfc
