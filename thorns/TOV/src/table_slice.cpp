#include "TOV/table_slice.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "EOS/beta_equilibrium.hpp"
#include "enthalpy_curve.hpp"

namespace remnant::tov {
namespace {

// The state a cell of the evolution sees: Ye from beta equilibrium at (rho, T_min) and eps, p from the
// table's own (trilinear) interpolation at (rho, T_min, Ye), so that the temperature the evolution
// recovers from eps is T_min and its p(rho, T, Ye) is the star's p. The enthalpy-density relation
// H(rho) is integrated from the same values, piece by piece between the kinks of the interpolated
// table (enthalpy_curve.hpp), so that dp/dH = e + p: the star is in hydrostatic equilibrium with the
// table the evolution uses, at its nodes too.
class TableColdSlice final : public ColdSlice {
 public:
  TableColdSlice(const eos::Tabulated<>& table, EnthalpyCurve curve) : table_(table), curve_(std::move(curve)) {}
  ColdState at(double H) const override { return exact(std::exp(curve_.x_of(H))); }
  double log_enthalpy(double rho) const override { return curve_.H(std::log(rho)); }

 private:
  ColdState exact(double rho) const { return cold_beta_state(table_, rho); }
  const eos::Tabulated<>& table_;
  EnthalpyCurve curve_;
};

}  // namespace

ColdState cold_beta_state(const eos::Tabulated<>& table, double rho) {
  const double T = table.bounds().T_min;
  const double ye = eos::beta_equilibrium_ye(table, rho, T).ye;
  const eos::Thermo th = table.thermo(rho, T, ye);
  return {rho, th.eps, th.press, ye};
}

std::vector<double> slice_kinks(const eos::Tabulated<>& table, int scan_points) {
  const eos::Axis& a = table.table().lrho;
  const eos::Axis& y = table.table().ye;
  const double T = table.bounds().T_min;
  const double x_lo = std::log(table.bounds().rho_min), x_hi = std::log(table.bounds().rho_max);
  // The Ye cell of beta equilibrium at x (cells of the Ye axis; its kinks lie between them).
  auto ye_cell = [&](double x) {
    if (y.n < 2) return 0;
    const double ye = eos::beta_equilibrium_ye(table, std::exp(x), T).ye;
    return int(std::clamp(std::floor((ye - y.x0) * y.inv_dx), 0.0, double(y.n - 2)));
  };
  std::vector<double> kinks{x_lo};
  for (int i = 0; i + 1 < a.n; ++i) {
    const double xa = std::max(a.node(i), x_lo), xb = std::min(a.node(i + 1), x_hi);
    if (i > 0) kinks.push_back(xa);
    double xp = xa;
    int cp = ye_cell(xa + 1e-12 * a.dx);
    for (int k = 1; k <= scan_points; ++k) {
      const double xn = k == scan_points ? xb - 1e-12 * a.dx : xa + (xb - xa) * k / scan_points;
      const int cn = ye_cell(xn);
      if (cn != cp) {  // a Ye node between xp and xn: bisect for it
        double l = xp, r = xn;
        for (int it = 0; it < 60 && r - l > 1e-13 * a.dx; ++it) {
          const double m = 0.5 * (l + r);
          (ye_cell(m) == cp ? l : r) = m;
        }
        kinks.push_back(0.5 * (l + r));
      }
      xp = xn, cp = cn;
    }
  }
  kinks.push_back(x_hi);
  // Kinks closer than 1e-6 of a table interval merge (a piece needs room for its samples).
  std::vector<double> out{kinks.front()};
  for (std::size_t k = 1; k < kinks.size(); ++k)
    if (kinks[k] - out.back() > 1e-6 * a.dx || k + 1 == kinks.size()) out.push_back(kinks[k]);
  if (out.size() > 2 && out[out.size() - 1] - out[out.size() - 2] <= 1e-6 * a.dx) out.erase(out.end() - 2);
  return out;
}

std::unique_ptr<ColdSlice> cold_beta_slice(const eos::Tabulated<>& table, int points_per_interval) {
  const eos::Axis& a = table.table().lrho;
  if (a.n < 2) throw std::runtime_error(table.table().file + ": TOV needs a table with at least 2 densities");
  const std::vector<double> kinks = slice_kinks(table, 64);
  std::vector<SlicePiece> pieces;
  for (std::size_t k = 0; k + 1 < kinks.size(); ++k) {
    const double w = kinks[k + 1] - kinks[k];
    const int m = std::max(8, int(std::ceil(points_per_interval * w / a.dx)));
    SlicePiece s;
    s.x0 = kinks[k];
    s.dx = w / m;
    for (int j = 0; j <= m; ++j) {
      // The piece's own ends, evaluated a hair inside: the values of its smooth side of the kink.
      const double x = std::clamp(s.x0 + s.dx * j, kinks[k] + 1e-13 * w, kinks[k + 1] - 1e-13 * w);
      const ColdState c = cold_beta_state(table, std::exp(x));
      s.p.push_back(c.press);
      s.e.push_back(c.rho * (1 + c.eps));
    }
    pieces.push_back(std::move(s));
  }
  return std::make_unique<TableColdSlice>(table, EnthalpyCurve(pieces));
}

}  // namespace remnant::tov
