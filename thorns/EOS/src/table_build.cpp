// Load-time checks and conversion of a RawTable into the internal TableData.
// Errors (TableError): missing or mis-sized fields, bad axes, NaN/Inf in thermodynamic data,
// eps + shift <= 0. Counted warnings: cs2 outside [0, 1] (clamped), eps not increasing with T,
// p <= 0 (stored with a shift), NaN in composition (set to 0), thermal-index jumps along T (with
// BuildOptions::repair_thermal_index their nodes' pressure is replaced first, and that is a warning).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "EOS/errors.hpp"
#include "EOS/table.hpp"
#include "table_checks.hpp"

namespace remnant::eos {
namespace {

struct Where {
  int ir, it, iy;
};
Where where(const RawTable& raw, std::size_t i) {
  const std::size_t nr = raw.rho.size(), nt = raw.T.size();
  return {int(i % nr), int((i / nr) % nt), int(i / (nr * nt))};
}
std::string at_str(const RawTable& raw, std::size_t i) {
  auto w = where(raw, i);
  std::ostringstream o;
  o.precision(6);
  o << "(irho, iT, iYe) = (" << w.ir << ", " << w.it << ", " << w.iy << "): rho = " << raw.rho[w.ir]
    << " (code), T = " << raw.T[w.it] << " MeV, Ye = " << raw.ye[w.iy];
  return o.str();
}

Axis make_axis(const RawTable& raw, const std::vector<double>& x, bool log, const std::string& ds, double tol) {
  if (x.empty()) throw TableError(raw.file, ds, "axis is empty");
  std::vector<double> u(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || (log && x[i] <= 0))
      throw TableError(raw.file, ds, "axis value " + std::to_string(i) + " is " + std::to_string(x[i]) +
                                         (log ? " (must be finite and > 0)" : " (must be finite)"));
    u[i] = log ? std::log(x[i]) : x[i];
  }
  Axis a;
  a.n = int(u.size());
  a.x0 = u.front();
  if (a.n == 1) return a;  // dx = 1, inv_dx = 0: a single point
  a.dx = (u.back() - u.front()) / (a.n - 1);
  if (!(a.dx > 0)) throw TableError(raw.file, ds, "axis is not increasing");
  a.inv_dx = 1 / a.dx;
  for (int i = 0; i < a.n; ++i) {
    if (i > 0 && !(u[i] > u[i - 1]))
      throw TableError(raw.file, ds, "axis is not strictly increasing at index " + std::to_string(i));
    if (std::abs(u[i] - a.node(i)) > tol * a.dx)
      throw TableError(raw.file, ds,
                       std::string("axis is not uniform") + (log ? " in log" : "") + " at index " +
                           std::to_string(i) + " (off by " + std::to_string(std::abs(u[i] - a.node(i)) / a.dx) +
                           " spacings); regrid the table");
  }
  return a;
}

void require(const RawTable& raw, const RawField& f, const char* what) {
  if (!f.present()) throw TableError(raw.file, f.dataset.empty() ? what : f.dataset, std::string(what) + " is missing");
  if (f.v.size() != raw.size())
    throw TableError(raw.file, f.dataset, std::string(what) + " has " + std::to_string(f.v.size()) +
                                              " values, the grid has " + std::to_string(raw.size()));
}

void require_finite(const RawTable& raw, const RawField& f) {
  std::size_t bad = 0, first = 0;
  for (std::size_t i = 0; i < f.v.size(); ++i)
    if (!std::isfinite(f.v[i]) && bad++ == 0) first = i;
  if (bad)
    throw TableError(raw.file, f.dataset, std::to_string(bad) + " NaN/Inf values, first at " + at_str(raw, first));
}

// p along rho at fixed (T, Ye): pairs where it falls are counted (a warning; LS220-type
// tables have a few in the nuclear/NSE blend region) and their points marked inconsistent; a fall by
// more than max_pressure_drop between neighbours is a corrupted value and an error.
void check_pressure_monotonic(const RawTable& raw, const BuildOptions& opts, std::vector<std::uint8_t>& inconsistent,
                              CheckReport& rep) {
  const std::size_t nr = raw.rho.size(), nt = raw.T.size(), ny = raw.ye.size();
  const auto& p = raw.press.v;
  std::size_t bad = 0, first = 0;
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t it = 0; it < nt; ++it)
      for (std::size_t ir = 0; ir + 1 < nr; ++ir) {
        const std::size_t i = (iy * nt + it) * nr + ir;
        if (p[i + 1] >= p[i]) continue;  // equal: radiation-dominated corners
        if (bad++ == 0) first = i;
        inconsistent[i] = inconsistent[i + 1] = 1;
        if (p[i + 1] > 0 && p[i + 1] * opts.max_pressure_drop < p[i]) {  // p <= 0: its own warning
          std::ostringstream m;
          m.precision(6);
          m << "p falls from " << p[i] << " to " << p[i + 1] << " (code units) between neighbouring rho points at "
            << at_str(raw, i) << " and the next rho: a corrupted value (p must rise with rho; a fall by more than a "
            << "factor " << opts.max_pressure_drop << " is not physical)";
          throw TableError(raw.file, raw.press.dataset, m.str());
        }
      }
  if (bad)
    rep.warn(raw.file, raw.press.dataset, bad,
             "p falls with rho between adjacent rho points, first at " + at_str(raw, first));
}

