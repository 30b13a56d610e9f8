#include "RotatingStar/eos_slice.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "EOS/beta_equilibrium.hpp"
#include "EOS/piecewise_polytrope.hpp"

namespace remnant::rotstar {

namespace {

std::vector<double> densities(const eos::Tabulated<>& table) {
  const auto& b = table.bounds();
  std::vector<double> rhos;
  const int n = 800;
  for (int i = 0; i < n; ++i) rhos.push_back(b.rho_min * std::pow(b.rho_max / b.rho_min, double(i) / (n - 1)));
  rhos.front() = b.rho_min;
  rhos.back() = b.rho_max;
  return rhos;
}

double temperature(const eos::Tabulated<>& table, double T) {
  const auto& b = table.bounds();
  if (T < 0) return b.T_min;
  if (!(T >= b.T_min && T <= b.T_max)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "slice temperature %g MeV is outside the table's range [%g, %g]", T, b.T_min, b.T_max);
    throw std::runtime_error(msg);
  }
  return T;
}

class PiecewisePolytropeSlice final : public tov::ColdSlice {
 public:
  PiecewisePolytropeSlice(double K0, const std::vector<double>& gammas, const std::vector<double>& rho_bounds, double ye)
      : pp_(K0, gammas, rho_bounds), ye_(ye) {
    // eps = a_i + K_i rho^(Gamma_i - 1) / (Gamma_i - 1) on piece i: a_i from the EOS at the piece's
    // lower division; H at the divisions.
    a_.assign(gammas.size(), 0.0);
    for (std::size_t i = 1; i < gammas.size(); ++i) {
      const double r = rho_bounds[i - 1];
      a_[i] = pp_.eps(r) - pp_.K()[i] * std::pow(r, gammas[i] - 1) / (gammas[i] - 1);
      H_bounds_.push_back(log_enthalpy(r));
    }
  }
  tov::ColdState at(double H) const override {
    std::size_t i = 0;
    while (i < H_bounds_.size() && H >= H_bounds_[i]) ++i;
    const double g = pp_.gammas()[i], K = pp_.K()[i];
    // h = 1 + a_i + Gamma K rho^(Gamma - 1) / (Gamma - 1)
    const double q = std::max(std::expm1(std::max(H, 0.0)) - a_[i], 0.0) * (g - 1) / (g * K);
    tov::ColdState s;
    s.rho = std::pow(q, 1 / (g - 1));
    s.press = pp_.press(s.rho);
    s.eps = s.rho > 0 ? pp_.eps(s.rho) : 0.0;
    s.ye = ye_;
    return s;
  }
  double log_enthalpy(double rho) const override { return std::log1p(pp_.eps(rho) + pp_.press(rho) / rho); }

 private:
  eos::PiecewisePolytrope pp_;
  double ye_;
  std::vector<double> a_, H_bounds_;
};

// A table slice at fixed T: rho(H) and Ye from the sampled slice, eps and p from the table's own
// interpolation at (rho, T, Ye), so that the temperature the evolution recovers from eps on the grid
// is the slice's (the sampled eps differs from the table's by ~1e-4 in places, which in degenerate
// matter is a temperature error of ~0.5 MeV at T = 1 MeV), as the TOV thorn's table slice does.
class TableSlice final : public tov::ColdSlice {
 public:
  TableSlice(const eos::Tabulated<>& table, double T, std::unique_ptr<tov::ColdSlice> sampled)
      : table_(table), T_(T), sampled_(std::move(sampled)) {}
  tov::ColdState at(double H) const override {
    tov::ColdState s = sampled_->at(H);
    if (s.rho >= table_.bounds().rho_min) {
      const eos::Thermo th = table_.thermo(s.rho, T_, s.ye);
      s.eps = th.eps;
      s.press = th.press;
    }
    return s;
  }
  double log_enthalpy(double rho) const override { return sampled_->log_enthalpy(rho); }

 private:
  const eos::Tabulated<>& table_;
  double T_;
  std::unique_ptr<tov::ColdSlice> sampled_;
};

}  // namespace

std::unique_ptr<tov::ColdSlice> piecewise_polytrope_slice(double K0, const std::vector<double>& gammas,
                                                          const std::vector<double>& rho_bounds, double ye) {
  return std::make_unique<PiecewisePolytropeSlice>(K0, gammas, rho_bounds, ye);
}

std::unique_ptr<tov::ColdSlice> beta_slice(const eos::Tabulated<>& table, double T) {
  T = temperature(table, T);
  const eos::BetaSlice s = eos::beta_equilibrium_slice(table, T, densities(table));
  return std::make_unique<TableSlice>(table, T, tov::tabulated_slice(s.rho, s.press, s.eps, s.ye));
}

std::unique_ptr<tov::ColdSlice> fixed_ye_slice(const eos::Tabulated<>& table, double ye, double T) {
  const auto& b = table.bounds();
  if (!(ye >= b.ye_min && ye <= b.ye_max)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "slice Ye %g is outside the table's range [%g, %g]", ye, b.ye_min, b.ye_max);
    throw std::runtime_error(msg);
  }
  T = temperature(table, T);
  std::vector<double> rho = densities(table), press, eps, yes(rho.size(), ye);
  for (double r : rho) {
    press.push_back(table.press(r, T, ye));
    eps.push_back(table.eps(r, T, ye));
  }
  return std::make_unique<TableSlice>(table, T, tov::tabulated_slice(rho, press, eps, yes));
}

std::string check_density_in_table(const eos::Tabulated<>& table, double rho_c) {
  const auto& b = table.bounds();
  if (rho_c > b.rho_min && rho_c < b.rho_max) return "";
  char msg[256];
  std::snprintf(msg, sizeof msg, "central density %g is outside the EOS table's density range (%g, %g) (code units)", rho_c,
                b.rho_min, b.rho_max);
  return msg;
}

}  // namespace remnant::rotstar
