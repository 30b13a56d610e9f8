#pragma once
// Radial oscillation frequencies of a polytropic TOV star in the relativistic Cowling approximation
// (metric frozen) or in full GR (below), computed here from scratch as an independent reference for
// the BU0-cow and BU0-dyn runs (the TOV thorn is not used). Schwarzschild coordinates, G = c = 1,
// p = K rho^Gamma, e = rho + p / (Gamma - 1), adiabatic perturbations with the same Gamma.
// Background: m' = 4 pi r^2 e, Phi' = (m + 4 pi r^3 p) / (r (r - 2m)), p' = -(e + p) Phi'.
// Perturbations (radial Lagrangian displacement xi, Lagrangian pressure change P = Delta p), from
// baryon conservation and the radial Euler equation with delta Phi = delta Lambda = 0:
//   xi' = -(2/r + Lambda') xi - P / (Gamma p)
//   P'  = (e + p) [omega^2 e^(2 Lambda - 2 Phi) - Phi''] xi + p' xi' - [(e + p) / (Gamma p) + 1] Phi' P
// with xi = r, P = -3 Gamma p at the centre and P = 0 at the surface; omega is the frequency seen
// from infinity (Phi(R) = ln(1 - 2M/R) / 2). Shooting on omega with RK4 and bisection.
// With full_gr the metric is perturbed too: Chandrasekhar's equations in the form of Kokkotas &
// Ruoff 2001 (A&A 366, 565, eqs. 4-5), for x = xi / r and P (checks the machinery against the
// published full-GR frequencies of BU0):
//   x' = -(3 x + P / (Gamma p)) / r - p' x / (e + p)
//   P' = x [omega^2 e^(2 Lambda - 2 Phi) (e + p) r - 4 p'] + x [p'^2 r / (e + p) - 8 pi e^(2 Lambda) (e + p) p r]
//        + P [p' / (e + p) - 4 pi (e + p) r e^(2 Lambda)]
#include <cmath>
#include <numbers>
#include <vector>

namespace remnant::tov_test {

class RadialModes {
 public:
  RadialModes(double K, double Gamma, double rho_c, bool full_gr = false, int steps = 4000)
      : K_(K), G_(Gamma), full_gr_(full_gr), steps_(steps) {
    p_c_ = K * std::pow(rho_c, Gamma);
    // The background alone: the radius, the mass and the offset of Phi.
    const State s = integrate(0.0, false, 1e-3, &r_surface_);
    phi0_ = 0.5 * std::log(1 - 2 * s.m / r_surface_) - s.phi;
  }
  double radius() const { return r_surface_; }

  // Surface value of P at angular frequency omega (code units).
  double surface_P(double omega) const { return integrate(omega, true, r_surface_ / steps_).P; }

  // The n-th (0 = F) eigenfrequency in kHz with the time unit t_unit_ms (G M_sun / c^3 in ms):
  // scans omega for sign changes of P(R) and bisects.
  std::vector<double> frequencies_khz(int count, double t_unit_ms, double f_max_khz = 12.0) const {
    std::vector<double> out;
    const double to_omega = 2 * std::numbers::pi * t_unit_ms;
    const int n = 240;
    double w_prev = 0.05 * to_omega, P_prev = surface_P(w_prev);
    for (int i = 1; i <= n && static_cast<int>(out.size()) < count; ++i) {
      const double w = (0.05 + (f_max_khz - 0.05) * i / n) * to_omega, P = surface_P(w);
      if ((P > 0) != (P_prev > 0)) {
        double a = w_prev, b = w, Pa = P_prev;
        for (int k = 0; k < 60; ++k) {
          const double c = 0.5 * (a + b), Pc = surface_P(c);
          if ((Pc > 0) == (Pa > 0)) a = c, Pa = Pc;
          else b = c;
        }
        out.push_back(0.5 * (a + b) / to_omega);
      }
      w_prev = w, P_prev = P;
    }
    return out;
  }

 private:
  struct State {
    double m = 0, p = 0, phi = 0, xi = 0, P = 0;
  };
  double energy(double p) const { return std::pow(p / K_, 1 / G_) + p / (G_ - 1); }

  // Derivatives at r; omega < 0: background only.
  State rhs(double r, const State& y, double omega, bool perturb) const {
    State d;
    const double p = std::max(y.p, 0.0), e = energy(p), m = y.m, D = r * (r - 2 * m);
    d.m = 4 * std::numbers::pi * r * r * e;
    const double phi1 = (m + 4 * std::numbers::pi * r * r * r * p) / D;
    d.phi = phi1;
    d.p = -(e + p) * phi1;
    if (!perturb) return d;
    const double lambda1 = (4 * std::numbers::pi * r * r * r * e - m) / D;
    const double num1 = d.m + 12 * std::numbers::pi * r * r * p + 4 * std::numbers::pi * r * r * r * d.p;
    const double phi2 = (num1 * D - (m + 4 * std::numbers::pi * r * r * r * p) * (2 * r - 2 * m - 2 * d.m * r)) / (D * D);
    const double e2l = r / (r - 2 * m), e2p = std::exp(-2 * y.phi);
    if (full_gr_) {  // y.xi is x = xi / r here
      const double pi = std::numbers::pi;
      d.xi = -(3 * y.xi + y.P / (G_ * p)) / r - d.p * y.xi / (e + p);
      d.P = y.xi * (omega * omega * e2l * e2p * (e + p) * r - 4 * d.p) +
            y.xi * (d.p * d.p * r / (e + p) - 8 * pi * e2l * (e + p) * p * r) +
            y.P * (d.p / (e + p) - 4 * pi * (e + p) * r * e2l);
      return d;
    }
    d.xi = -(2 / r + lambda1) * y.xi - y.P / (G_ * p);
    d.P = (e + p) * (omega * omega * e2l * e2p - phi2) * y.xi + d.p * d.xi - ((e + p) / (G_ * p) + 1) * phi1 * y.P;
    return d;
  }

  // RK4 with step h from the centre to the surface (where p would turn negative): the state and
  // (r_end) the radius of the last full step.
  State integrate(double omega, bool perturb, double h, double* r_end = nullptr) const {
    double r = 1e-6;
    State y;
    y.p = p_c_;
    y.m = 4.0 / 3.0 * std::numbers::pi * r * r * r * energy(p_c_);
    y.phi = perturb ? phi0_ : 0.0;
    y.xi = full_gr_ ? 1.0 : r;
    y.P = -3 * G_ * p_c_;
    auto add = [](const State& a, const State& b, double f) {
      return State{a.m + f * b.m, a.p + f * b.p, a.phi + f * b.phi, a.xi + f * b.xi, a.P + f * b.P};
    };
    for (;;) {
      const State k1 = rhs(r, y, omega, perturb);
      const State y2 = add(y, k1, h / 2);
      if (y2.p <= 0) break;
      const State k2 = rhs(r + h / 2, y2, omega, perturb);
      const State y3 = add(y, k2, h / 2);
      if (y3.p <= 0) break;
      const State k3 = rhs(r + h / 2, y3, omega, perturb);
      const State y4 = add(y, k3, h);
      if (y4.p <= 0) break;
      const State k4 = rhs(r + h, y4, omega, perturb);
      const State n = add(add(add(add(y, k1, h / 6), k2, h / 3), k3, h / 3), k4, h / 6);
      if (n.p <= 0) break;
      y = n;
      r += h;
    }
    if (r_end) *r_end = r;
    return y;
  }

  double K_, G_;
  bool full_gr_;
  int steps_;
  double p_c_ = 0, phi0_ = 0, r_surface_ = 0;
};

}  // namespace remnant::tov_test
