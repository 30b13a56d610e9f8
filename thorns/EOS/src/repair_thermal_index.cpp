// Opt-in repair of thermal-index outliers (EOS::table_repair_thermal_index): a T interval whose
// (dp/deps)_rho / rho jumps far above its neighbours' (check_thermal_index.cpp) has one node whose
// pressure does not follow its column. Of the interval's two nodes, the one replaced is the one whose
// new pressure -- log p linear in log T through its column's neighbouring nodes, the way the table is
// interpolated (extrapolated from the next two nodes at T_min or T_max) -- leaves the smaller largest
// index on the intervals around it; a replacement that still jumps is not made (the check then
// warns). eps, cs2 and the rest are kept: the reduced SFHo node (1.377e-4, T_min, Ye 0.0721) has eps
// 2.0e-6 below the next temperature's (0.03 %, plausible for cold matter) and p 8.2 % below it.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "EOS/units.hpp"
#include "table_checks.hpp"

namespace remnant::eos {
namespace {

// log p linear in log T through (T_a, p_a), (T_b, p_b), at T; linear in log T where a p is <= 0.
double pressure_along_T(double Ta, double pa, double Tb, double pb, double T) {
  const double s = std::log(T / Ta) / std::log(Tb / Ta);
  if (pa > 0 && pb > 0) return pa * std::pow(pb / pa, s);
  return pa + (pb - pa) * s;
}

// Pressure of node k of a column from its neighbouring nodes (k - 1, k + 1, or the next two).
double replacement(const RawTable& raw, std::size_t ir, std::size_t k, std::size_t iy) {
  const std::size_t nr = raw.rho.size(), nt = raw.T.size();
  const auto p = [&](std::size_t it) { return raw.press.v[(iy * nt + it) * nr + ir]; };
  const std::size_t a = k == 0 ? 1 : k == nt - 1 ? nt - 3 : k - 1, b = k == 0 ? 2 : k == nt - 1 ? nt - 2 : k + 1;
  return pressure_along_T(raw.T[a], p(a), raw.T[b], p(b), raw.T[k]);
}

}  // namespace

void repair_thermal_index(RawTable& raw, const BuildOptions& opts, CheckReport& rep) {
  const std::size_t nr = raw.rho.size(), nt = raw.T.size(), ny = raw.ye.size();
  if (!opts.repair_thermal_index || nt < 3) return;
  std::size_t repaired = 0;
  double worst_change = 0;
  std::ostringstream worst;
  worst.precision(4);
  std::vector<double> g(nt - 1);
  const auto column = [&](std::size_t ir, std::size_t iy) {
    for (std::size_t it = 0; it + 1 < nt; ++it) g[it] = thermal_index(raw, ir, it, iy);
  };
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ir = 0; ir < nr; ++ir) {
      column(ir, iy);
      for (std::size_t it = 0; it + 1 < nt; ++it) {
        double nb;
        if (!thermal_index_jumps(g, it, opts, nb)) continue;
        const double before = g[it];
        // Try both nodes of the interval; keep the one that leaves the smaller largest index nearby.
        double best_p = 0, best_max = INFINITY;
        std::size_t best_k = 0;
        for (std::size_t k : {it, it + 1}) {
          double& pk = raw.press.v[(iy * nt + k) * nr + ir];
          const double old = pk;
          pk = replacement(raw, ir, k, iy);
          column(ir, iy);
          double largest = 0, unused;
          bool jumps = false;
          for (std::size_t j = k > 0 ? k - 1 : 0; j <= std::min(k, nt - 2); ++j) {
            largest = std::max(largest, std::abs(g[j]));
            jumps = jumps || thermal_index_jumps(g, j, opts, unused);
          }
          if (!jumps && largest < best_max) best_max = largest, best_p = pk, best_k = k;
          pk = old;
        }
        column(ir, iy);
        if (!std::isfinite(best_max)) continue;  // no single-node fix: the check warns
        double& pk = raw.press.v[(iy * nt + best_k) * nr + ir];
        const double old = pk;
        pk = best_p;
        column(ir, iy);
        if (std::abs(best_p / old - 1) >= worst_change) {
          worst_change = std::abs(best_p / old - 1);
          worst.str("");
          worst << "(irho, iT, iYe) = (" << ir << ", " << best_k << ", " << iy << "): rho = " << raw.rho[ir] * units::density_cgs
                << " g/cm^3, T = " << raw.T[best_k] << " MeV, Ye = " << raw.ye[iy] << ": p " << old << " -> " << best_p
                << " (code, " << 100 * (best_p / old - 1) << " %), index of T interval " << it << " " << before << " -> "
                << g[it];
        }
        ++repaired;
      }
    }
  if (!repaired) return;
  std::ostringstream m;
  m << "EOS::table_repair_thermal_index: replaced the pressure of " << repaired
    << " node(s) whose T interval's thermal index jumped (log p interpolated in log T from the column's "
       "neighbouring nodes); largest change at "
    << worst.str();
  rep.warn(raw.file, "thermal_index_repair", repaired, m.str());
}

}  // namespace remnant::eos
