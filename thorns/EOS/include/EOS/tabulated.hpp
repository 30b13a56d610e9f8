#pragma once
// Tabulated EOS: trilinear interpolation in (ln rho, ln T, Ye) of the interleaved table, and the
// eps -> T inversion. Non-virtual and inline: meant to be called per cell. Inputs outside the
// table are evaluated at the nearest edge (the error policy decides what to do with them).
#include <algorithm>
#include <cmath>
#include <memory>

#include "EOS/brent.hpp"
#include "EOS/counter.hpp"
#include "EOS/table.hpp"
#include "EOS/types.hpp"

namespace remnant::eos {

struct EpsRange {
  double low = 0, high = 0;  // eps(rho, T_min, Ye), eps(rho, T_max, Ye)
};

template <class Counter = NoCount>
class Tabulated {
 public:
  static constexpr bool has_temperature = true;
  static constexpr int max_iterations = 50;  // the paper's fallback threshold

  explicit Tabulated(std::shared_ptr<const TableData> t) : t_(std::move(t)) {
    const int nr = t_->lrho.n, nt = t_->lT.n;
    sr_ = nr > 1 ? kThermoStride : 0;
    st_ = nt > 1 ? std::size_t(kThermoStride) * nr : 0;
    sy_ = t_->ye.n > 1 ? std::size_t(kThermoStride) * nr * nt : 0;
    node_t_ = std::size_t(kThermoStride) * nr;
  }
  template <class C>
  explicit Tabulated(const Tabulated<C>& o) : Tabulated(o.table_ptr()) {}

  const TableData& table() const { return *t_; }
  const std::shared_ptr<const TableData>& table_ptr() const { return t_; }
  const Bounds& bounds() const { return t_->bounds; }
  bool has_chemical_potentials() const { return t_->has_chem; }
  bool has_composition() const { return t_->has_compo; }
  const Counter& counter() const { return counter_; }

  // --- from (rho, T, Ye) -------------------------------------------------------------------
  Thermo thermo(double rho, double T, double ye) const {
    const Stencil s = stencil(rho, T, ye);
    counter_.add();
    Thermo o;
    o.press = std::exp(interp(s, kLogP)) - t_->p_shift;
    o.eps = std::exp(interp(s, kLogEps)) - t_->eps_shift;
    o.cs2 = interp(s, kCs2);
    o.entropy = interp(s, kEntropy);
    o.h = 1 + o.eps + o.press / rho;
    return o;
  }
  // p and cs2 of thermo() where ln T is already known (the primitive recovery's root): the same
  // interpolant without the ln T -> T -> ln T round trip and without the other fields.
  [[gnu::always_inline]] PressCs2 press_cs2(double rho, double lnT, double ye) const {
    std::size_t ir, it, iy;
    double fr, ft, fy;
    locate(t_->lrho, std::log(rho), ir, fr);
    locate(t_->lT, lnT, it, ft);
    locate(t_->ye, ye, iy, fy);
    const double* p = t_->thermo.data() + ((iy * t_->lT.n + it) * t_->lrho.n + ir) * kThermoStride;
    counter_.add();
    // acausal(rho, ye) from the indices found here: the recovery asks for it at this point, and
    // its own locate would take ln rho once more.
    const bool acausal = !t_->acausal_cell.empty() && t_->acausal_cell[iy * t_->lrho.n + ir] != 0;
    return {std::exp(trilinear(p + kLogP, sr_, st_, sy_, fr, ft, fy)) - t_->p_shift,
            trilinear(p + kCs2, sr_, st_, sy_, fr, ft, fy), acausal};
  }
  double press(double rho, double T, double ye) const {
    counter_.add();
    return std::exp(interp(stencil(rho, T, ye), kLogP)) - t_->p_shift;
  }
  double eps(double rho, double T, double ye) const {
    counter_.add();
    return std::exp(interp(stencil(rho, T, ye), kLogEps)) - t_->eps_shift;
  }
  double cs2(double rho, double T, double ye) const {
    counter_.add();
    return interp(stencil(rho, T, ye), kCs2);
  }
  double entropy(double rho, double T, double ye) const {
    counter_.add();
    return interp(stencil(rho, T, ye), kEntropy);
  }
  // Requires has_chemical_potentials().
  ChemPot chem(double rho, double T, double ye) const {
    const Stencil s = stencil(rho, T, ye);
    counter_.add();
    return {interp(s, kMuE), interp(s, kMuP), interp(s, kMuN)};
  }
  double mu_nu(double rho, double T, double ye) const {
    const Stencil s = stencil(rho, T, ye);
    counter_.add();
    return interp(s, kMuE) + interp(s, kMuP) - interp(s, kMuN);
  }
  // Requires has_composition().
  Composition composition(double rho, double T, double ye) const {
    const Stencil s = stencil(rho, T, ye);
    counter_.add();
    const double* p = t_->compo.data() + (s.base / kThermoStride) * kCompoFields;
    const std::size_t r = s.sr / kThermoStride * kCompoFields, t = s.st / kThermoStride * kCompoFields,
                      y = s.sy / kThermoStride * kCompoFields;
    double v[kCompoFields];
    for (int k = 0; k < kCompoFields; ++k) v[k] = trilinear(p + k, r, t, y, s.fr, s.ft, s.fy);
    return {v[kXa], v[kXh], v[kXn], v[kXp], v[kAbar], v[kZbar]};
  }

