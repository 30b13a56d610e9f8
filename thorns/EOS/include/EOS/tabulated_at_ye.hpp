#pragma once
// A tabulated EOS at one fixed Ye, for the primitive recovery: Ye is known before the master root
// is sought, so its index and weight are found once per recovery. Each master-function evaluation
// then needs T from eps at some rho and the pressure at that T; both come from one (rho, Ye) column:
// ln(eps + shift) and ln(p + shift) of a grid point share one 64-byte record, so the T interval that
// brackets eps gives p with the same weights (no second stencil, no ln T -> T -> ln T round trip).
// The interval of the previous evaluation is tried first; where eps rises with T in the cell
// (TableData::monotone_cell) a bracket there decides everything, rules 8/9 included.
//
// Results equal Tabulated::temperature(rho, eps, ye, T_guess, exact) followed by press(rho, T, ye)
// to round-off, with the same flags (tests EOSTabulatedAtYe.*).
//
// Table calls counted (the unit of Tabulated's counter): one per read of a (rho, Ye)-column node or
// of one interpolation cell, however many fields are taken from it (ln p is read with ln eps at
// every node, so the interval found by the search needs no further read for p).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "EOS/table.hpp"
#include "EOS/tabulated.hpp"
#include "EOS/types.hpp"

namespace remnant::eos {

// The search is forced inline (gnu::always_inline) into the master function, which calls it once per
// evaluation: as separate calls the Result and Column copies cost more than the search itself.
template <class Tab>
class TabulatedAtYe {
 public:
  struct Result {
    double eps = 0;    // the eps used: the input, or eps_low / eps_high under rules 8/9
    double press = 0;  // p(rho, T, Ye)
    double T = 0;      // MeV under rules 8/9 (T_min, T_max exactly); 0 otherwise: T = exp(lnT)
    double lnT = 0;    // ln T (the guess of the next call)
    double temperature() const { return T > 0 ? T : std::exp(lnT); }
    std::uint32_t flags = kInvOk;
  };

  TabulatedAtYe(const Tab& eos, double ye) : eos_(eos), t_(eos.table()) {
    const int nr = t_.lrho.n, nt = t_.lT.n;
    sr_ = nr > 1 ? kThermoStride : 0;
    st_ = nt > 1 ? std::size_t(kThermoStride) * nr : 0;
    sy_ = t_.ye.n > 1 ? std::size_t(kThermoStride) * nr * nt : 0;
    std::size_t iy;
    locate(t_.ye, ye, iy, fy_);
    slice_ = t_.thermo.data() + iy * std::size_t(nt) * nr * kThermoStride;
    cells_ = t_.monotone_cell.data() + iy * nr;
    const Bounds& b = t_.bounds;
    ye_flags_ = (ye >= b.ye_min && ye <= b.ye_max) ? kInvOk : kInvYeClamped;
    lr_top_ = nr > 1 ? double(nr - 1) : 0.0;
    lr_kmax_ = nr > 1 ? nr - 2 : 0;
  }

  // T from eps at rho (rules 8/9 as Tabulated::temperature), and p there.
  //   lnT_guess: ln T of the previous call, Tabulated::temperature's T_guess (not finite: none); it
  //              selects the root where eps is not monotonic in T (monotone_cell 0).
  //   lnT_hint:  where the search starts in a monotone cell (not finite: none); the result there is
  //              unique, so the hint changes only the cost.
  [[gnu::always_inline]] Result invert(double rho, double eps, double lnT_guess, double lnT_hint) const {
    Result r;
    r.eps = eps;
    const Bounds& b = t_.bounds;
    r.flags = ye_flags_ | ((rho >= b.rho_min && rho <= b.rho_max) ? kInvOk : kInvRhoClamped);
    int ir;
    double fr;
    locate_rho(std::log(rho), ir, fr);
    const Column c{slice_ + std::size_t(ir) * kThermoStride, sr_, sy_, st_, (1 - fy_) * (1 - fr), (1 - fy_) * fr, fy_ * (1 - fr), fy_ * fr};
    const double arg = eps + t_.eps_shift;
    const double target = arg > 0 ? std::log(arg) : -Bounds::inf;
    if (cells_[ir]) return invert_monotone(c, target, interval(lnT_hint), r);
    return invert_any(c, target, interval(lnT_guess), r);
  }