// Flags the (up to 4) (iye, irho) cells that have grid point i's column as a corner.
void mark_acausal(TableData& t, std::size_t i) {
  const std::size_t nr = t.lrho.n, nt = t.lT.n, ny = t.ye.n;
  if (t.acausal_cell.empty()) t.acausal_cell.assign(nr * ny, 0);
  const std::size_t ir = i % nr, iy = i / (nr * nt);
  for (std::size_t dy = 0; dy <= std::min<std::size_t>(iy, 1); ++dy)
    for (std::size_t dr = 0; dr <= std::min<std::size_t>(ir, 1); ++dr) t.acausal_cell[(iy - dy) * nr + (ir - dr)] = 1;
}

}  // namespace

std::shared_ptr<const TableData> build_table(RawTable raw, const BuildOptions& opts) {
  auto t = std::make_shared<TableData>();
  t->file = raw.file;
  t->format = raw.format;
  t->lrho = make_axis(raw, raw.rho, true, raw.rho_dataset, opts.axis_tolerance);
  t->lT = make_axis(raw, raw.T, true, raw.T_dataset, opts.axis_tolerance);
  t->ye = make_axis(raw, raw.ye, false, raw.ye_dataset, opts.axis_tolerance);
  for (std::size_t i = 0; i < raw.ye.size(); ++i)
    if (!(raw.ye[i] >= 0 && raw.ye[i] <= 1))
      throw TableError(raw.file, raw.ye_dataset,
                       "Ye axis value " + std::to_string(i) + " is " + std::to_string(raw.ye[i]) +
                           ": an electron fraction must lie in [0, 1]");
  const std::size_t n = raw.size(), nr = raw.rho.size(), nt = raw.T.size(), ny = raw.ye.size();
  CheckReport& rep = t->report;

  require(raw, raw.press, "pressure");
  require(raw, raw.eps, "specific internal energy");
  require(raw, raw.cs2, "sound speed");
  for (RawField* f : {&raw.press, &raw.eps, &raw.cs2}) require_finite(raw, *f);
  if (!raw.entropy.present()) {
    raw.entropy = {"entropy", std::vector<double>(n, 0.0)};
    rep.info(raw.file, "entropy", 0, "no entropy in the table: s = 0");
  }
  require(raw, raw.entropy, "entropy");
  require_finite(raw, raw.entropy);
  t->has_chem = raw.mu_e.present() && raw.mu_p.present() && raw.mu_n.present();
  if (t->has_chem)
    for (RawField* f : {&raw.mu_e, &raw.mu_p, &raw.mu_n}) require(raw, *f, "chemical potential"), require_finite(raw, *f);
  else
    rep.info(raw.file, "mu_e", 0, "no chemical potentials: beta equilibrium unavailable");
  // Composition is all six fields or none: a partial set is reported and not used (no zeros
  // standing in for a missing Xa).
  {
    std::string missing, present;
    const std::pair<RawField*, const char*> fields[] = {{&raw.Xa, "Xa"},     {&raw.Xh, "Xh"},     {&raw.Xn, "Xn"},
                                                        {&raw.Xp, "Xp"},     {&raw.Abar, "Abar"}, {&raw.Zbar, "Zbar"}};
    for (const auto& [f, name] : fields) (f->present() ? present : missing) += std::string(" ") + name;
    t->has_compo = missing.empty();
    if (!t->has_compo && !present.empty())
      rep.warn(raw.file, "composition", 0,
               "incomplete composition: has" + present + " but not" + missing + "; composition disabled");
  }
  if (t->has_compo) {
    for (RawField* f : {&raw.Xa, &raw.Xh, &raw.Xn, &raw.Xp, &raw.Abar, &raw.Zbar}) {
      require(raw, *f, "composition");
      std::size_t bad = 0, first = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(f->v[i])) {
          if (bad++ == 0) first = i;
          f->v[i] = 0;
        }
      if (bad) rep.warn(raw.file, f->dataset, bad, "NaN/Inf composition set to 0, first at " + at_str(raw, first));
    }
  }

  repair_thermal_index(raw, opts, rep);  // opt-in, before anything reads the pressure

  // Pressure is interpolated in log: shift it when the table has p <= 0.
  const auto [pmin_it, pmax_it] = std::minmax_element(raw.press.v.begin(), raw.press.v.end());
  const double pmin = *pmin_it, pmax = *pmax_it;
  if (pmin <= 0) {
    std::size_t cnt = std::count_if(raw.press.v.begin(), raw.press.v.end(), [](double p) { return p <= 0; });
    double pos_min = pmax;
    for (double p : raw.press.v)
      if (p > 0) pos_min = std::min(pos_min, p);
    t->p_shift = pmin < 0 ? -2 * pmin : 0.5 * pos_min;
    rep.warn(raw.file, raw.press.dataset, cnt,
             "p <= 0: pressure interpolated as log(p + " + std::to_string(t->p_shift) + ")");
  }
  // Energy shift: the file's, or automatic when eps <= 0 somewhere.
  const auto [emin_it, emax_it] = std::minmax_element(raw.eps.v.begin(), raw.eps.v.end());
  const double emin = *emin_it, emax = *emax_it;
  t->eps_shift = raw.eps_shift >= 0 ? raw.eps_shift : (emin <= 0 ? std::max(-2 * emin, 1e-3) : 0.0);
  if (emin + t->eps_shift <= 0)
    throw TableError(raw.file, raw.eps.dataset,
                     "eps + energy_shift <= 0 at " + at_str(raw, emin_it - raw.eps.v.begin()) +
                         ": energy_shift too small");

  // Thermodynamic consistency, point by point: a point fails if its cs2 leaves [0, 1] or it is an
  // end of an adjacent pair along which p does not rise with rho or eps does not rise with T.
  std::vector<std::uint8_t> inconsistent(n, 0);
  check_pressure_monotonic(raw, opts, inconsistent, rep);

  // cs2 must lie in [0, 1].
  {
    std::size_t bad = 0, first = 0;
    double lo = 0, hi = 1;
    for (std::size_t i = 0; i < n; ++i) {
      double& c = raw.cs2.v[i];
      if (c < 0 || c > 1) {
        inconsistent[i] = 1;
        if (c > 1) mark_acausal(*t, i);
        if (bad++ == 0) first = i;
        lo = std::min(lo, c), hi = std::max(hi, c);
        if (opts.clamp_cs2) c = std::clamp(c, 0.0, 1.0);
      }
    }
    if (bad) {
      std::ostringstream m;
      m << "cs2 outside [0, 1] (range " << lo << " .. " << hi << "), first at " << at_str(raw, first)
        << (opts.clamp_cs2 ? "; clamped to [0, 1]" : "");
      rep.warn(raw.file, raw.cs2.dataset, bad, m.str());
    }
  }

  // eps must increase with T for the eps -> T inversion to be unique.
  std::vector<std::uint8_t> mono_col(nr * ny, 1);
  {
    std::size_t bad = 0, first = 0;
    for (std::size_t iy = 0; iy < ny; ++iy)
      for (std::size_t it = 0; it + 1 < nt; ++it)
        for (std::size_t ir = 0; ir < nr; ++ir) {
          const std::size_t i = (iy * nt + it) * nr + ir;
          if (!(raw.eps.v[i + nr] > raw.eps.v[i])) {
            if (bad++ == 0) first = i;
            mono_col[iy * nr + ir] = 0;
            inconsistent[i] = inconsistent[i + nr] = 1;
          }
        }
    if (bad)
      rep.warn(raw.file, raw.eps.dataset, bad,
               "eps does not increase with T between adjacent T points, first at " + at_str(raw, first) +
                   "; eps -> T takes the root nearest the temperature guess there");
  }
  check_thermal_index(raw, opts, rep);  // a warning only: not counted as inconsistent
  {
    const std::size_t bad = std::count(inconsistent.begin(), inconsistent.end(), std::uint8_t(1));
    const double fraction = double(bad) / double(n);
    std::ostringstream m;
    m << "thermodynamic checks (cs2 in [0, 1], p rising with rho, eps rising with T) fail at " << bad << " of " << n
      << " points (" << 100 * fraction << " %); the limit is " << 100 * opts.max_inconsistent_fraction << " %";
    if (fraction > opts.max_inconsistent_fraction)
      throw TableError(raw.file, raw.press.dataset,
                       m.str() + ": the table is not a usable EOS (raise EOS::table_max_inconsistent_fraction only "
                                 "if you know why)");
    if (bad) rep.info(raw.file, "", 0, m.str());
  }
  t->monotone_cell.assign(nr * ny, 1);
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ir = 0; ir < nr; ++ir) {
      const std::size_t iy1 = std::min(iy + 1, ny - 1), ir1 = std::min(ir + 1, nr - 1);
      t->monotone_cell[iy * nr + ir] = mono_col[iy * nr + ir] & mono_col[iy * nr + ir1] &
                                       mono_col[iy1 * nr + ir] & mono_col[iy1 * nr + ir1];
    }

  // Interleave: one 64-byte record of thermodynamic quantities per grid point.
  t->thermo.assign(n * kThermoStride, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double* r = &t->thermo[i * kThermoStride];
    r[kLogP] = std::log(raw.press.v[i] + t->p_shift);
    r[kLogEps] = std::log(raw.eps.v[i] + t->eps_shift);
    r[kCs2] = raw.cs2.v[i];
    r[kEntropy] = raw.entropy.v[i];
    if (t->has_chem) r[kMuE] = raw.mu_e.v[i], r[kMuP] = raw.mu_p.v[i], r[kMuN] = raw.mu_n.v[i];
  }
  if (t->has_compo) {
    t->compo.assign(n * kCompoFields, 0.0);
    const RawField* f[kCompoFields] = {&raw.Xa, &raw.Xh, &raw.Xn, &raw.Xp, &raw.Abar, &raw.Zbar};
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < kCompoFields; ++k) t->compo[i * kCompoFields + k] = f[k]->v[i];
  }

  // Bounds. h_min bounds the interpolant from below: within a cell, eps and p/rho each stay
  // above their smallest corner value (monotone maps of trilinear interpolants).
  Bounds& b = t->bounds;
  b.rho_min = raw.rho.front(), b.rho_max = raw.rho.back();
  b.T_min = raw.T.front(), b.T_max = raw.T.back();
  b.ye_min = raw.ye.front(), b.ye_max = raw.ye.back();
  b.eps_min = emin, b.eps_max = emax;
  b.press_min = pmin, b.press_max = pmax;
  double hmax = -Bounds::inf, hmin = Bounds::inf;
  auto idx = [&](std::size_t ir, std::size_t it, std::size_t iy) { return (iy * nt + it) * nr + ir; };
  for (std::size_t iy = 0; iy < std::max<std::size_t>(ny - 1, 1); ++iy)
    for (std::size_t it = 0; it < std::max<std::size_t>(nt - 1, 1); ++it)
      for (std::size_t ir = 0; ir < std::max<std::size_t>(nr - 1, 1); ++ir) {
        double e = Bounds::inf, pr = Bounds::inf;
        for (int c = 0; c < 8; ++c) {
          const std::size_t i = idx(std::min(ir + (c & 1), nr - 1), std::min(it + ((c >> 1) & 1), nt - 1),
                                    std::min(iy + (c >> 2), ny - 1));
          const double rho = raw.rho[i % nr];
          e = std::min(e, raw.eps.v[i]);
          pr = std::min(pr, t->p_shift > 0 ? (raw.press.v[i] - t->p_shift) / rho : raw.press.v[i] / rho);
          hmax = std::max(hmax, 1 + raw.eps.v[i] + raw.press.v[i] / rho);
        }
        hmin = std::min(hmin, 1 + e + pr);
      }
  b.h_min = hmin;
  b.h_max = hmax;
  return t;
}

}  // namespace remnant::eos
