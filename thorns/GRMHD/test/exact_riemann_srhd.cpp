#include "exact_riemann_srhd.hpp"

#include <cmath>
#include <stdexcept>

namespace remnant::grmhd::test {

ExactRiemannSRHD::ExactRiemannSRHD(double gamma, SrhdState left, SrhdState right) : g_(gamma), L_(left), R_(right) {
  auto f = [&](double p) { return velocity_behind(L_, p, -1) - velocity_behind(R_, p, +1); };
  double lo = 1e-14 * std::min(L_.p, R_.p), hi = 10 * std::max(L_.p, R_.p);
  if (!(f(lo) > 0 && f(hi) < 0)) throw std::runtime_error("exact Riemann solver: no bracket (vacuum?)");
  for (int it = 0; it < 300; ++it) {
    const double mid = std::sqrt(lo * hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  p_star_ = std::sqrt(lo * hi);
  v_star_ = 0.5 * (velocity_behind(L_, p_star_, -1) + velocity_behind(R_, p_star_, +1));
}

double ExactRiemannSRHD::sound_speed(double rho, double p) const {
  const double h = 1 + g_ / (g_ - 1) * p / rho;
  return std::sqrt(g_ * p / (rho * h));
}

double ExactRiemannSRHD::density_behind(const SrhdState& a, double p) const {
  if (p <= a.p) return a.rho * std::pow(p / a.p, 1 / g_);  // isentropic rarefaction
  // Taub adiabat, quadratic in h_b (Marti & Mueller 1994, eq. 31).
  const double ha = 1 + g_ / (g_ - 1) * a.p / a.rho;
  const double q = (g_ - 1) * (a.p - p) / (g_ * p);
  const double A = 1 + q, B = -q, C = ha * (a.p - p) / a.rho - ha * ha;
  const double hb = (-B + std::sqrt(B * B - 4 * A * C)) / (2 * A);
  return g_ * p / ((g_ - 1) * (hb - 1));
}

double ExactRiemannSRHD::shock_speed(const SrhdState& a, double p, int side) const {
  const double ha = 1 + g_ / (g_ - 1) * a.p / a.rho;
  const double rb = density_behind(a, p);
  const double hb = 1 + g_ / (g_ - 1) * p / rb;
  const double j2 = (p - a.p) / (ha / a.rho - hb / rb);
  const double Wa2 = 1 / (1 - a.v * a.v);
  const double r2W2 = a.rho * a.rho * Wa2;
  return (r2W2 * a.v + side * std::sqrt(j2) * std::sqrt(j2 + r2W2 * (1 - a.v * a.v))) / (r2W2 + j2);
}

double ExactRiemannSRHD::velocity_behind(const SrhdState& a, double p, int side) const {
  if (p <= a.p) {
    // Riemann invariant atanh(v) -/+ F(cs) across the fan.
    const double s = std::sqrt(g_ - 1);
    auto F = [&](double cs) { return std::log((s + cs) / (s - cs)) / s; };
    const double rb = density_behind(a, p);
    return std::tanh(std::atanh(a.v) + side * (F(sound_speed(rb, p)) - F(sound_speed(a.rho, a.p))));
  }
  const double ha = 1 + g_ / (g_ - 1) * a.p / a.rho;
  const double rb = density_behind(a, p);
  const double hb = 1 + g_ / (g_ - 1) * p / rb;
  const double j = side * std::sqrt((p - a.p) / (ha / a.rho - hb / rb));
  const double Vs = shock_speed(a, p, side);
  const double Ws = 1 / std::sqrt(1 - Vs * Vs), Wa = 1 / std::sqrt(1 - a.v * a.v);
  return (ha * Wa * a.v + Ws * (p - a.p) / j) / (ha * Wa + (p - a.p) * (Ws * a.v / j + 1 / (a.rho * Wa)));
}

// The state on one side of the contact (side = -1: left, xi measured from the left).
SrhdState ExactRiemannSRHD::sample_side(const SrhdState& a, double xi, int side) const {
  const SrhdState star{density_behind(a, p_star_), v_star_, p_star_};
  if (p_star_ > a.p) {  // shock
    const double Vs = shock_speed(a, p_star_, side);
    return side * (xi - Vs) > 0 ? a : star;
  }
  // Rarefaction: characteristic speeds (v -/+ cs) / (1 -/+ v cs) at head and tail.
  auto lambda = [&](double v, double cs) { return (v + side * cs) / (1 + side * v * cs); };
  const double head = lambda(a.v, sound_speed(a.rho, a.p));
  const double tail = lambda(star.v, sound_speed(star.rho, star.p));
  if (side * (xi - head) >= 0) return a;
  if (side * (xi - tail) <= 0) return star;
  double lo = p_star_, hi = a.p;  // inside the fan: the pressure whose characteristic passes xi
  for (int it = 0; it < 200; ++it) {
    const double p = 0.5 * (lo + hi);
    const double r = density_behind(a, p);
    const double l = lambda(velocity_behind(a, p, side), sound_speed(r, p));
    // Along the fan the pressure rises towards the head: side * (xi - l) > 0 means p is too low.
    (side * (xi - l) > 0 ? lo : hi) = p;
  }
  const double p = 0.5 * (lo + hi);
  return {density_behind(a, p), velocity_behind(a, p, side), p};
}

SrhdState ExactRiemannSRHD::sample(double xi) const {
  return xi < v_star_ ? sample_side(L_, xi, -1) : sample_side(R_, xi, +1);
}

}  // namespace remnant::grmhd::test