  // The largest eps(rho_i, T_max, Ye) over the table's rho nodes strictly between rho_a and rho_b
  // (-inf: none; one table call per node read). Between nodes ln(eps + shift) at T_max, the rule-9
  // threshold, is linear in ln rho, so with its values at rho_a and rho_b this bounds it on [rho_a, rho_b].
  double eps_high_between(double rho_a, double rho_b) const {
    int ia, ib;
    double f;
    locate_rho(std::log(rho_a), ia, f);
    locate_rho(std::log(rho_b), ib, f);
    if (ia > ib) std::swap(ia, ib);
    double le = -Bounds::inf;
    const std::size_t last = std::size_t(t_.lT.n - 1);
    for (int i = ia + 1; i <= ib; ++i) {
      eos_.counter().add();
      const double* q = slice_ + std::size_t(i) * kThermoStride + last * st_ + kLogEps;
      le = std::max(le, (1 - fy_) * q[0] + fy_ * q[sy_]);
    }
    return le == -Bounds::inf ? le : std::exp(le) - t_.eps_shift;
  }

 private:
  // ln p and ln(eps + shift) at one T node: the bilinear (rho, Ye) combination of the four columns.
  // Both fields sit next to each other in each 64-byte record, so they are read together (one table
  // call) and combined with the same weights (the two lanes do the same arithmetic as one field).
  struct Node {
    double lp, le;
  };
  struct Column {
    const double* p;
    std::size_t sr, sy, st;
    double w00, w01, w10, w11;  // corner weights (1-fy)(1-fr), (1-fy)fr, fy(1-fr), fy fr
    [[gnu::always_inline]] Node node(int j) const {
      static_assert(kLogEps == kLogP + 1, "ln p and ln eps adjacent in the record");
      const double* q = p + j * st + kLogP;
      return {w00 * q[0] + w01 * q[sr] + w10 * q[sy] + w11 * q[sy + sr],
              w00 * q[1] + w01 * q[sr + 1] + w10 * q[sy + 1] + w11 * q[sy + sr + 1]};
    }
  };

  // locate(t_.lrho, x, i, f) with its bounds precomputed and an int index (the size_t conversion of
  // the general version costs a branch per call): the same i and f, bit for bit.
  [[gnu::always_inline]] void locate_rho(double x, int& i, double& f) const {
    double s = (x - t_.lrho.x0) * t_.lrho.inv_dx;
    if (!(s > 0)) s = 0;
    if (s > lr_top_) s = lr_top_;
    int k = int(s);
    if (k > lr_kmax_) k = lr_kmax_;
    i = k;
    f = s - double(k);
  }

  // The T interval holding ln T (as Tabulated::temperature takes its guess), -1 for none.
  int interval(double lnT) const {
    const Axis& a = t_.lT;
    if (!std::isfinite(lnT) || a.n < 2) return -1;
    return int(std::clamp((lnT - a.x0) * a.inv_dx, 0.0, double(a.n - 2)));
  }

