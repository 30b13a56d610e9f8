#include "TOV/tov_solver.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace remnant::tov {

namespace {

constexpr double kPi = std::numbers::pi;

// y = (r^2, m, ln(rbar / r), rest mass) as functions of H.
int tov_rhs(double H, const double y[], double dydH[], void* params) {
  const auto* slice = static_cast<const ColdSlice*>(params);
  const ColdState s = slice->at(H);
  const double r2 = std::max(y[0], 1e-300), r = std::sqrt(r2), m = y[1];
  const double e = s.rho * (1 + s.eps);
  const double drdH = -r * (r - 2 * m) / (m + 4 * kPi * r2 * r * s.press);
  const double metric = 1 / std::sqrt(1 - 2 * m / r);
  dydH[0] = 2 * r * drdH;
  dydH[1] = 4 * kPi * r2 * e * drdH;
  dydH[2] = (metric - 1) / r * drdH;
  dydH[3] = 4 * kPi * r2 * s.rho * metric * drdH;
  return GSL_SUCCESS;
}

}  // namespace

struct TovStar::Interp {
  gsl_interp* H = nullptr;
  gsl_interp* lnpsi = nullptr;
  ~Interp() {
    if (H) gsl_interp_free(H);
    if (lnpsi) gsl_interp_free(lnpsi);
  }
};

TovStar::TovStar(const ColdSlice& slice, double rho_central, int samples) : slice_(slice) {
  Hc_ = slice.log_enthalpy(rho_central);
  if (!(Hc_ > 0)) throw std::runtime_error("TOV: central density below the EOS slice");
  // Samples H_k = Hc (1 - (k/N)^2): dense in H near the centre (where r ~ sqrt(Hc - H)).
  const int N = samples;
  const ColdState c = slice.at(Hc_);
  const double ec = c.rho * (1 + c.eps), dH = Hc_ / (double(N) * N);
  const double r2 = 3 * dH / (2 * kPi * (ec + 3 * c.press)), r = std::sqrt(r2);
  double y[4] = {r2, 4 * kPi / 3 * ec * r2 * r, 2 * kPi / 3 * ec * r2, 4 * kPi / 3 * c.rho * r2 * r};
  gsl_odeiv2_system sys{tov_rhs, nullptr, 4, const_cast<ColdSlice*>(&slice)};
  gsl_odeiv2_driver* drv = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rkf45, -dH, 1e-12, 1e-12);
  std::vector<double> rs{0.0}, Hs{Hc_}, ls{0.0};
  double H = Hc_ - dH;
  rs.push_back(r);
  Hs.push_back(H);
  ls.push_back(y[2]);
  for (int k = 2; k <= N; ++k) {
    const double Hk = k == N ? 0.0 : Hc_ * (1 - double(k) * k / (double(N) * N));
    const int status = gsl_odeiv2_driver_apply(drv, &H, Hk, y);
    if (status != GSL_SUCCESS) {
      gsl_odeiv2_driver_free(drv);
      throw std::runtime_error("TOV: GSL integrator failed at H = " + std::to_string(H));
    }
    rs.push_back(std::sqrt(y[0]));
    Hs.push_back(Hk);
    ls.push_back(y[2]);
  }
  gsl_odeiv2_driver_free(drv);
  R_ = rs.back();
  M_ = y[1];
  M0_ = y[3];
  Rbar_ = 0.5 * (R_ - M_ + std::sqrt(R_ * R_ - 2 * M_ * R_));
  // Normalise ln(rbar/r) so that rbar(R) is the exterior isotropic radius.
  const double shift = std::log(Rbar_ / R_) - ls.back();
  rbar_.resize(rs.size());
  lnpsi_.resize(rs.size());
  for (std::size_t k = 0; k < rs.size(); ++k) {
    const double l = ls[k] + shift;  // ln(rbar/r) = -2 ln psi
    lnpsi_[k] = -0.5 * l;
    rbar_[k] = rs[k] * std::exp(l);
  }
  H_ = Hs;
  interp_ = std::make_shared<Interp>();
  interp_->H = gsl_interp_alloc(gsl_interp_steffen, rbar_.size());
  interp_->lnpsi = gsl_interp_alloc(gsl_interp_steffen, rbar_.size());
  gsl_interp_init(interp_->H, rbar_.data(), H_.data(), rbar_.size());
  gsl_interp_init(interp_->lnpsi, rbar_.data(), lnpsi_.data(), rbar_.size());
}

TovPoint TovStar::at(double rbar) const {
  TovPoint p;
  rbar = std::abs(rbar);
  if (rbar >= Rbar_) {
    const double q = M_ / (2 * rbar);
    p.psi = 1 + q;
    p.alpha = (1 - q) / (1 + q);
    return p;
  }
  const double H = std::max(gsl_interp_eval(interp_->H, rbar_.data(), H_.data(), rbar, nullptr), 0.0);
  const ColdState s = slice_.at(H);
  p.rho = s.rho;
  p.eps = s.eps;
  p.press = s.press;
  p.ye = s.ye;
  p.psi = std::exp(gsl_interp_eval(interp_->lnpsi, rbar_.data(), lnpsi_.data(), rbar, nullptr));
  p.alpha = std::sqrt(1 - 2 * M_ / R_) * std::exp(-H);
  p.inside = true;
  return p;
}

}  // namespace remnant::tov
