#pragma once
// Cold piecewise polytrope p = K_i rho^Gamma_i on [rho_{i-1}, rho_i), with K_i and the energy
// constants a_i fixed by continuity of p and eps: eps = a_i + K_i rho^(Gamma_i - 1) / (Gamma_i - 1).
#include <cmath>
#include <string>
#include <vector>

#include "EOS/errors.hpp"

namespace remnant::eos {

class PiecewisePolytrope {
 public:
  PiecewisePolytrope() = default;
  // K0: K of the first piece; gammas: one per piece; rho_bounds: the n-1 increasing divisions.
  PiecewisePolytrope(double K0, std::vector<double> gammas, std::vector<double> rho_bounds)
      : gam_(std::move(gammas)), rb_(std::move(rho_bounds)) {
    if (gam_.empty()) throw EosError("piecewise polytrope: no Gamma given");
    if (rb_.size() + 1 != gam_.size())
      throw EosError("piecewise polytrope: " + std::to_string(gam_.size()) + " Gammas need " +
                     std::to_string(gam_.size() - 1) + " density divisions, got " + std::to_string(rb_.size()));
    if (!(K0 > 0)) throw EosError("piecewise polytrope: K must be > 0");
    for (double g : gam_)
      if (!(g > 1)) throw EosError("piecewise polytrope: every Gamma must be > 1");
    for (std::size_t i = 0; i < rb_.size(); ++i)
      if (!(rb_[i] > 0) || (i > 0 && !(rb_[i] > rb_[i - 1])))
        throw EosError("piecewise polytrope: density divisions must be positive and increasing");
    K_.assign(gam_.size(), K0);
    a_.assign(gam_.size(), 0.0);
    for (std::size_t i = 0; i + 1 < gam_.size(); ++i) {
      const double r = rb_[i];
      K_[i + 1] = K_[i] * std::pow(r, gam_[i] - gam_[i + 1]);
      a_[i + 1] = a_[i] + K_[i] * std::pow(r, gam_[i] - 1) / (gam_[i] - 1) -
                  K_[i + 1] * std::pow(r, gam_[i + 1] - 1) / (gam_[i + 1] - 1);
    }
  }
  std::size_t piece(double rho) const {
    std::size_t i = 0;
    while (i < rb_.size() && rho >= rb_[i]) ++i;
    return i;
  }
  double press(double rho) const {
    const std::size_t i = piece(rho);
    return K_[i] * std::pow(rho, gam_[i]);
  }
  double eps(double rho) const {
    const std::size_t i = piece(rho);
    return a_[i] + K_[i] * std::pow(rho, gam_[i] - 1) / (gam_[i] - 1);
  }
  // p, eps and dp/drho at once.
  void eval(double rho, double& p, double& e, double& dpdrho) const {
    const std::size_t i = piece(rho);
    const double q = K_[i] * std::pow(rho, gam_[i] - 1);
    p = q * rho;
    e = a_[i] + q / (gam_[i] - 1);
    dpdrho = gam_[i] * q;
  }
  const std::vector<double>& gammas() const { return gam_; }
  const std::vector<double>& K() const { return K_; }

 private:
  std::vector<double> gam_, rb_, K_, a_;
};

}  // namespace remnant::eos
