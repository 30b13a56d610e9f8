#include "RotatingStar/eos_slice.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include "EOS/beta_equilibrium.hpp"

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

}  // namespace

std::unique_ptr<tov::ColdSlice> beta_slice(const eos::Tabulated<>& table, double T) {
  const eos::BetaSlice s = eos::beta_equilibrium_slice(table, temperature(table, T), densities(table));
  return tov::tabulated_slice(s.rho, s.press, s.eps, s.ye);
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
  return tov::tabulated_slice(rho, press, eps, yes);
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
