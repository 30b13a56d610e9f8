#include "HandOff/sampler.hpp"

#include <algorithm>
#include <cmath>

#include "remnant/error.hpp"

namespace remnant::handoff {
namespace {

constexpr double kSnap = 1e-9;  // a point this close to a node (in spacings) is the node

struct Stencil1D {
  int first = 0, count = 1;  // nodes first .. first+count-1 (cubic); lin: nodes lin_first, +1
  double w[4] = {1, 0, 0, 0};
  int lin_first = 0, lin_count = 1;
  double lw[2] = {1, 0};
};

Stencil1D stencil(double t) {
  Stencil1D s;
  double i0 = std::floor(t);
  double f = t - i0;
  if (f < kSnap) f = 0;
  if (f > 1 - kSnap) f = 0, i0 += 1;
  const int i = static_cast<int>(i0);
  if (f == 0) {
    s.first = s.lin_first = i;
    return s;
  }
  s.first = i - 1, s.count = 4;
  s.w[0] = -f * (f - 1) * (f - 2) / 6;
  s.w[1] = (f + 1) * (f - 1) * (f - 2) / 2;
  s.w[2] = -(f + 1) * f * (f - 2) / 2;
  s.w[3] = (f + 1) * f * (f - 1) / 6;
  s.lin_first = i, s.lin_count = 2;
  s.lw[0] = 1 - f, s.lw[1] = f;
  return s;
}

double minmod(double a, double b) { return a * b <= 0 ? 0.0 : (a > 0 ? std::min(a, b) : std::max(a, b)); }

// How far a smooth function may exceed the range of the 8 nearest points: per direction, the
// minmod of the second differences at the two inner nodes of the cubic stencil (on the lines
// through the nearest points) over 8 is the excess of a parabola between two nodes; the sum over
// the directions is doubled for rounding. A jump makes neighbouring second differences change
// sign: no excess, the trilinear value stays.
double smooth_overshoot(const SourceLevel& L, const double* a, const Stencil1D (&s)[3]) {
  double m = 0;
  for (int d = 0; d < 3; ++d) {
    if (s[d].count != 4) continue;
    const int e1 = d == 0 ? 1 : 0, e2 = d == 2 ? 1 : 2;
    double worst = 0;
    for (int q = 0; q < s[e2].lin_count; ++q)
      for (int p = 0; p < s[e1].lin_count; ++p) {
        double v[4];
        for (int n = 0; n < 4; ++n) {
          int idx[3];
          idx[d] = s[d].first + n, idx[e1] = s[e1].lin_first + p, idx[e2] = s[e2].lin_first + q;
          v[n] = a[L.index(idx[0], idx[1], idx[2])];
        }
        worst = std::max(worst, std::abs(minmod(v[0] - 2 * v[1] + v[2], v[1] - 2 * v[2] + v[3])));
      }
    m += worst / 8;
  }
  return 2 * m;
}

}  // namespace

Sampler::Sampler(const SourceData& src, const std::vector<std::string>& fields) : src_(src), nfields_(fields.size()) {
  for (const auto& L : src.levels) {
    std::vector<const double*> f;
    for (const auto& name : fields) {
      auto it = L.fields.find(name);
      if (it == L.fields.end()) throw RunError("HandOff: the source data has no field '" + name + "'");
      f.push_back(it->second.data());
    }
    fields_.push_back(std::move(f));
  }
}

bool Sampler::sample(const Point3& X, double* out, int* level_used) const {
  for (int l = static_cast<int>(src_.levels.size()) - 1; l >= 0; --l)
    if (sample_level(src_.levels[static_cast<std::size_t>(l)], fields_[static_cast<std::size_t>(l)], X, out)) {
      if (level_used) *level_used = l;
      return true;
    }
  return false;
}

double Sampler::spacing_at(const Point3& X) const {
  for (auto L = src_.levels.rbegin(); L != src_.levels.rend(); ++L) {
    int idx[3];
    for (std::size_t a = 0; a < 3; ++a) idx[a] = static_cast<int>(std::lround((X[a] - L->origin[a]) / L->delta[a]));
    if (L->is_valid(idx[0], idx[1], idx[2])) return L->delta[0];
  }
  return src_.levels.empty() ? 1.0 : src_.levels.front().delta[0];
}

bool Sampler::sample_level(const SourceLevel& L, const std::vector<const double*>& f, const Point3& X, double* out) const {
  Stencil1D s[3];
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    const double t = (X[ud] - L.origin[ud]) / L.delta[ud];
    if (!(t > -1) || !(t < L.n[d])) return false;
    s[d] = stencil(t);
  }
  auto all_valid = [&](bool cubic) {
    for (int k = 0; k < (cubic ? s[2].count : s[2].lin_count); ++k)
      for (int j = 0; j < (cubic ? s[1].count : s[1].lin_count); ++j)
        for (int i = 0; i < (cubic ? s[0].count : s[0].lin_count); ++i) {
          const int ii = (cubic ? s[0].first : s[0].lin_first) + i, jj = (cubic ? s[1].first : s[1].lin_first) + j,
                    kk = (cubic ? s[2].first : s[2].lin_first) + k;
          if (!L.is_valid(ii, jj, kk)) return false;
        }
    return true;
  };
  const bool linear_ok = all_valid(false);
  if (!linear_ok) return false;
  const bool cubic_ok = all_valid(true);
  for (std::size_t v = 0; v < nfields_; ++v) {
    const double* a = f[v];
    double lin = 0, lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < s[2].lin_count; ++k)
      for (int j = 0; j < s[1].lin_count; ++j)
        for (int i = 0; i < s[0].lin_count; ++i) {
          const double x = a[L.index(s[0].lin_first + i, s[1].lin_first + j, s[2].lin_first + k)];
          lin += s[0].lw[i] * s[1].lw[j] * s[2].lw[k] * x;
          lo = std::min(lo, x), hi = std::max(hi, x);
        }
    double value = lin;
    if (cubic_ok) {
      double c = 0;
      for (int k = 0; k < s[2].count; ++k)
        for (int j = 0; j < s[1].count; ++j) {
          double row = 0;
          for (int i = 0; i < s[0].count; ++i) row += s[0].w[i] * a[L.index(s[0].first + i, s[1].first + j, s[2].first + k)];
          c += s[1].w[j] * s[2].w[k] * row;
        }
      if (c >= lo && c <= hi) {
        value = c;
      } else {
        // A smooth extremum between the points may exceed their range (a star's centre), but not
        // change the sign they share (a surface: no negative density from an undershoot).
        const double m = smooth_overshoot(L, a, s);
        const double below = lo >= 0 ? std::max(lo - m, 0.0) : lo - m, above = hi <= 0 ? std::min(hi + m, 0.0) : hi + m;
        if (c >= below && c <= above) value = c;
      }
    }
    out[v] = value;
  }
  return true;
}

}  // namespace remnant::handoff
