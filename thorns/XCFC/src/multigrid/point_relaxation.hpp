#pragma once
// Point kernels of one level (or one refined patch): the operator A(u) = Lap u - S(u) and one colour
// of red-black Gauss-Seidel with a local Newton step per cell.
#include <vector>

#include "level_ops.hpp"

namespace remnant::xcfc {

// out = A(u) on the cells R (u ghosted with its ghosts filled; out interior).
void apply_operator(const Level& L, const std::vector<double>& u, std::vector<double>& out, const Range& R);

// One colour ((i + j + k) % 2 == colour) of red-black Newton-Gauss-Seidel on L.u over R against L.f;
// reads only the other colour and the ghosts. Returns the number of cells relaxed.
long long red_black_pass(Level& L, const Range& R, int colour);

}  // namespace remnant::xcfc
