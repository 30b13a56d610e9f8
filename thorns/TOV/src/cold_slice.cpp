#include "TOV/cold_slice.hpp"

#include <gsl/gsl_interp.h>

#include <cmath>
#include <stdexcept>

namespace remnant::tov {
namespace {

class PolytropeSlice final : public ColdSlice {
 public:
  PolytropeSlice(double K, double G, double ye) : K_(K), G_(G), ye_(ye) {}
  ColdState at(double H) const override {
    const double hm1 = std::expm1(std::max(H, 0.0));  // h - 1 = Gamma/(Gamma-1) K rho^(Gamma-1)
    ColdState s;
    s.rho = std::pow(hm1 * (G_ - 1) / (G_ * K_), 1 / (G_ - 1));
    s.press = K_ * std::pow(s.rho, G_);
    s.eps = K_ * std::pow(s.rho, G_ - 1) / (G_ - 1);
    s.ye = ye_;
    return s;
  }
  double log_enthalpy(double rho) const override { return std::log1p(G_ / (G_ - 1) * K_ * std::pow(rho, G_ - 1)); }

 private:
  double K_, G_, ye_;
};

// Monotone (Steffen) interpolation of y(x) over increasing x.
class Monotone {
 public:
  Monotone(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    i_ = gsl_interp_alloc(gsl_interp_steffen, x_.size());
    gsl_interp_init(i_, x_.data(), y_.data(), x_.size());
    a_ = gsl_interp_accel_alloc();
  }
  ~Monotone() {
    gsl_interp_free(i_);
    gsl_interp_accel_free(a_);
  }
  Monotone(const Monotone&) = delete;
  Monotone& operator=(const Monotone&) = delete;
  double operator()(double x) const {
    x = std::min(std::max(x, x_.front()), x_.back());
    return gsl_interp_eval(i_, x_.data(), y_.data(), x, a_);
  }

 private:
  std::vector<double> x_, y_;
  gsl_interp* i_;
  gsl_interp_accel* a_;
};

class TabulatedSlice final : public ColdSlice {
 public:
  TabulatedSlice(const std::vector<double>& rho, const std::vector<double>& p, const std::vector<double>& eps,
                 const std::vector<double>& ye) {
    // H by the trapezoidal rule in dp / (e + p); keep only strictly increasing H.
    std::vector<double> H{0.0}, lr{std::log(rho[0])}, lp{std::log(p[0])}, e{eps[0]}, y{ye[0]};
    double h = 0;
    for (std::size_t i = 1; i < rho.size(); ++i) {
      const double w0 = rho[i - 1] * (1 + eps[i - 1]) + p[i - 1], w1 = rho[i] * (1 + eps[i]) + p[i];
      h += (p[i] - p[i - 1]) * 0.5 * (1 / w0 + 1 / w1);
      if (!(h > H.back())) continue;
      H.push_back(h);
      lr.push_back(std::log(rho[i]));
      lp.push_back(std::log(p[i]));
      e.push_back(eps[i]);
      y.push_back(ye[i]);
    }
    if (H.size() < 4) throw std::runtime_error("TOV: the cold slice has fewer than 4 points of increasing enthalpy");
    rho_of_H_ = std::make_unique<Monotone>(H, lr);
    p_of_H_ = std::make_unique<Monotone>(H, lp);
    eps_of_H_ = std::make_unique<Monotone>(H, e);
    ye_of_H_ = std::make_unique<Monotone>(H, y);
    H_of_lrho_ = std::make_unique<Monotone>(lr, H);
  }
  ColdState at(double H) const override {
    return {std::exp((*rho_of_H_)(H)), (*eps_of_H_)(H), std::exp((*p_of_H_)(H)), (*ye_of_H_)(H)};
  }
  double log_enthalpy(double rho) const override { return (*H_of_lrho_)(std::log(rho)); }

 private:
  std::unique_ptr<Monotone> rho_of_H_, p_of_H_, eps_of_H_, ye_of_H_, H_of_lrho_;
};

}  // namespace

std::unique_ptr<ColdSlice> polytrope_slice(double K, double Gamma, double ye) {
  return std::make_unique<PolytropeSlice>(K, Gamma, ye);
}

std::unique_ptr<ColdSlice> tabulated_slice(std::vector<double> rho, std::vector<double> press, std::vector<double> eps,
                                           std::vector<double> ye) {
  return std::make_unique<TabulatedSlice>(rho, press, eps, ye);
}

}  // namespace remnant::tov
