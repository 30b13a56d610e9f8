#pragma once
// Exact solution of the special-relativistic Riemann problem for an ideal gas without tangential
// velocities (Marti & Mueller 1994, J. Fluid Mech. 258, 317; Living Rev. Relativ. 6, 7 (2003)),
// for the shock-tube tests: the star-state pressure by bisection of v*_L(p) = v*_R(p), rarefactions
// from the Riemann invariants, shocks from the Taub adiabat.
namespace remnant::grmhd::test {

struct SrhdState {
  double rho = 1, v = 0, p = 1;
};

class ExactRiemannSRHD {
 public:
  ExactRiemannSRHD(double gamma, SrhdState left, SrhdState right);
  // The state at similarity coordinate xi = (x - x0) / t.
  SrhdState sample(double xi) const;
  double star_pressure() const { return p_star_; }
  double star_velocity() const { return v_star_; }

 private:
  double sound_speed(double rho, double p) const;
  // Velocity behind a wave (side = -1 left wave, +1 right wave) into state a with pressure p behind.
  double velocity_behind(const SrhdState& a, double p, int side) const;
  double density_behind(const SrhdState& a, double p) const;
  double shock_speed(const SrhdState& a, double p, int side) const;
  SrhdState sample_side(const SrhdState& a, double xi, int side) const;

  double g_;
  SrhdState L_, R_;
  double p_star_ = 0, v_star_ = 0;
};

}  // namespace remnant::grmhd::test
