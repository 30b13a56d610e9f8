#pragma once
// Constrained transport of a face-centred B by a constant velocity on a 2D Cartesian block:
// E_z = -(v x B)_z at the corners from upwind, MC-limited reconstructions of the face values
// (B_x along y, B_y along x), and dPhi/dt = -(circulation of E) for each face.
#include <array>

#include "remnant/grid.hpp"

namespace remnant::field_loop {

struct Loop {
  std::array<double, 2> velocity{1.0, 0.5};
  std::array<double, 2> centre{-0.3, 0.0};
  double radius = 0.3, amplitude = 1e-3;
  std::array<double, 2> period{2.0, 2.0};  // domain size (periodic images of the loop)
};

// Distance of (x, y) from the loop centre at time t (nearest periodic image).
double distance_to_centre(const Loop& loop, double t, double x, double y);
// The potential A_z at (x, y) and time t (the loop moved by v t, periodic images included).
double potential(const Loop& loop, double t, double x, double y);
// The exact magnetic energy of the loop, integral of |B|^2 / 2 = 4 pi A0^2 / 7.
double exact_energy(const Loop& loop);

// B = curl A_z on the faces of the interior (block faces included): Phi = A_z(top) - A_z(bottom).
void set_initial(const Loop& loop, double t, Block& b, const Field& bx, const Field& by);
// E_z on the corners of the interior (block edges included); reads two ghost layers of bx, by.
void corner_emf(const Loop& loop, Block& b, const Field& bx, const Field& by, const Field& ez);
// Right-hand sides on the faces of the interior from the corner EMFs.
void face_rhs(Block& b, const Field& ez, const Field& bx_rhs, const Field& by_rhs);
// |B|^2 / 2 of the face means and (1/V) sum(+-A B) per cell.
void analyse(Block& b, const Field& bx, const Field& by, const Field& b2, const Field& div);

}  // namespace remnant::field_loop
