// RotatingStar with a purely toroidal field (Kiuchi & Yoshida law, magnetic_law.hpp): the Euler
// equation with the Lorentz force holds where the model puts matter (the Bernoulli term is its exact
// integral), the virial identities with the magnetic terms, convergence with the radial resolution,
// regularity on the axis for m > 1, and bad field parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "RotatingStar/rns_solver.hpp"
#include "TOV/cold_slice.hpp"

namespace {
using namespace remnant::rotstar;
using remnant::tov::polytrope_slice;

RnsParameters paper_drns(int nr = 800) {  // the paper's magnetized-DRNS
  RnsParameters p;
  p.rho_central = 1.28e-3;
  p.law = RotationLaw::j_constant;
  p.omega = 2.575e-2;
  p.A2 = 70;
  p.field.K_m = 3;
  p.field.m = 1;
  p.nr = nr;
  return p;
}

RnsParameters xns_static(double m = 1, double K_m = 3.746) {  // XNS's NonRotMagToroPol2 (K = 110)
  RnsParameters p;
  p.rho_central = 1.366e-3;
  p.field.K_m = K_m;
  p.field.m = m;
  return p;
}

// The stationary Euler equation of a circular flow with a toroidal field, component d (0: r, 1: theta),
//   d ln h + d ln alpha - d ln W + u^t u_phi d Omega + d(alpha^2 varpi^2 B^2) / (2 rho h alpha^2 varpi^2) = 0,
// by centred differences of the model's at(); returned relative to the largest of its terms.
double euler_residual(const RotatingStarModel& m, double r, double th, int d, bool with_lorentz_force = true) {
  struct Terms {
    double lnh, lnalpha, lnW, omega, F, M2, rho_h, a2w2;
  };
  auto terms = [&](double rr, double tt) {
    const RnsPoint q = m.at(rr, tt);
    const double h = 1 + q.eps + q.press / q.rho, varpi = q.psi * q.psi * rr * std::sin(tt);
    const double omega = q.alpha * q.vel_phi - q.beta_phi, v = varpi * q.vel_phi;
    const double a2w2 = q.alpha * q.alpha * varpi * varpi;
    return Terms{std::log(h), std::log(q.alpha), std::log(q.W), omega, q.W * q.W * v * varpi / q.alpha, a2w2 * q.B * q.B,
                 q.rho * h, a2w2};
  };
  const double step = 1e-4;
  const Terms c = terms(r, th);
  const Terms p = d == 0 ? terms(r + step, th) : terms(r, th + step);
  const Terms n = d == 0 ? terms(r - step, th) : terms(r, th - step);
  auto D = [&](double Terms::*f) { return (p.*f - n.*f) / (2 * step); };
  const double t[] = {D(&Terms::lnh), D(&Terms::lnalpha), -D(&Terms::lnW), c.F * D(&Terms::omega),
                      with_lorentz_force ? D(&Terms::M2) / (2 * c.rho_h * c.a2w2) : 0.0};
  double sum = 0, scale = 0;
  for (double x : t) sum += x, scale = std::max(scale, std::abs(x));
  return std::abs(sum) / scale;
}

// Across the star (both models, r and theta components) the residual is the finite differences'
// (6e-8); without the Lorentz force it is the force's share (printed, > 1e-2).
TEST(MagnetisedStar, EulerEquationWithLorentzForceHolds) {
  const auto slice100 = polytrope_slice(100.0, 2.0, 0.5), slice110 = polytrope_slice(110.0, 2.0, 0.5);
  const RotatingStarModel drns(*slice100, paper_drns(400));
  RnsParameters ps = xns_static();
  ps.nr = 400;
  const RotatingStarModel stat(*slice110, ps);
  for (const RotatingStarModel* m : {&drns, &stat}) {
    double worst = 0, force_share = 0, without = 0;
    for (double f : {0.15, 0.4, 0.65, 0.85})
      for (double th : {0.3, 0.8, 1.2, 1.5}) {
        const double r = f * m->globals().r_e;
        for (int d = 0; d < 2; ++d) {
          worst = std::max(worst, euler_residual(*m, r, th, d));
          without = std::max(without, euler_residual(*m, r, th, d, false));
        }
        const RnsPoint q = m->at(r, th);
        force_share = std::max(force_share, q.B * q.B / (q.rho * (1 + q.eps + q.press / q.rho)));
      }
    std::printf("%s: max relative Euler residual %.2e (%.2e without the Lorentz force), max B^2/(rho h) %.2e\n",
                m == &drns ? "magnetized-DRNS" : "XNS static", worst, without, force_share);
    EXPECT_LT(worst, 1e-6);
    EXPECT_GT(without, 1e-2);  // the force matters: a wrong Bernoulli term fails the test
  }
}

// The paper's magnetized-DRNS at nr = 200, 400, 800: M_Komar, M_0 and H converge at second order,
// the xCFC virial identities with the field's E, S (and GRV2_GR's S^phi_phi) are small; B_max
// about 5e17 G as the paper says.
TEST(MagnetisedStar, PaperDrnsConvergesAndSatisfiesTheVirialIdentities) {
  const auto slice = polytrope_slice(100.0, 2.0, 0.5);
  RnsGlobals g[3];
  for (int k = 0; k < 3; ++k) {
    g[k] = RotatingStarModel(*slice, paper_drns(200 << k)).globals();
    std::printf("nr %4d: M_K %.8f M_0 %.8f H %.8f H/|W| %.6f T/|W| %.6f r_p/r_e %.6f B_max %.6e GRV2 %.2e GRV3 %.2e "
                "GRV2_GR %.2e GRV3_GR %.2e\n",
                200 << k, g[k].M_komar, g[k].M_rest, g[k].H_mag, g[k].H_over_W, g[k].T_over_W, g[k].axis_ratio, g[k].B_max,
                g[k].grv2, g[k].grv3, g[k].grv2_gr, g[k].grv3_gr);
  }
  auto order = [&](double RnsGlobals::*f) { return std::log2((g[0].*f - g[1].*f) / (g[1].*f - g[2].*f)); };
  for (auto [name, f] : {std::pair{"M_komar", &RnsGlobals::M_komar}, {"M_rest", &RnsGlobals::M_rest}, {"H_mag", &RnsGlobals::H_mag}}) {
    std::printf("order of %s: %.2f\n", name, order(f));
    EXPECT_GT(order(f), 1.6) << name;
  }
  EXPECT_LT(g[2].grv2, 1e-4);
  EXPECT_LT(g[2].grv3, 1e-5);
  EXPECT_LT(g[2].grv3_gr, 1e-5);  // M_Komar = M_ADM holds with the field's energy in the Komar integrand
  EXPECT_NEAR(g[2].B_max * 8.35e19, 5.2e17, 0.1e17);
  EXPECT_GT(g[2].H_over_W, 0.1);
}

// m = 2: B ~ varpi^3 on the axis, B^phi ~ R^2; the identity B = psi^2 R B^phi holds at any point.
TEST(MagnetisedStar, HigherIndexIsRegularOnTheAxis) {
  const auto slice = polytrope_slice(110.0, 2.0, 0.5);
  RnsParameters p = xns_static(2, 30.0);
  p.nr = 200;
  const RotatingStarModel m(*slice, p);
  const RnsGlobals& g = m.globals();
  std::printf("m = 2, K_m = 30: H/|W| %.4f B_max %.4e GRV2 %.2e GRV3 %.2e\n", g.H_over_W, g.B_max, g.grv2, g.grv3);
  EXPECT_GT(g.H_over_W, 1e-3);
  EXPECT_LT(g.grv3, 1e-4);
  for (double th : {1e-3, 0.5, 1.5}) {
    const RnsPoint q = m.at(3.0, th);
    EXPECT_NEAR(q.B, q.psi * q.psi * 3.0 * std::sin(th) * q.B_phi, 1e-14);
  }
  EXPECT_EQ(m.at(3.0, 0.0).B, 0.0);
  EXPECT_EQ(m.at(3.0, 0.0).B_phi, 0.0);
  EXPECT_EQ(m.at(2 * g.r_e, 1.5).B, 0.0);  // outside the star
}

TEST(MagnetisedStar, BadFieldParametersThrow) {
  const auto slice = polytrope_slice(100.0, 2.0, 0.5);
  auto message = [&](RnsParameters p) -> std::string {
    try {
      RotatingStarModel m(*slice, p);
    } catch (const RnsError& e) {
      return e.what();
    }
    return "no error";
  };
  RnsParameters p = paper_drns(100);
  p.field.K_m = -1;
  EXPECT_NE(message(p).find("K_m = -1 of the toroidal field must be >= 0"), std::string::npos) << message(p);
  p = paper_drns(100);
  p.field.m = 0.5;
  EXPECT_NE(message(p).find("m = 0.5 of the toroidal field must be >= 1"), std::string::npos) << message(p);
}

}  // namespace
