#include "lohner.hpp"

#include <algorithm>
#include <cmath>

namespace remnant::grid {

double lohner_estimate(const Block& b, const Field& f, int dim, bool log_scale, double eps) {
  auto u = [&](int i, int j, int k) {
    const double v = f(i, j, k);
    return log_scale ? std::log10(std::max(std::abs(v), 1e-300)) : v;
  };
  const std::ptrdiff_t step[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double worst = 0;
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        const double c = u(i, j, k);
        double num = 0, den = 0;
        for (int p = 0; p < dim; ++p) {
          const auto* sp = step[p];
          const int ip = static_cast<int>(sp[0]), jp = static_cast<int>(sp[1]), kp = static_cast<int>(sp[2]);
          for (int q = 0; q < dim; ++q) {
            const auto* sq = step[q];
            const int iq = static_cast<int>(sq[0]), jq = static_cast<int>(sq[1]), kq = static_cast<int>(sq[2]);
            double d2, d1;
            double filt;
            if (p == q) {
              const double a = u(i + ip, j + jp, k + kp), z = u(i - ip, j - jp, k - kp);
              d2 = a - 2 * c + z;
              d1 = std::abs(a - c) + std::abs(c - z);
              filt = std::abs(a) + 2 * std::abs(c) + std::abs(z);
            } else {
              const double pp = u(i + ip + iq, j + jp + jq, k + kp + kq), pm = u(i + ip - iq, j + jp - jq, k + kp - kq);
              const double mp = u(i - ip + iq, j - jp + jq, k - kp + kq), mm = u(i - ip - iq, j - jp - jq, k - kp - kq);
              d2 = 0.25 * (pp - pm - mp + mm);
              d1 = 0.5 * (std::abs(pp - mp) + std::abs(pm - mm));
              filt = 0.25 * (std::abs(pp) + std::abs(pm) + std::abs(mp) + std::abs(mm));
            }
            num += d2 * d2;
            const double t = d1 + eps * filt;
            den += t * t;
          }
        }
        if (den > 0) worst = std::max(worst, std::sqrt(num / den));
      }
  return worst;
}

int lohner_wish(double estimate, double threshold, double derefine_ratio) {
  if (estimate > threshold) return 1;
  if (estimate < derefine_ratio * threshold) return -1;
  return 0;
}

}  // namespace remnant::grid
