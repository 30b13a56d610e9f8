#include "TOV/cold_slice.hpp"

#include <gsl/gsl_interp.h>

#include <cmath>
#include <algorithm>
#include <stdexcept>

namespace remnant::tov {
namespace {

class PolytropeSlice final : public ColdSlice {
 public:
  PolytropeSlice(double K, double G, double ye) : K_(K), G_(G), ye_(ye) {}
  ColdState at(double H) const override {
    const double hm1 = std::expm1(std::max(H, 0.0));  // h - 1 = Gamma/(Gamma-1) K rho^(Gamma-1)
    ColdState s;
    s.rho = std::pow(hm1 * (G_ - 1) / (G_ * K_), 1 / (G_ - 1));
    s.press = K_ * std::pow(s.rho, G_);
    s.eps = K_ * std::pow(s.rho, G_ - 1) / (G_ - 1);
    s.ye = ye_;
    return s;
  }
  double log_enthalpy(double rho) const override { return std::log1p(G_ / (G_ - 1) * K_ * std::pow(rho, G_ - 1)); }

 private:
  double K_, G_, ye_;
};

// Monotone (Steffen) interpolation of y(x) over increasing x.
class Monotone {
 public:
  Monotone(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    i_ = gsl_interp_alloc(gsl_interp_steffen, x_.size());
    gsl_interp_init(i_, x_.data(), y_.data(), x_.size());
    a_ = gsl_interp_accel_alloc();
  }
  ~Monotone() {
    gsl_interp_free(i_);
    gsl_interp_accel_free(a_);
  }
  Monotone(const Monotone&) = delete;
  Monotone& operator=(const Monotone&) = delete;
  double operator()(double x) const {
    x = std::min(std::max(x, x_.front()), x_.back());
    return gsl_interp_eval(i_, x_.data(), y_.data(), x, a_);
  }

 private:
  std::vector<double> x_, y_;
  gsl_interp* i_;
  gsl_interp_accel* a_;
};

// Integral over [a, b] of the quadratic through (x[k], f[k]), k = 0..2 (Newton form).
double quadratic_integral(const double* x, const double* f, double a, double b) {
  const double d01 = (f[1] - f[0]) / (x[1] - x[0]), d12 = (f[2] - f[1]) / (x[2] - x[1]);
  const double d012 = (d12 - d01) / (x[2] - x[0]);
  auto F = [&](double t) {
    const double u = t - x[0];
    return f[0] * u + d01 * u * u / 2 + d012 * (u * u * u / 3 - (x[1] - x[0]) * u * u / 2);
  };
  return F(b) - F(a);
}

// Points of a cold slice, split into segments inside which the EOS is smooth (the interpolated
// table has kinks at its nodes): H = int dp / (e + p) by the trapezoidal rule (`order` 2) or by
// quadratics that stay inside a segment (`order` 3); the inverse functions are interpolated
// separately in each segment, so no interpolant straddles a kink. Only points of strictly
// increasing H are kept.
class TabulatedSlice final : public ColdSlice {
 public:
  TabulatedSlice(const std::vector<double>& rho, const std::vector<double>& p, const std::vector<double>& eps,
                 const std::vector<double>& ye, std::vector<std::size_t> starts, int order) {
    starts.push_back(rho.size() - 1);
    std::vector<double> w(rho.size());
    for (std::size_t i = 0; i < rho.size(); ++i) w[i] = 1 / (rho[i] * (1 + eps[i]) + p[i]);
    double h = 0;
    for (std::size_t s = 0; s + 1 < starts.size(); ++s) {
      const std::size_t b = starts[s], e = starts[s + 1];  // the segment's points b..e (inclusive)
      Segment seg;
      for (std::size_t i = b; i <= e; ++i) {
        if (i > b) {
          double dh = (p[i] - p[i - 1]) * 0.5 * (w[i - 1] + w[i]);
          if (order == 3 && e - b >= 2) {
            const std::size_t k = std::min(i, e - 1);  // the stencil k-1, k, k+1 stays inside
            const double x[3] = {p[k - 1], p[k], p[k + 1]}, f[3] = {w[k - 1], w[k], w[k + 1]};
            if (x[0] < x[1] && x[1] < x[2]) dh = quadratic_integral(x, f, p[i - 1], p[i]);
          }
          h += dh;
        }
        const double last = !seg.H.empty() ? seg.H.back() : !all_.empty() ? all_.back().H.back() : -1.0;
        const bool shared = i == b && !all_.empty() && h == last;  // kept as the previous segment's end
        if (!(h > last) && !shared) continue;
        seg.push(h, rho[i], p[i], eps[i], ye[i]);
      }
      if (seg.H.size() >= 2) all_.push_back(std::move(seg));
    }
    std::size_t n = 0;
    for (const Segment& g : all_) n += g.H.size();
    if (n < 4) throw std::runtime_error("TOV: the cold slice has fewer than 4 points of increasing enthalpy");
    for (Segment& g : all_) g.build();
  }
  ColdState at(double H) const override {
    const Segment& g = find([&](const Segment& s) { return s.H.back(); }, H);
    return {std::exp((*g.rho)(H)), (*g.eps)(H), std::exp((*g.p)(H)), (*g.ye)(H)};
  }
  double log_enthalpy(double rho) const override {
    const double lr = std::log(rho);
    const Segment& g = find([&](const Segment& s) { return s.lr.back(); }, lr);
    return (*g.H_of_lrho)(lr);
  }

 private:
  struct Segment {
    std::vector<double> H, lr, lp, e, y;
    std::unique_ptr<Monotone> rho, p, eps, ye, H_of_lrho;
    void push(double h, double r, double pr, double ep, double yy) {
      H.push_back(h);
      lr.push_back(std::log(r));
      lp.push_back(std::log(pr));
      e.push_back(ep);
      y.push_back(yy);
    }
    void build() {
      rho = std::make_unique<Monotone>(H, lr);
      p = std::make_unique<Monotone>(H, lp);
      eps = std::make_unique<Monotone>(H, e);
      ye = std::make_unique<Monotone>(H, y);
      H_of_lrho = std::make_unique<Monotone>(lr, H);
    }
  };
  // The first segment whose upper end reaches x (the last one beyond the top).
  template <class Top>
  const Segment& find(Top top, double x) const {
    std::size_t lo = 0, hi = all_.size() - 1;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (top(all_[mid]) < x) lo = mid + 1;
      else hi = mid;
    }
    return all_[lo];
  }
  std::vector<Segment> all_;
};

}  // namespace

std::unique_ptr<ColdSlice> polytrope_slice(double K, double Gamma, double ye) {
  return std::make_unique<PolytropeSlice>(K, Gamma, ye);
}

std::unique_ptr<ColdSlice> tabulated_slice(std::vector<double> rho, std::vector<double> press, std::vector<double> eps,
                                           std::vector<double> ye) {
  return std::make_unique<TabulatedSlice>(rho, press, eps, ye, std::vector<std::size_t>{0}, 2);
}

std::unique_ptr<ColdSlice> tabulated_slice_segments(const std::vector<double>& rho, const std::vector<double>& press,
                                                    const std::vector<double>& eps, const std::vector<double>& ye,
                                                    std::vector<std::size_t> segment_starts) {
  return std::make_unique<TabulatedSlice>(rho, press, eps, ye, std::move(segment_starts), 3);
}

}  // namespace remnant::tov
