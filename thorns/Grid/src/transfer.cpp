#include "transfer.hpp"

#include <algorithm>
#include <cmath>

#include "remnant/limiters.hpp"

namespace remnant::grid {

namespace {

std::int64_t floor_half(std::int64_t i) { return i >= 0 ? i / 2 : -((1 - i) / 2); }

struct Kernel {
  const Transfer& t;
  const Field& src;
  const std::array<int, 3>& stagger;
  int dim;
  const LevelGeometry& geo;

  double at(std::int64_t I, std::int64_t J, std::int64_t K) const {
    return src(static_cast<int>(I - t.src_origin[0]), static_cast<int>(J - t.src_origin[1]),
               static_cast<int>(K - t.src_origin[2]));
  }

  // Q: image point on the destination level.
  double restrict_at(const Range& Q) const {
    const int fine = t.dst_level + 1;
    std::array<int, 3> nchild{1, 1, 1};
    for (int d = 0; d < dim; ++d) nchild[static_cast<std::size_t>(d)] = stagger[static_cast<std::size_t>(d)] ? 1 : 2;
    double sum = 0, wsum = 0;
    for (int c2 = 0; c2 < nchild[2]; ++c2)
      for (int c1 = 0; c1 < nchild[1]; ++c1)
        for (int c0 = 0; c0 < nchild[0]; ++c0) {
          const int c[3] = {c0, c1, c2};
          Range F{};
          double w = 1;
          for (int d = 0; d < 3; ++d) {
            const auto ud = static_cast<std::size_t>(d);
            F[ud] = d < dim ? 2 * Q[ud] + c[d] : Q[ud];
            // A face's area factor g_d is common to its fine faces: only tangential weights count.
            if (d < dim && !stagger[ud]) w *= geo.weight(fine, d, F[ud]);
          }
          sum += w * at(F[0], F[1], F[2]);
          wsum += w;
        }
    return sum / wsum;
  }

  double prolong_at(const Range& Q) const {
    const int coarse = t.dst_level - 1;
    Range J{};
    for (std::size_t d = 0; d < 3; ++d) J[d] = static_cast<int>(d) < dim ? floor_half(Q[d]) : Q[d];
    const bool cells = stagger[0] == 0 && stagger[1] == 0 && stagger[2] == 0;
    if (!cells) {
      // Faces: linear between the two coarse faces in the normal direction, constant across it.
      // Edges: bilinear between the coarse nodes in their staggered directions, constant along.
      int odd[3], m = 0;
      for (int d = 0; d < dim; ++d)
        if (stagger[static_cast<std::size_t>(d)] && Q[static_cast<std::size_t>(d)] % 2 != 0) odd[m++] = d;
      if (m == 0) return at(J[0], J[1], J[2]);
      double sum = 0;
      for (int c = 0; c < (1 << m); ++c) {
        Range Jc = J;
        for (int b = 0; b < m; ++b) Jc[static_cast<std::size_t>(odd[b])] += (c >> b) & 1;
        sum += at(Jc[0], Jc[1], Jc[2]);
      }
      return sum / static_cast<double>(1 << m);
    }
    const double u0 = at(J[0], J[1], J[2]);
    double v = u0;
    for (int d = 0; d < dim; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      Range Jm = J, Jp = J;
      Jm[ud] -= 1;
      Jp[ud] += 1;
      const double s = mc_slope(at(Jm[0], Jm[1], Jm[2]), u0, at(Jp[0], Jp[1], Jp[2]), geo.centroid(coarse, d, Jm[ud]),
                                geo.centroid(coarse, d, J[ud]), geo.centroid(coarse, d, Jp[ud]));
      v += s * (geo.centroid(t.dst_level, d, Q[ud]) - geo.centroid(coarse, d, J[ud]));
    }
    return v;
  }
};

}  // namespace

void apply_transfer(const Transfer& t, const Field& src, const Field& dst, double sign,
                    const std::array<int, 3>& stagger, int dimension, const LevelGeometry& geometry) {
  const Box& b = t.dst_box;
  if (t.kind == TransferKind::copy && t.map.preserves_orientation()) {
    // The common case (same level, no mirror): contiguous rows.
    const int nx = b.size(0);
    const std::int64_t off[3] = {t.dst_origin[0] + t.map.shift[0] - t.src_origin[0],
                                 t.dst_origin[1] + t.map.shift[1] - t.src_origin[1],
                                 t.dst_origin[2] + t.map.shift[2] - t.src_origin[2]};
    for (int k = b.lo[2]; k < b.hi[2]; ++k)
      for (int j = b.lo[1]; j < b.hi[1]; ++j) {
        const double* s = &src(static_cast<int>(b.lo[0] + off[0]), static_cast<int>(j + off[1]), static_cast<int>(k + off[2]));
        double* d = &dst(b.lo[0], j, k);
        if (sign == 1.0) copy_row(s, nx, d);
        else
          for (int i = 0; i < nx; ++i) d[i] = sign * s[i];
      }
    return;
  }
  const Kernel kernel{t, src, stagger, dimension, geometry};
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j)
      for (int i = b.lo[0]; i < b.hi[0]; ++i) {
        const Range P{t.dst_origin[0] + i, t.dst_origin[1] + j, t.dst_origin[2] + k};
        const Range Q{t.map.apply(0, P[0]), t.map.apply(1, P[1]), t.map.apply(2, P[2])};
        double v = 0;
        switch (t.kind) {
          case TransferKind::copy: v = kernel.at(Q[0], Q[1], Q[2]); break;
          case TransferKind::restrict: v = kernel.restrict_at(Q); break;
          case TransferKind::prolong: v = kernel.prolong_at(Q); break;
        }
        dst(i, j, k) = sign * v;
      }
}

}  // namespace remnant::grid
