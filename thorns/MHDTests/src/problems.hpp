#pragma once
// The standard relativistic MHD test problems as tables and point functions, independent of the
// grid: the five Riemann problems of Balsara (2001, ApJS 132, 83), the relativistic field loop of
// Beckwith & Stone (2011, ApJS 193, 6), the cylindrical blast wave of Komissarov (1999, MNRAS
// 303, 343; strong-field case) and the rotor of Del Zanna, Bucciantini & Londrillo (2003, A&A 400,
// 397). Flat space, ideal gas. B is the Eulerian field in Heaviside-Lorentz units with sqrt(4 pi)
// absorbed (magnetic pressure b^2 / 2), as the papers write it.
#include <array>
#include <string_view>

namespace remnant::mhd_tests {

enum class Problem { balsara1, balsara2, balsara3, balsara4, balsara5, field_loop, cylindrical_blast, rotor };

// Throws std::invalid_argument for an unknown name.
Problem problem_from_name(std::string_view name);
std::string_view name_of(Problem p);
bool is_riemann_problem(Problem p);

struct FluidState {
  double rho = 1, press = 1;
  std::array<double, 3> v{0, 0, 0};
  std::array<double, 3> B{0, 0, 0};
};

// What a parfile needs to reproduce a published run: adiabatic index, domain [xmin, xmax] per
// used direction, final time.
struct ProblemSetup {
  double gamma = 5.0 / 3.0;
  std::array<double, 2> xmin{-0.5, -0.5}, xmax{0.5, 0.5};
  double t_final = 0.4;
};
ProblemSetup setup_of(Problem p);

// Riemann problems (balsara1..5): left state for x < 0, right state for x >= 0.
struct RiemannProblem {
  FluidState left, right;
};
RiemannProblem riemann_problem(Problem p);

// Parameters of the 2D problems (defaults: the published values).
struct FieldLoopParams {
  enum class Profile { beckwith_stone, smooth };
  Profile profile = Profile::beckwith_stone;
  double amplitude = 1e-3, radius = 0.3;
  std::array<double, 2> centre{0, 0};
  std::array<double, 2> velocity{1.0 / 1.2, 1.0 / 2.4};
  std::array<double, 2> period{2, 1};  // domain size: the loop's periodic images
  double rho = 1, press = 3;
};
struct BlastParams {
  double r_in = 0.8, r_out = 1.0;      // uniform inside r_in / outside r_out, log-linear between
  double rho_in = 1e-2, press_in = 1;
  double rho_out = 1e-4, press_out = 3e-5;
  double B0 = 1.0;                     // uniform B along x (strong-field case)
};
struct RotorParams {
  double radius = 0.1, omega = 9.95;   // v_phi = omega r inside: 0.995 at the rim
  double rho_in = 10, rho_out = 1, press = 1;
  double B0 = 1.0;                     // uniform B along x
};

// Fluid state (B excluded: it comes from the potential) at a point of the plane.
FluidState field_loop_state(const FieldLoopParams& p);
FluidState blast_state(const BlastParams& p, double x, double y);
FluidState rotor_state(const RotorParams& p, double x, double y);

// The potential A_z of each 2D problem; B = curl(A_z e_z) = (dA_z/dy, -dA_z/dx, 0).
double field_loop_potential(const FieldLoopParams& p, double x, double y);
inline double uniform_x_field_potential(double B0, double /*x*/, double y) { return B0 * y; }

// Exact magnetic energy integral of |B|^2 / 2 over the plane (per unit length in z) of the loop.
double field_loop_magnetic_energy(const FieldLoopParams& p);

}  // namespace remnant::mhd_tests
