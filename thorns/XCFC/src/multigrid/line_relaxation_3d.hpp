#pragma once
// Zebra line relaxation on 3D cylindrical and spherical levels, where the coupling across phi
// (1 / (varpi dphi)^2) dominates next to the axis and the angular couplings next to the origin, so
// that point smoothing stalls. Lines along direction d are coloured by the parity of their two
// transverse indices (a line's transverse neighbours have the other colour); each line is one
// tridiagonal solve (one Newton linearisation for nonlinear equations), cyclic along a periodic phi.
#include <cstddef>
#include <vector>

#include "level.hpp"

namespace remnant::xcfc {

// One colour of lines along d; the level's ghosts must be current (they are held, except that the
// line's own ends follow it: Robin, Dirichlet, reflection onto the end cell, periodic wrap).
// Only lines whose index t1 + n_e1 t2 (e1, e2 = d+1, d+2 mod 3) lies in [first, last) (a rank's
// share). Returns the number of cells relaxed.
long long line_pass_3d(Level& L, const ScalarEquation& eq, int d, int colour, std::size_t first = 0,
                       std::size_t last = static_cast<std::size_t>(-1));

// The cells of the lines of one colour with index in [first, last), in line order: their number,
// appended to `out` (pack) or read from `in` starting at `at` (unpack; returns the position after).
std::size_t line_cells_3d(const Level& L, int d, int colour, std::size_t first, std::size_t last);
void pack_lines_3d(const Level& L, int d, int colour, std::size_t first, std::size_t last, std::vector<double>& out);
std::size_t unpack_lines_3d(Level& L, int d, int colour, std::size_t first, std::size_t last, const std::vector<double>& in,
                            std::size_t at);

// Thomas algorithm for a[m] x[m-1] + b[m] x[m] + c[m] x[m+1] = r[m] (a[0] and c[n-1] unused):
// thomas_factor overwrites b by the inverse pivots, thomas_solve (any number of times) replaces r
// by the solution.
void thomas_factor(int n, const double* a, double* b, const double* c);
void thomas_solve(int n, const double* a, const double* b, const double* c, double* r);

// The ghost beyond face (d, side) as c0 + c1 u_end of the adjacent cell: c1 (Robin ratio,
// -1 Dirichlet, the parity of a reflection onto the cell itself; 0: the ghost is held).
double line_end_factor(const Level& L, const ScalarEquation& eq, int d, int side, std::size_t face_index);

// Linear equations (no s1, s7): the Thomas factors of every line, kept on the level for the
// passes of one solve (sets L.factored; nonlinear equations are linearised per pass instead).
void factor_lines_3d(Level& L, const ScalarEquation& eq);

}  // namespace remnant::xcfc