  // True in a (rho, Ye) cell where cs2 exceeded 1 at some T (TableData::acausal_cell): there
  // the conserved variables may not determine the state uniquely. No EOS call is counted.
  bool acausal(double rho, double ye) const {
    if (t_->acausal_cell.empty()) return false;
    std::size_t ir, iy;
    double f;
    locate(t_->lrho, std::log(rho), ir, f);
    locate(t_->ye, ye, iy, f);
    return t_->acausal_cell[iy * t_->lrho.n + ir] != 0;
  }

  // --- eps bounds along T and the eps -> T inversion ------------------------------------------
  EpsRange eps_range(double rho, double ye) const {
    const Column c = column(rho, ye);
    return {std::exp(c.node(0)) - t_->eps_shift, std::exp(c.node(t_->lT.n - 1)) - t_->eps_shift};
  }

  // T such that eps(rho, T, ye) = eps. Rules 8/9: eps at or beyond eps(T_min) / eps(T_max) gives
  // T_min / T_max and the clamped eps. T_guess (<= 0: none) selects the root nearest to it where
  // eps is not monotonic in T, and shortens the search. `exact` inverts the piecewise-linear
  // (in ln T) interpolant directly; `brent` is the paper's method.
  Inversion temperature(double rho, double eps, double ye, double T_guess = 0,
                        InversionMethod method = InversionMethod::exact) const {
    Inversion r;
    r.flags = range_flags(rho, ye);
    const Column c = column(rho, ye);
    const Axis& a = t_->lT;
    const double lo = c.node(0), hi = c.node(a.n - 1);
    const double arg = eps + t_->eps_shift;
    const double target = arg > 0 ? std::log(arg) : -Bounds::inf;
    if (!(target > lo)) {  // rule 8 (also catches NaN eps)
      r.T = t_->bounds.T_min;
      r.eps = std::exp(lo) - t_->eps_shift;
      r.flags |= kInvBelowEpsLow;
      return r;
    }
    if (target >= hi) {  // rule 9
      r.T = t_->bounds.T_max;
      r.eps = std::exp(hi) - t_->eps_shift;
      r.flags |= kInvAboveEpsHigh;
      return r;
    }
    r.eps = eps;
    const double xg = T_guess > 0 ? std::log(T_guess) : Bounds::inf;
    r.T = std::exp(method == InversionMethod::exact ? invert_exact(c, target, lo, hi, xg, r)
                                                    : invert_brent(c, target, lo, hi, xg, r));
    return r;
  }

