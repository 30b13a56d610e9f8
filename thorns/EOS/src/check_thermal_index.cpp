// Thermal-index check: a node whose pressure jumps with T while eps barely moves.
// Along T at fixed (rho, Ye) the table interpolates log(p + p_shift) and log(eps + eps_shift)
// linearly in log T, so on one T interval the interpolant's mean (dp/deps)_rho is exactly the chord
// (p1 - p0) / (eps1 - eps0) of the node values, whatever the shifts: that chord over rho is the
// index checked here. Physical matter has Gamma_th - 1 of order 0.3 .. 2; an interval far above its
// neighbours (SFHo reduced: 158 next to 5.0 at 1.377e-4, T_min, Ye 0.0721) turns the slightest
// heating of cold matter there into a pressure step.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "EOS/units.hpp"
#include "table_checks.hpp"

namespace remnant::eos {

double thermal_index(const RawTable& raw, std::size_t ir, std::size_t it, std::size_t iy) {
  const std::size_t nr = raw.rho.size(), nt = raw.T.size();
  const std::size_t i = (iy * nt + it) * nr + ir, j = i + nr;
  const double de = raw.eps.v[j] - raw.eps.v[i];
  return de > 0 ? (raw.press.v[j] - raw.press.v[i]) / de / raw.rho[ir] : std::nan("");
}

bool thermal_index_jumps(const std::vector<double>& g, std::size_t it, const BuildOptions& opts, double& nb) {
  if (!(g[it] > opts.thermal_index_max)) return false;
  nb = -1;  // largest |index| of the neighbouring intervals that have one
  if (it > 0 && std::isfinite(g[it - 1])) nb = std::max(nb, std::abs(g[it - 1]));
  if (it + 1 < g.size() && std::isfinite(g[it + 1])) nb = std::max(nb, std::abs(g[it + 1]));
  return nb >= 0 && g[it] > opts.thermal_index_jump * nb;
}

void check_thermal_index(const RawTable& raw, const BuildOptions& opts, CheckReport& rep) {
  const std::size_t nr = raw.rho.size(), nt = raw.T.size(), ny = raw.ye.size();
  if (nt < 3) return;  // no neighbouring interval to compare with
  const auto& p = raw.press.v;
  const auto& e = raw.eps.v;
  const auto at = [&](std::size_t ir, std::size_t it, std::size_t iy) { return (iy * nt + it) * nr + ir; };
  std::size_t flagged = 0;
  double worst = 0, worst_nb = 0;
  std::size_t wr = 0, wt = 0, wy = 0;
  std::vector<double> g(nt - 1);
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ir = 0; ir < nr; ++ir) {
      for (std::size_t it = 0; it + 1 < nt; ++it) g[it] = thermal_index(raw, ir, it, iy);
      for (std::size_t it = 0; it + 1 < nt; ++it) {
        double nb;
        if (!thermal_index_jumps(g, it, opts, nb)) continue;
        ++flagged;
        if (g[it] > worst) worst = g[it], worst_nb = nb, wr = ir, wt = it, wy = iy;
      }
    }
  if (!flagged) return;
  const std::size_t i = at(wr, wt, wy), j = at(wr, wt + 1, wy);
  std::ostringstream m;
  m.precision(4);
  m << "thermal index (dp/deps)_rho / rho jumps on " << flagged << " T interval(s) (index > "
    << opts.thermal_index_max << " and > " << opts.thermal_index_jump
    << "x its neighbouring intervals'); worst at (irho, iT, iYe) = (" << wr << ", " << wt << ", " << wy
    << "): rho = " << raw.rho[wr] * units::density_cgs << " g/cm^3 (" << raw.rho[wr] << " code), T = " << raw.T[wt]
    << " .. " << raw.T[wt + 1] << " MeV, Ye = " << raw.ye[wy] << ": index " << worst << " against " << worst_nb
    << " on the neighbouring interval (p changes by " << 100 * (p[j] - p[i]) / std::abs(p[i]) << " %, eps by "
    << (e[j] - e[i]) << "). The table is usable, but cold matter interpolating such a node (a star near T = "
    << raw.T[wt] << " MeV) turns the slightest heating into a pressure step (a drift that does not converge "
    << "with resolution); EOS::table_repair_thermal_index = true replaces such a node's pressure at load time";
  rep.warn(raw.file, "thermal_index", flagged, m.str());
}

}  // namespace remnant::eos
