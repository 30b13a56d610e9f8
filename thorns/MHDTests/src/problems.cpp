#include "problems.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace remnant::mhd_tests {

namespace {
constexpr std::array<std::string_view, 8> kNames{"balsara1", "balsara2", "balsara3", "balsara4",
                                                 "balsara5", "field_loop", "cylindrical_blast", "rotor"};
}  // namespace

Problem problem_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<Problem>(i);
  throw std::invalid_argument("unknown MHD test problem '" + std::string(name) + "'");
}

std::string_view name_of(Problem p) { return kNames[static_cast<std::size_t>(p)]; }

bool is_riemann_problem(Problem p) { return static_cast<int>(p) <= static_cast<int>(Problem::balsara5); }

ProblemSetup setup_of(Problem p) {
  ProblemSetup s;
  switch (p) {
    case Problem::balsara1: s.gamma = 2.0; break;   // the relativistic Brio & Wu problem
    case Problem::balsara5: s.t_final = 0.55; break;
    case Problem::field_loop:  // one crossing of the periodic box along the diagonal velocity
      s.xmin = {-1.0, -0.5};
      s.xmax = {1.0, 0.5};
      s.t_final = 2.4;
      break;
    case Problem::cylindrical_blast:
      s.gamma = 4.0 / 3.0;
      s.xmin = {-6.0, -6.0};
      s.xmax = {6.0, 6.0};
      s.t_final = 4.0;
      break;
    default: break;  // balsara2..4 and the rotor: Gamma = 5/3, [-0.5, 0.5], t = 0.4
  }
  return s;
}

RiemannProblem riemann_problem(Problem p) {
  // Balsara (2001), Table 1 / section 5; the same states as Giacomazzo & Rezzolla (2006), Table 1.
  switch (p) {
    case Problem::balsara1: return {{1.0, 1.0, {0, 0, 0}, {0.5, 1.0, 0}}, {0.125, 0.1, {0, 0, 0}, {0.5, -1.0, 0}}};
    case Problem::balsara2: return {{1.0, 30.0, {0, 0, 0}, {5.0, 6.0, 6.0}}, {1.0, 1.0, {0, 0, 0}, {5.0, 0.7, 0.7}}};
    case Problem::balsara3: return {{1.0, 1000.0, {0, 0, 0}, {10.0, 7.0, 7.0}}, {1.0, 0.1, {0, 0, 0}, {10.0, 0.7, 0.7}}};
    case Problem::balsara4:
      return {{1.0, 0.1, {0.999, 0, 0}, {10.0, 7.0, 7.0}}, {1.0, 0.1, {-0.999, 0, 0}, {10.0, -7.0, -7.0}}};
    case Problem::balsara5:
      return {{1.08, 0.95, {0.4, 0.3, 0.2}, {2.0, 0.3, 0.3}}, {1.0, 1.0, {-0.45, -0.2, 0.2}, {2.0, -0.7, 0.5}}};
    default: throw std::invalid_argument("riemann_problem: " + std::string(name_of(p)) + " is not a Riemann problem");
  }
}

FluidState field_loop_state(const FieldLoopParams& p) {
  FluidState s;
  s.rho = p.rho;
  s.press = p.press;
  s.v = {p.velocity[0], p.velocity[1], 0};
  return s;
}

FluidState blast_state(const BlastParams& p, double x, double y) {
  const double r = std::hypot(x, y);
  FluidState s;
  if (r <= p.r_in) {
    s.rho = p.rho_in;
    s.press = p.press_in;
  } else if (r >= p.r_out) {
    s.rho = p.rho_out;
    s.press = p.press_out;
  } else {  // Komissarov's exponential (log-linear) transition
    const double w = (r - p.r_in) / (p.r_out - p.r_in);
    s.rho = std::exp((1 - w) * std::log(p.rho_in) + w * std::log(p.rho_out));
    s.press = std::exp((1 - w) * std::log(p.press_in) + w * std::log(p.press_out));
  }
  s.B = {p.B0, 0, 0};
  return s;
}

FluidState rotor_state(const RotorParams& p, double x, double y) {
  FluidState s;
  s.press = p.press;
  s.B = {p.B0, 0, 0};
  if (std::hypot(x, y) < p.radius) {
    s.rho = p.rho_in;
    s.v = {-p.omega * y, p.omega * x, 0};
  } else {
    s.rho = p.rho_out;
  }
  return s;
}

double field_loop_potential(const FieldLoopParams& p, double x, double y) {
  double dx = x - p.centre[0], dy = y - p.centre[1];
  dx -= p.period[0] * std::round(dx / p.period[0]);  // nearest periodic image
  dy -= p.period[1] * std::round(dy / p.period[1]);
  const double r = std::hypot(dx, dy);
  if (r >= p.radius) return 0.0;
  if (p.profile == FieldLoopParams::Profile::beckwith_stone) return p.amplitude * (p.radius - r);
  // Smooth variant (B and its first derivatives continuous) for convergence measurements.
  const double w = 1 - r * r / (p.radius * p.radius);
  return p.amplitude * p.radius * w * w * w * w;
}

double field_loop_magnetic_energy(const FieldLoopParams& p) {
  const double a = p.amplitude, R = p.radius;
  // |B| = |dA/dr|: A0 inside (Beckwith & Stone): pi R^2 A0^2 / 2. Smooth: |dA/dr| = 8 A0 r w^3 / R,
  // integral of (1/2) 64 A0^2 r^2 w^6 / R^2 2 pi r dr = 4 pi A0^2 R^2 / 7.
  if (p.profile == FieldLoopParams::Profile::beckwith_stone) return 0.5 * std::numbers::pi * R * R * a * a;
  return 4 * std::numbers::pi * a * a * R * R / 7;
}

}  // namespace remnant::mhd_tests
