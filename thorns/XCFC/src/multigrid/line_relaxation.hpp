#pragma once
// Line relaxation on 1D and 2D levels: the geometry of the lines of one direction, their boundary
// ends, the Thomas factors of fixed (linear) line matrices and one zebra pass of line solves.
#include <array>
#include <cstddef>

#include "level.hpp"

namespace remnant::xcfc {

// Line geometry of direction d on a 1D or 2D level: lines are indexed by t along the transverse
// direction e (none in 1D); interior and ghosted strides along and across the lines.
struct Lines {
  int d, e, n, count;
  std::ptrdiff_t qd, qe, pd, pe;
  Lines(const Level& L, int dir) : d(dir), e(L.shape.dimension == 2 ? 1 - dir : -1), n(L.shape.n[dir]) {
    const GridShape& s = L.shape;
    count = e < 0 ? 1 : s.n[e];
    qd = d == 0 ? 1 : s.n[0];
    qe = e == 0 ? 1 : s.n[0];
    pd = L.st[d];
    pe = e < 0 ? 0 : L.st[e];
  }
  std::size_t q0(int t) const { return static_cast<std::size_t>(t * qe); }
  std::ptrdiff_t p0(const Level& L, int t) const { return d == 0 ? L.at(0, e < 0 ? 0 : t, 0) : L.at(t, 0, 0); }
};

// Line ends: ghost = c0 + c1 * u_end, c1 from the boundary kind (the Robin ratio is geometry);
// c0 is taken from the current ghost in the relaxation.
void set_line_ends(Level& L, const ScalarEquation& eq);

// Thomas forward-elimination factors of the (fixed) line matrices of a linear equation; sets
// L.factored (false for nonlinear equations and 3D levels). Lines t0[d] <= t < t1[d] of each
// direction d only (a distributed level: the lines this rank relaxes; the others keep stale
// factors that no pass of this rank reads); by default all.
// Returns the number of cells factored.
long long factor_lines(Level& L, std::array<int, 2> t0 = {0, 0}, std::array<int, 2> t1 = {1 << 30, 1 << 30});

// Zebra line Gauss-Seidel along direction d (Thomas algorithm): robust against the anisotropy of
// spherical grids (theta coupling dominates near the origin, radial coupling far out). Linear
// equations use the factors of factor_lines (substitutions only); nonlinear ones take one Newton
// linearisation per line. Line ends take the boundary ghost as an affine function of the end
// cell; other ghosts are held. In 1D the single line is an exact (Newton) solve.
// Lines t0 <= t < t1 of one colour; returns the number of cells relaxed.
long long line_pass(Level& L, const Lines& ln, int colour, int t0, int t1);

}  // namespace remnant::xcfc
