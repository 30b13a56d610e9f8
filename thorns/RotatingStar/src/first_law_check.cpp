#include "RotatingStar/first_law_check.hpp"

#include <cmath>

namespace remnant::rotstar {

FirstLawDeparture first_law_departure(const eos::Tabulated<>& table, const tov::ColdSlice& slice, double T, double rho_lo,
                                      double rho_hi, int samples) {
  FirstLawDeparture d;
  const double rel = 1e-6;  // central difference in rho (kinks of the interpolant are measure zero)
  for (int i = 0; i < samples; ++i) {
    const double rho = rho_lo * std::pow(rho_hi / rho_lo, (i + 0.5) / samples);
    const double ye = slice.at(slice.log_enthalpy(rho)).ye;
    const double deps = table.eps(rho * (1 + rel), T, ye) - table.eps(rho * (1 - rel), T, ye);
    const double r = deps / (2 * rel * rho) * rho * rho / table.press(rho, T, ye);
    const double dev = std::abs(r - 1);
    d.mean += dev / samples;
    if (dev > d.worst) d.worst = dev, d.rho_worst = rho;
  }
  return d;
}

}  // namespace remnant::rotstar
