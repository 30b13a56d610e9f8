#include "enthalpy_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace remnant::tov {
namespace {

// dp/dx at sample j of n uniform samples (spacing h), fourth order, one-sided near the ends.
double derivative(const std::vector<double>& p, std::size_t j, double h) {
  const std::size_t n = p.size();
  if (j >= 2 && j + 2 < n) return (p[j - 2] - 8 * p[j - 1] + 8 * p[j + 1] - p[j + 2]) / (12 * h);
  const bool low = j < 2;
  // Mirror the upper end onto the lower one: q[k] = p[n-1-k], derivative changes sign.
  auto q = [&](std::size_t k) { return low ? p[k] : p[n - 1 - k]; };
  const std::size_t k = low ? j : n - 1 - j;
  const double d = k == 0 ? (-25 * q(0) + 48 * q(1) - 36 * q(2) + 16 * q(3) - 3 * q(4)) / (12 * h)
                          : (-3 * q(0) - 10 * q(1) + 18 * q(2) - 6 * q(3) + q(4)) / (12 * h);
  return low ? d : -d;
}

// int over [x_j, x_j+1] of g, from the cubic through four neighbouring samples (fourth order).
double interval_integral(const std::vector<double>& g, std::size_t j, double h) {
  const std::size_t n = g.size();
  if (j == 0) return h * (9 * g[0] + 19 * g[1] - 5 * g[2] + g[3]) / 24;
  if (j + 2 >= n) return h * (g[n - 4] - 5 * g[n - 3] + 19 * g[n - 2] + 9 * g[n - 1]) / 24;
  return h * (-g[j - 1] + 13 * g[j] + 13 * g[j + 1] - g[j + 2]) / 24;
}

// Cubic Hermite on [0, 1] with end values a, b and end slopes da, db (per unit t).
double hermite(double t, double a, double b, double da, double db) {
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * a + (t3 - 2 * t2 + t) * da + (-2 * t3 + 3 * t2) * b + (t3 - t2) * db;
}
double hermite_slope(double t, double a, double b, double da, double db) {
  const double t2 = t * t;
  return (6 * t2 - 6 * t) * a + (3 * t2 - 4 * t + 1) * da + (-6 * t2 + 6 * t) * b + (3 * t2 - 2 * t) * db;
}

}  // namespace

EnthalpyCurve::EnthalpyCurve(const std::vector<SlicePiece>& pieces) {
  double H = 0;
  for (const SlicePiece& s : pieces) {
    if (s.p.size() < 5 || s.e.size() != s.p.size() || !(s.dx > 0))
      throw std::runtime_error("TOV: a piece of the cold slice needs at least 5 uniform samples");
    Piece q{s.x0, s.dx, {}, {}};
    for (std::size_t j = 0; j < s.p.size(); ++j) q.g.push_back(std::max(derivative(s.p, j, s.dx), 0.0) / (s.e[j] + s.p[j]));
    q.H.push_back(H);
    for (std::size_t j = 0; j + 1 < s.p.size(); ++j) {
      H += std::max(interval_integral(q.g, j, s.dx), 0.0);  // p may stall (never fall) with rho
      q.H.push_back(H);
    }
    pieces_.push_back(std::move(q));
  }
  if (pieces_.empty() || !(H > 0)) throw std::runtime_error("TOV: the cold slice has no increasing enthalpy");
}

std::size_t EnthalpyCurve::piece_of_x(double x) const {
  std::size_t k = 0;
  while (k + 1 < pieces_.size() && x > pieces_[k].x0 + pieces_[k].dx * double(pieces_[k].H.size() - 1)) ++k;
  return k;
}

std::size_t EnthalpyCurve::piece_of_H(double H) const {
  std::size_t k = 0;
  while (k + 1 < pieces_.size() && H > pieces_[k].H.back()) ++k;
  return k;
}

double EnthalpyCurve::H(double x) const {
  const Piece& q = pieces_[piece_of_x(x)];
  const std::size_t n = q.H.size();
  const double s = std::clamp((x - q.x0) / q.dx, 0.0, double(n - 1));
  const std::size_t j = std::min(std::size_t(s), n - 2);
  return hermite(s - double(j), q.H[j], q.H[j + 1], q.g[j] * q.dx, q.g[j + 1] * q.dx);
}

double EnthalpyCurve::x_of(double H) const {
  const Piece& q = pieces_[piece_of_H(H)];
  H = std::clamp(H, q.H.front(), q.H.back());
  // The interval with H_j <= H < H_j+1 (zero-width intervals, where p stalls, are never chosen).
  const std::size_t j = std::min<std::size_t>(std::upper_bound(q.H.begin(), q.H.end(), H) - q.H.begin(), q.H.size() - 1) - 1;
  const double a = q.H[j], b = q.H[j + 1], da = q.g[j] * q.dx, db = q.g[j + 1] * q.dx;
  if (!(b > a)) return q.x0 + q.dx * double(j);
  // Newton on the cubic, kept inside a bisection bracket.
  double lo = 0, hi = 1, t = (H - a) / (b - a);
  for (int it = 0; it < 60; ++it) {
    const double f = hermite(t, a, b, da, db) - H;
    if (f == 0) break;
    (f < 0 ? lo : hi) = t;
    const double d = hermite_slope(t, a, b, da, db);
    double next = d > 0 ? t - f / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - t) < 1e-15) {
      t = next;
      break;
    }
    t = next;
  }
  return q.x0 + q.dx * (double(j) + t);
}

}  // namespace remnant::tov
