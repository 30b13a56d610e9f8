#pragma once
// The one internal representation of a tabulated EOS, whatever file format it came from.
//   axes: ln(rho) (code units), ln(T/MeV), Ye; each uniform.
//   thermo: per grid point kThermoStride doubles {ln(p+p_shift), ln(eps+eps_shift), cs2, s,
//           mu_e, mu_p, mu_n, pad}: one 64-byte line, [iye][iT][irho] order (rho fastest).
//   compo (optional): per grid point {Xa, Xh, Xn, Xp, Abar, Zbar}, same order.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "EOS/check_report.hpp"
#include "EOS/types.hpp"

namespace remnant::eos {

struct Axis {
  double x0 = 0, dx = 1, inv_dx = 0;  // inv_dx = 0 for a single-point axis
  int n = 0;
  double lo() const { return x0; }
  double hi() const { return x0 + dx * (n - 1); }
  double node(int i) const { return x0 + dx * i; }
};

// The cell of a uniform axis holding x: index i (0 .. n-2) and fraction f in [0, 1]; x outside the
// axis maps to its nearest end (NaN to the first node).
inline void locate(const Axis& a, double x, std::size_t& i, double& f) {
  double s = (x - a.x0) * a.inv_dx;
  if (!(s > 0)) s = 0;
  const double top = a.n > 1 ? double(a.n - 1) : 0.0;
  if (s > top) s = top;
  std::size_t k = std::size_t(s);
  if (a.n > 1 && k > std::size_t(a.n - 2)) k = a.n - 2;
  i = k;
  f = s - double(k);
}

enum ThermoField : int { kLogP = 0, kLogEps, kCs2, kEntropy, kMuE, kMuP, kMuN, kThermoFields };
inline constexpr int kThermoStride = 8;
enum CompoField : int { kXa = 0, kXh, kXn, kXp, kAbar, kZbar, kCompoFields };

struct TableData {
  std::string file;     // where it was read from
  std::string format;   // "StellarCollapse HDF5", "CompOSE ASCII", "CompOSE HDF5", ...
  Axis lrho, lT, ye;
  double eps_shift = 0;  // code units, > -min(eps)
  double p_shift = 0;    // code units, 0 unless the table has p <= 0
  bool has_chem = false;
  bool has_compo = false;
  std::vector<double> thermo;
  std::vector<double> compo;
  // Per (iye, irho) cell: 1 if eps rises with T along all four corner columns.
  std::vector<std::uint8_t> monotone_cell;
  // Per (iye, irho) cell, like monotone_cell: 1 if at any T a corner's cs2 exceeded 1 before the
  // clamp (acausal: the conserved variables may not determine the state uniquely; the other states
  // that share them lie at other T). Empty when none. (cs2 < 0, as in LS220's blend region near
  // 1e11 g/cm^3, is tiny there and not flagged: it would put a root scan in every cell of a shell.)
  std::vector<std::uint8_t> acausal_cell;
  Bounds bounds;
  CheckReport report;

  std::size_t points() const { return std::size_t(lrho.n) * lT.n * ye.n; }
  std::size_t index(int ir, int it, int iy) const {
    return (std::size_t(iy) * lT.n + it) * lrho.n + ir;
  }
  double at(int ir, int it, int iy, int field) const {
    return thermo[index(ir, it, iy) * kThermoStride + field];
  }
};

// Reader output before conversion: physical values in code units (T in MeV), [iye][iT][irho].
// Each field remembers the dataset it came from, so that checks can name it.
struct RawField {
  std::string dataset;
  std::vector<double> v;
  bool present() const { return !v.empty(); }
};

struct RawTable {
  std::string file, format;
  std::vector<double> rho, T, ye;          // axis values: rho (code), T (MeV), Ye
  std::string rho_dataset = "logrho", T_dataset = "logtemp", ye_dataset = "ye";
  RawField press, eps, cs2, entropy, mu_e, mu_p, mu_n;  // press, eps, cs2 required
  RawField Xa, Xh, Xn, Xp, Abar, Zbar;                  // optional composition
  double eps_shift = -1;  // preferred shift (code units); < 0: choose automatically
  std::size_t size() const { return rho.size() * T.size() * ye.size(); }
};

struct BuildOptions {
  bool clamp_cs2 = true;        // clamp cs2 into [0, 1] after counting the violations
  double axis_tolerance = 1e-6;  // allowed deviation from a uniform axis, in units of the spacing
  // Largest fraction of grid points that may fail the thermodynamic checks (cs2 outside [0, 1],
  // p not increasing with rho, eps not increasing with T) before loading stops with an error.
  double max_inconsistent_fraction = 0.1;
  // p may fall with rho (phase transitions, blend regions), but a fall by more than this factor
  // between neighbouring rho points is a corrupted value: an error.
  double max_pressure_drop = 10;
  // Thermal-index warning (check_thermal_index.cpp): a T interval whose (dp/deps)_rho / rho exceeds
  // thermal_index_max and thermal_index_jump times its neighbouring intervals' is counted.
  double thermal_index_max = 10;
  double thermal_index_jump = 10;
  // Replace the pressure of the outlying node of each such interval by log-linear interpolation in
  // log T from its column (repair_thermal_index.cpp; opt-in: it changes the table's data).
  bool repair_thermal_index = false;
};

// Checks a raw table (throws TableError for errors, records warnings) and builds the internal
// representation with its bounds.
std::shared_ptr<const TableData> build_table(RawTable raw, const BuildOptions& opts = {});

}  // namespace remnant::eos
