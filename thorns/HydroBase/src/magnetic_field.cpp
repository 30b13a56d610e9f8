#include "HydroBase/magnetic_field.hpp"

#include <cmath>
#include <vector>

#include "remnant/cell_geometry.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::hydrobase {

bool magnetic_field_evolved(const Context& ctx) {
  return ctx.param<std::string>("HydroBase", "magnetic_field") == "evolved";
}

FieldGroups FieldGroups::of(const Context& ctx) {
  FieldGroups g;
  if (!magnetic_field_evolved(ctx)) return g;
  for (int d = 0; d < 3; ++d) g.bface[d] = ctx.var("HydroBase::Bface" + std::to_string(d + 1));
  g.bvec = ctx.var("HydroBase::Bvec");
  g.metric = vars::Spacetime::metric::id(ctx);
  return g;
}

double orthonormal_factor(const Block& b, int c, const int* id) {
  auto width = [&](int e) { return b.face_coordinate(e, id[e] + 1) - b.face_coordinate(e, id[e]); };
  auto half_square_step = [&](int e) {
    const double lo = b.face_coordinate(e, id[e]), hi = b.face_coordinate(e, id[e] + 1);
    return 0.5 * (hi * hi - lo * lo);
  };
  switch (b.coordinates) {
    case CoordinateSystem::cartesian: return 1.0;
    case CoordinateSystem::cylindrical:  // (R, z, phi)
      return c == 2 ? b.volume_weight(0, id[0]) / width(0) : 1.0;
    case CoordinateSystem::spherical: {  // (r, theta, phi)
      if (c == 0) return 1.0;
      const double radial = b.volume_weight(0, id[0]) / half_square_step(0);
      return c == 1 ? radial : radial * b.volume_weight(1, id[1]) / width(1);
    }
  }
  return 1.0;
}

namespace {

// Rows of cells along x (i fastest), one pass per row: 1/psi^6 once for the three components, the
// face areas as Block::face_area multiplies them ((g_0 g_1) g_2, the face factor in direction a, the
// volume weights in the others) from the per-direction arrays, and the weighted mean as a select,
// so that the row vectorises; the same operations as the per-cell formula, hence the same bits.
struct RowScratch {
  std::vector<double> ipsi6, mean;
  void ensure(int n) {
    ipsi6.resize(static_cast<std::size_t>(n));
    mean.resize(static_cast<std::size_t>(n));
  }
};

// The area-weighted mean of the two faces of direction a for cells i = 0..n-1 of a row: g0m/g0p the
// x factors of the lower/upper faces (arrays), g1*, g2* the product's constant factors; times
// ipsi6[i] where given (the cell-centred B itself), else the mean alone.
void face_mean_row(const double* __restrict lo, const double* __restrict hi, const double* __restrict g0m,
                   const double* __restrict g0p, double g1m, double g2m, double g1p, double g2p,
                   const double* __restrict ipsi6, double* __restrict out, int n) {
  const auto mean = [&](int i) {
    const double am = g0m[i] * g1m * g2m, ap = g0p[i] * g1p * g2p;  // 1.0 * g0 * g1 * g2, as face_area
    const double w = am + ap;
    const double weighted = (am * lo[i] + ap * hi[i]) / w, plain = 0.5 * (lo[i] + hi[i]);
    return w > 0 ? weighted : plain;
  };
  if (ipsi6)
    for (int i = 0; i < n; ++i) out[i] = mean(i) * ipsi6[i];
  else
    for (int i = 0; i < n; ++i) out[i] = mean(i);
}

}  // namespace

void cell_centred_field(const FieldGroups& g, Block& b) {
  const Field psi = b.field(g.metric, vars::Spacetime::metric::idx::psi);
  const bool curvilinear = b.coordinates != CoordinateSystem::cartesian;
  Field bf[3], out[3];
  bool used[3];
  const double *ff[3], *vw[3];
  for (int a = 0; a < 3; ++a) {
    bf[a] = b.field(g.bface[a], 0);
    out[a] = b.field(g.bvec, a);
    used[a] = direction_used(b, a);
    ff[a] = b.face_factors(a);
    vw[a] = b.volume_weights(a);
  }
  const int n = b.n[0];
  thread_local RowScratch scratch;
  scratch.ensure(n);
  double* __restrict ipsi6 = scratch.ipsi6.data();
  double* __restrict mean = scratch.mean.data();
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j) {
      const double* ps = &psi(0, j, k);
      for (int i = 0; i < n; ++i) {
        const double p2 = ps[i] * ps[i];
        ipsi6[i] = 1.0 / (p2 * p2 * p2);
      }
      for (int a = 0; a < 3; ++a) {
        const double* lo = &bf[a](0, j, k);
        double* o = &out[a](0, j, k);
        if (!used[a]) {  // the one face of an unused direction
          for (int i = 0; i < n; ++i) o[i] = lo[i] * ipsi6[i];
          continue;
        }
        const std::ptrdiff_t up = a == 0 ? 1 : a == 1 ? bf[a].sj : bf[a].sk;
        const double* g0 = a == 0 ? ff[0] : vw[0];
        const double g1m = a == 1 ? ff[1][j] : vw[1][j], g1p = a == 1 ? ff[1][j + 1] : vw[1][j];
        const double g2m = a == 2 ? ff[2][k] : vw[2][k], g2p = a == 2 ? ff[2][k + 1] : vw[2][k];
        if (!curvilinear || a == 0) {  // straight into Bvec
          face_mean_row(lo, lo + up, g0, a == 0 ? g0 + 1 : g0, g1m, g2m, g1p, g2p, ipsi6, o, n);
          continue;
        }
        // Curvilinear theta, phi: the orthonormal factor between the mean and 1/psi^6.
        face_mean_row(lo, lo + up, g0, a == 0 ? g0 + 1 : g0, g1m, g2m, g1p, g2p, nullptr, mean, n);
        for (int i = 0; i < n; ++i) {
          const int id[3] = {i, j, k};
          const Point3 f = coords::metric_diagonal(b.coordinates, cell_point(b, i, j, k));
          mean[i] *= orthonormal_factor(b, a, id) / std::sqrt(f[a]);
        }
        for (int i = 0; i < n; ++i) o[i] = mean[i] * ipsi6[i];
      }
    }
}

}  // namespace remnant::hydrobase
