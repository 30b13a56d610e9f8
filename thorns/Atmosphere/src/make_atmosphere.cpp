// The EOS-handle entry point and a one-line description for the log.
#include <cstdio>

#include "Atmosphere/make_atmosphere.hpp"
#include "EOS/units.hpp"

namespace remnant::atmosphere {

Atmosphere make_atmosphere(const eos::EOS& eos, const AtmosphereConfig& c) {
  return eos.visit([&](const auto& e) { return make_atmosphere(e, c); });
}

std::string describe(const Atmosphere& a) {
  const char* src = a.ye_source == YeSource::parameter          ? "parameter"
                    : a.ye_source == YeSource::beta_equilibrium ? "beta equilibrium"
                    : a.ye_source == YeSource::beta_nearest_end ? "no beta-equilibrium root, nearest table end"
                                                                : "table without chemical potentials, parameter";
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "rho_thr = %.6e, rho_atm = %.6e (code; %.6e g/cm^3), eps = %.6e, p = %.6e, T = %.6e MeV, "
                "Ye = %.6f (%s), cs2 = %.6e",
                a.rho_thr, a.rho, a.rho / units::rho_cgs_to_code, a.eps, a.press, a.T, a.ye, src, a.cs2);
  return buf;
}

}  // namespace remnant::atmosphere