  // eps rises with T along the column: the interval j with E(j) <= target < E(j+1) is unique. From
  // the hinted interval, hunt outwards (steps 1, 2, 4, ...) to a bracket, then bisect; the end nodes
  // are read only when the hunt reaches them (rules 8/9: target <= E(0), target >= E(last)).
  // Every node read gives ln p too, so the bracketing interval's p costs no further read.
  [[gnu::always_inline]] Result invert_monotone(const Column& c, double target, int j, Result& r) const {
    const int last = t_.lT.n - 1;
    int l = 0, h = last;
    Node nl{}, nh{};
    if (j >= 0) {
      eos_.counter().add();  // one cell: E and p at both ends of the hinted interval
      const Node g0 = c.node(j), g1 = c.node(j + 1);
      if (g0.le < target && target < g1.le) return interior(j, g0, g1, target, r);
      if (!(target > g0.le)) {  // below: hunt down for a node <= target
        if (j == 0) return clamped(g0, t_.bounds.T_min, kInvBelowEpsLow, r);
        h = j, nh = g0;
        for (int step = 1;; step *= 2) {
          const int k = std::max(h - step, 0);
          eos_.counter().add();
          const Node nk = c.node(k);
          if (k == 0 && !(target > nk.le)) return clamped(nk, t_.bounds.T_min, kInvBelowEpsLow, r);
          if (nk.le <= target) {
            l = k, nl = nk;
            break;
          }
          h = k, nh = nk;
        }
      } else {  // at or above: hunt up for a node > target
        if (j + 1 == last) return clamped(g1, t_.bounds.T_max, kInvAboveEpsHigh, r);
        l = j + 1, nl = g1;
        for (int step = 1;; step *= 2) {
          const int k = std::min(l + step, last);
          eos_.counter().add();
          const Node nk = c.node(k);
          if (k == last && target >= nk.le) return clamped(nk, t_.bounds.T_max, kInvAboveEpsHigh, r);
          if (nk.le > target) {
            h = k, nh = nk;
            break;
          }
          l = k, nl = nk;
        }
      }
    } else {
      eos_.counter().add(2);
      nl = c.node(0), nh = c.node(last);
      if (!(target > nl.le)) return clamped(nl, t_.bounds.T_min, kInvBelowEpsLow, r);  // rule 8
      if (target >= nh.le) return clamped(nh, t_.bounds.T_max, kInvAboveEpsHigh, r);  // rule 9
    }
    while (h - l > 1) {
      const int mid = (l + h) / 2;
      eos_.counter().add();
      const Node nm = c.node(mid);
      if (nm.le <= target) l = mid, nl = nm;
      else h = mid, nh = nm;
    }
    return interior(l, nl, nh, target, r);
  }

  // Any column (Tabulated::temperature's exact inversion): the end nodes for rules 8/9, then the
  // bracketing interval nearest to the guess (without one, nearest T_min).
  Result invert_any(const Column& c, double target, int jg, Result& r) const {
    const int last = t_.lT.n - 1;
    eos_.counter().add(2);
    const Node lo = c.node(0), hi = c.node(last);
    if (!(target > lo.le)) return clamped(lo, t_.bounds.T_min, kInvBelowEpsLow, r);  // rule 8 (and NaN)
    if (target >= hi.le) return clamped(hi, t_.bounds.T_max, kInvAboveEpsHigh, r);  // rule 9
    const int start = jg >= 0 ? jg : 0;
    bool read = false;
    for (int d = 0; d <= last; ++d)
      for (int s : {start + d, start - d}) {
        if (s < 0 || s >= last || (d == 0 && read)) continue;
        eos_.counter().add(2);
        read = true;
        const Node n0 = c.node(s), n1 = c.node(s + 1);
        if ((n0.le <= target && target <= n1.le) || (n1.le <= target && target <= n0.le))
          return interior(s, n0, n1, target, r);
      }
    return clamped(lo, t_.bounds.T_min, kInvBelowEpsLow, r);  // unreachable: lo < target < hi
  }

  // Linear in ln T on [node j, node j+1] (as Tabulated's exact inversion), p with the same fraction.
  [[gnu::always_inline]] Result interior(int j, const Node& n0, const Node& n1, double target, Result& r) const {
    const Axis& a = t_.lT;
    const double f = n1.le != n0.le ? (target - n0.le) / (n1.le - n0.le) : 0.0;
    r.lnT = a.node(j) + a.dx * f;  // T = exp(lnT) is left to the caller (needed at the root only)
    r.press = std::exp((1 - f) * n0.lp + f * n1.lp) - t_.p_shift;
    return r;
  }
  Result clamped(const Node& n, double T, std::uint32_t flag, Result& r) const {
    r.T = T;
    r.lnT = std::log(T);
    r.eps = std::exp(n.le) - t_.eps_shift;
    r.flags |= flag;
    r.press = std::exp(n.lp) - t_.p_shift;
    return r;
  }

  const Tab& eos_;
  const TableData& t_;
  const double* slice_ = nullptr;
  const std::uint8_t* cells_ = nullptr;
  std::size_t sr_ = 0, st_ = 0, sy_ = 0;
  double fy_ = 0;
  double lr_top_ = 0;  // ln rho axis: n - 1 (the largest scaled coordinate) and n - 2 (the last cell)
  int lr_kmax_ = 0;
  std::uint32_t ye_flags_ = kInvOk;
};

// True for the tabulated EOS types (those with a TabulatedAtYe).
template <class E>
inline constexpr bool is_tabulated_v = false;
template <class C>
inline constexpr bool is_tabulated_v<Tabulated<C>> = true;

}  // namespace remnant::eos