  // Thermodynamics from (rho, eps, Ye): T from the inversion (T_guess carried in and out),
  // eps replaced by the clamped value under rules 8/9; `flags` receives the inversion flags.
  Thermo thermo_from_eps(double rho, double eps, double ye, double& T_guess, std::uint32_t* flags = nullptr,
                         InversionMethod method = InversionMethod::exact) const {
    const Inversion inv = temperature(rho, eps, ye, T_guess, method);
    T_guess = inv.T;
    if (flags) *flags = inv.flags;
    Thermo o = thermo(rho, inv.T, ye);
    o.eps = inv.eps;
    o.h = 1 + o.eps + o.press / rho;
    return o;
  }

 private:
  struct Stencil {
    std::size_t base, sr, st, sy;
    double fr, ft, fy;
  };
  // ln(eps + shift) at the T nodes along fixed (rho, Ye): a bilinear combination of 4 columns.
  struct Column {
    const Tabulated* self;
    const double* p;
    std::size_t sr, sy, st;
    double fr, fy;
    std::size_t cell;  // (iye, irho) cell index for the monotonicity flag
    double node(int j) const {
      self->counter_.add();
      return node_uncounted(j);
    }
    double node_uncounted(int j) const {
      const double* q = p + j * st;
      return (1 - fy) * ((1 - fr) * q[0] + fr * q[sr]) + fy * ((1 - fr) * q[sy] + fr * q[sy + sr]);
    }
  };

  Stencil stencil(double rho, double T, double ye) const {
    std::size_t ir, it, iy;
    Stencil s;
    locate(t_->lrho, std::log(rho), ir, s.fr);
    locate(t_->lT, std::log(T), it, s.ft);
    locate(t_->ye, ye, iy, s.fy);
    s.base = ((iy * t_->lT.n + it) * t_->lrho.n + ir) * kThermoStride;
    s.sr = sr_, s.st = st_, s.sy = sy_;
    return s;
  }
  [[gnu::always_inline]] static double trilinear(const double* p, std::size_t sr, std::size_t st, std::size_t sy,
                                                 double fr, double ft, double fy) {
    const double c00 = (1 - fr) * p[0] + fr * p[sr];
    const double c10 = (1 - fr) * p[st] + fr * p[st + sr];
    const double c01 = (1 - fr) * p[sy] + fr * p[sy + sr];
    const double c11 = (1 - fr) * p[sy + st] + fr * p[sy + st + sr];
    return (1 - fy) * ((1 - ft) * c00 + ft * c10) + fy * ((1 - ft) * c01 + ft * c11);
  }
  double interp(const Stencil& s, int field) const {
    return trilinear(t_->thermo.data() + s.base + field, s.sr, s.st, s.sy, s.fr, s.ft, s.fy);
  }
  Column column(double rho, double ye) const {
    std::size_t ir, iy;
    double fr, fy;
    locate(t_->lrho, std::log(rho), ir, fr);
    locate(t_->ye, ye, iy, fy);
    const double* p = t_->thermo.data() + (iy * t_->lT.n * t_->lrho.n + ir) * kThermoStride + kLogEps;
    return {this, p, sr_, sy_, node_t_, fr, fy, iy * t_->lrho.n + ir};
  }
  std::uint32_t range_flags(double rho, double ye) const {
    const Bounds& b = t_->bounds;
    std::uint32_t f = 0;
    if (!(rho >= b.rho_min && rho <= b.rho_max)) f |= kInvRhoClamped;
    if (!(ye >= b.ye_min && ye <= b.ye_max)) f |= kInvYeClamped;
    return f;
  }
  // Exact inverse of the interpolant: find the T interval whose node values bracket the target,
  // then solve the linear interpolation in ln T. E(0) < target < E(n-1) on entry.
  double invert_exact(const Column& c, double target, double e_lo, double e_hi, double xg, Inversion& r) const {
    const Axis& a = t_->lT;
    const int last = a.n - 1;
    const int jg = std::isfinite(xg) ? int(std::clamp((xg - a.x0) * a.inv_dx, 0.0, double(last - 1))) : -1;
    if (t_->monotone_cell[c.cell]) {
      // Bisection over the nodes, narrowed first by the guess interval.
      int lo = 0, hi = last, n = 0;
      double flo = e_lo, fhi = e_hi;
      if (jg >= 0) {
        const double g0 = c.node(jg), g1 = c.node(jg + 1);
        n = 2;
        if (g0 <= target && target < g1) return finish(a, jg, g0, g1, target, r, n);
        if (target < g0) hi = jg, fhi = g0;
        else lo = jg + 1, flo = g1;
      }
      while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        const double fm = c.node(mid);
        ++n;
        if (fm <= target) lo = mid, flo = fm;
        else hi = mid, fhi = fm;
      }
      return finish(a, lo, flo, fhi, target, r, n);
    }
    // Not monotone: the bracketing interval nearest to the guess (without one, nearest T_min).
    const int start = jg >= 0 ? jg : 0;
    int n = 0;
    for (int d = 0; d <= last; ++d) {
      for (int s : {start + d, start - d}) {
        if (s < 0 || s >= last || (d == 0 && n > 0)) continue;
        const double e0 = c.node(s), e1 = c.node(s + 1);
        n += 2;
        if ((e0 <= target && target <= e1) || (e1 <= target && target <= e0)) return finish(a, s, e0, e1, target, r, n);
      }
    }
    return a.x0;  // unreachable: E(0) < target < E(last) guarantees a bracket
  }
  double finish(const Axis& a, int j, double ej, double ej1, double target, Inversion& r, int n) const {
    r.iterations = n;
    const double f = ej1 != ej ? (target - ej) / (ej1 - ej) : 0.0;
    return a.node(j) + a.dx * f;
  }

  // The paper's method: Brent in ln T on a bracket grown from the guess (else [T_min, T_max]).
  double invert_brent(const Column& c, double target, double e_lo, double e_hi, double xg, Inversion& r) const {
    const Axis& a = t_->lT;
    auto f = [&](double x) {
      std::size_t j;
      double fr;
      locate(a, x, j, fr);
      counter_.add();  // one eps(rho, T, Ye) evaluation
      return (1 - fr) * c.node_uncounted(int(j)) + fr * c.node_uncounted(int(j) + 1) - target;
    };
    double xa = a.lo(), xb = a.hi(), fa = e_lo - target, fb = e_hi - target;
    if (std::isfinite(xg)) {
      double w = a.dx;
      double ya = std::max(xg - w, a.lo()), yb = std::min(xg + w, a.hi());
      double ga = f(ya), gb = f(yb);
      while ((ga > 0) == (gb > 0) && (ya > a.lo() || yb < a.hi())) {
        w *= 4;
        if (ga > 0) ya = std::max(xg - w, a.lo()), ga = ya == a.lo() ? fa : f(ya);
        else yb = std::min(xg + w, a.hi()), gb = yb == a.hi() ? fb : f(yb);
      }
      if ((ga > 0) != (gb > 0)) xa = ya, xb = yb, fa = ga, fb = gb;
    }
    const BrentResult b = brent(f, xa, xb, fa, fb, 1e-14 * std::max(1.0, std::abs(xa)), max_iterations);
    r.iterations = b.iterations;
    if (!b.converged) r.flags |= kInvMaxIter;
    return b.x;
  }

  std::shared_ptr<const TableData> t_;
  std::size_t sr_ = 0, st_ = 0, sy_ = 0, node_t_ = 0;
  [[no_unique_address]] Counter counter_;
};

}  // namespace remnant::eos
