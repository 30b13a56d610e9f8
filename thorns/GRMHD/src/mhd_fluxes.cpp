// Pass 1 of the MHD right-hand side: the hydro sweep of rhs.cpp with the magnetic terms. Along a
// line in direction d, the transverse cell-centred B^b, B^c (b, c the other two directions; their
// orthonormal components in curvilinear coordinates) are reconstructed with the fluid variables; the normal B^d at a face is the face field itself
// (continuous there, never reconstructed): Bface_d / psi^6. The HLL solve of the nine-component
// state (valencia_mhd.hpp) gives the hydro fluxes (flux_x/y/z, as for hydro) and the face data the
// edge EMFs need (ct_x/y/z, see mhd_groups.hpp). The lines cover one ghost layer in the used
// transverse directions, so that every edge of the interior (block edges included) has both
// neighbouring faces of each direction.
#include "mhd_fluxes.hpp"

#include <algorithm>
#include <cmath>

#include "GRMHD/face_thermo.hpp"
#include "GRMHD/valencia_mhd.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "line_scratch.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {
namespace {

// The signed scale factors h_c (sqrt f_cc = |h_c|) of the orthonormal components sqrt(f_cc) B^c:
// signed so that r B^theta, r sin(theta) B^phi, R B^phi continue smoothly into the ghosts across
// the origin and the axis (negative r, R, theta there).
Point3 scale_factors(CoordinateSystem cs, const Point3& x, double sin_theta) {
  switch (cs) {
    case CoordinateSystem::cartesian: return {1, 1, 1};
    case CoordinateSystem::cylindrical: return {1, 1, x[0]};
    case CoordinateSystem::spherical: return {1, x[0], x[0] * sin_theta};
  }
  return {1, 1, 1};
}

// The momentum flux F^d_j of a smooth field scales as h_j / h_d (T^d_j = h_j / h_d times orthonormal
// components): the exact face mean of that factor (weight sqrt f over the face of cell idx normal to
// d) over its value at the face centre x. The flux divergence with exact areas then sees the face
// means, which the geometric sources (exact cell averages) balance: O(1) near the origin and the
// axis, where the factor varies over the face by O(1) (1/r on a theta face: 3/(2 dr) vs 4/(3 dr)).
std::array<double, 3> momentum_flux_weights(const Block& b, int d, const int* idx, const Point3& x) {
  auto lo = [&](int e) { return b.face_coordinate(e, idx[e]); };
  auto hi = [&](int e) { return b.face_coordinate(e, idx[e] + 1); };
  auto checked = [](double w) { return std::isfinite(w) && w > 0 ? w : 1.0; };
  std::array<double, 3> c{1.0, 1.0, 1.0};
  if (b.coordinates == CoordinateSystem::cylindrical) {  // (R, z, phi), h = (1, 1, R), sqrt f = R
    const double r0 = lo(0), r1 = hi(0);
    if (d == 1) c[2] = checked((r1 * r1 * r1 - r0 * r0 * r0) / 3.0 / (0.5 * (r1 * r1 - r0 * r0)) / x[0]);
    if (d == 2) c[0] = c[1] = checked((r1 - r0) / (0.5 * (r1 * r1 - r0 * r0)) * x[0]);
  } else if (b.coordinates == CoordinateSystem::spherical) {  // h = (1, r, r sin theta), sqrt f = r^2 sin theta
    const double r0 = lo(0), r1 = hi(0), t0 = lo(1), t1 = hi(1);
    const double int_sin = std::cos(t0) - std::cos(t1);
    const double inv_r = checked(0.5 * (r1 * r1 - r0 * r0) / ((r1 * r1 * r1 - r0 * r0 * r0) / 3.0) * x[0]);
    const double st = std::sin(x[1]);
    if (d == 0) c[2] = checked(0.5 * ((t1 - t0) - 0.5 * (std::sin(2 * t1) - std::sin(2 * t0))) / int_sin / st);
    if (d == 1) c[0] = inv_r;
    if (d == 2) {
      c[1] = checked((t1 - t0) / int_sin * st);
      c[0] = inv_r * c[1];
    }
  }
  return c;
}

// rho, W v^1..3, thermal, Ye, B^b, B^c.
inline constexpr int kNumRecMhd = 8;
using MhdLineScratch = LineScratch<kNumRecMhd, kNumCons>;

template <class E>
void sweep_direction_mhd(const E& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg, Block& b, int d,
                         MhdLineScratch& L) {
  const int n = b.n[d], ng = b.ng[d];
  L.ensure(n, ng);
  Field prim[Prim::ncomp], met[Metric::ncomp], fout[kNumCons], ct[kNumCt], bvec[3];
  for (int c = 0; c < Prim::ncomp; ++c) prim[c] = b.field(g.prim, c);
  for (int c = 0; c < Metric::ncomp; ++c) met[c] = b.field(g.metric, c);
  for (int c = 0; c < kNumCons; ++c) fout[c] = b.field(g.flux[d], c);
  for (int c = 0; c < kNumCt; ++c) ct[c] = b.field(mg.ct[d], c);
  for (int c = 0; c < 3; ++c) bvec[c] = b.field(mg.bvec, c);
  const Field bn = b.field(mg.bface[d], 0);
  const std::ptrdiff_t stride = d == 0 ? 1 : d == 1 ? prim[0].sj : prim[0].sk;
  const std::ptrdiff_t fstride = d == 0 ? 1 : d == 1 ? fout[0].sj : fout[0].sk;
  // The transverse directions in cyclic order: the induction fluxes of B^{next}, B^{prev}.
  const int next = (d + 1) % 3, prev = (d + 2) % 3;
  const int a = d == 0 ? 1 : 0, c2 = d == 2 ? 1 : 2;
  const int lo_a = direction_used(b, a) ? -1 : 0, hi_a = b.n[a] + (direction_used(b, a) ? 1 : 0);
  const int lo_c = direction_used(b, c2) ? -1 : 0, hi_c = b.n[c2] + (direction_used(b, c2) ? 1 : 0);
  const CoordinateSystem cs = b.coordinates;
  const bool cartesian = cs == CoordinateSystem::cartesian;
  const PolarTrig trig(b);

  for (int ic = lo_c; ic < hi_c; ++ic)
    for (int ia = lo_a; ia < hi_a; ++ia) {
      int idx[3];
      idx[d] = 0;
      idx[a] = ia;
      idx[c2] = ic;
      const std::ptrdiff_t base = idx[0] + idx[1] * prim[0].sj + idx[2] * prim[0].sk;
      const std::ptrdiff_t fbase = idx[0] + idx[1] * fout[0].sj + idx[2] * fout[0].sk;
      {
        const double* pr = prim[Prim::idx::rho].origin + base;
        const double* pw = prim[Prim::idx::W].origin + base;
        const double* pv[3] = {prim[Prim::idx::vel].origin + base, prim[Prim::idx::vel2].origin + base,
                               prim[Prim::idx::vel3].origin + base};
        const double* pth = (reconstructs_pressure<E> ? prim[Prim::idx::press] : prim[Prim::idx::temperature]).origin + base;
        const double* pye = prim[Prim::idx::Ye].origin + base;
        const double* pbn = bvec[next].origin + base;
        const double* pbp = bvec[prev].origin + base;
        for (int m = -ng; m < n + ng; ++m) {
          const std::ptrdiff_t o = m * stride;
          const double W = pw[o];
          L.cell[0][m] = pr[o];
          L.cell[1][m] = W * pv[0][o];
          L.cell[2][m] = W * pv[1][o];
          L.cell[3][m] = W * pv[2][o];
          L.cell[4][m] = pth[o];
          L.cell[5][m] = pye[o];
          L.cell[6][m] = pbn[o];
          L.cell[7][m] = pbp[o];
        }
        for (int c = 0; c < Metric::ncomp; ++c) {
          const double* pm = met[c].origin + base;
          double* out = L.met[c];
          for (int m = -ng; m < n + ng; ++m) out[m] = pm[m * stride];
        }
        // Curvilinear: reconstruct the orthonormal components sqrt(f_bb) B^b, smooth through the
        // axis and the origin, not the coordinate components (B^theta ~ 1/r, B^phi ~ 1/R there).
        if (!cartesian) {
          int id[3] = {idx[0], idx[1], idx[2]};
          for (int m = -ng; m < n + ng; ++m) {
            id[d] = m;
            const Point3 h = scale_factors(cs, cell_point(b, id[0], id[1], id[2]), trig.sin_centre(id[1]));
            L.cell[6][m] *= h[next];
            L.cell[7][m] *= h[prev];
          }
        }
      }
      for (int q = 0; q < kNumRecMhd; ++q) reconstruct(s.reconstruction, L.cell[q], L.left[q], L.right[q], n, L.ppm);

      Point3 x = cell_point(b, idx[0], idx[1], idx[2]);
      // The face field is the sqrt(f)-weighted face mean of B^d; the face states need the point value
      // at the face centre: the orthonormal mean (orthonormal_factor) over the scale factor h_d there.
      // They differ by O(1) in the first cells (B^theta ~ 1/r weighted with r^2: 3/(2 dr) instead of
      // 2/dr), which unbalanced the magnetic stress of a uniform field at the origin.
      double normal_factor = 1.0;
      if (!cartesian) {
        const double h = scale_factors(cs, x, trig.sin_centre(idx[1]))[d];
        if (h != 0) normal_factor = hydrobase::orthonormal_factor(b, d, idx) / h;
      }
      const std::array<double, 3> flux_weight =
          cartesian ? std::array<double, 3>{1.0, 1.0, 1.0} : momentum_flux_weights(b, d, idx, x);
      std::array<double, 3> fd{1.0, 1.0, 1.0};
      for (int f = 0; f <= n; ++f) {
        const double psi = face_value(s.metric_faces, L.met[Metric::idx::psi], f);
        const double alpha = face_value(s.metric_faces, L.met[Metric::idx::alpha], f);
        std::array<double, 3> beta{face_value(s.metric_faces, L.met[Metric::idx::beta], f),
                                   face_value(s.metric_faces, L.met[Metric::idx::beta2], f),
                                   face_value(s.metric_faces, L.met[Metric::idx::beta3], f)};
        if (!cartesian) {
          x[d] = b.face_coordinate(d, f);
          fd = coords::metric_diagonal(cs, x, d == 1 ? trig.sin_face(f) : trig.sin_centre(idx[1]));
        }
        const PointMetric pm = cartesian ? point_metric_cartesian(psi, alpha, beta) : point_metric(psi, alpha, beta, fd);
        const double p2 = psi * psi;
        const double psi6 = p2 * p2 * p2;
        FluidState sl, sr;
        sl.rho = L.left[0][f];
        sr.rho = L.right[0][f];
        sl.ye = L.left[5][f];
        sr.ye = L.right[5][f];
        set_velocity_from_wv(sl, pm, L.left[1][f], L.left[2][f], L.left[3][f]);
        set_velocity_from_wv(sr, pm, L.right[1][f], L.right[2][f], L.right[3][f]);
        complete_face_thermo(eos, sl, L.left[4][f]);
        complete_face_thermo(eos, sr, L.right[4][f]);
        std::array<double, 3> Bl, Br;
        Bl[d] = Br[d] = bn.origin[fbase + f * fstride] * normal_factor / psi6;
        Bl[next] = L.left[6][f];
        Br[next] = L.right[6][f];
        Bl[prev] = L.left[7][f];
        Br[prev] = L.right[7][f];
        if (!cartesian) {
          // Back to coordinate components; on a face on the axis or at the origin (zero factor) the
          // regular field has no such component.
          const Point3 h = scale_factors(cs, x, d == 1 ? trig.sin_face(f) : trig.sin_centre(idx[1]));
          const double in = h[next] != 0 ? 1.0 / h[next] : 0.0, ip = h[prev] != 0 ? 1.0 / h[prev] : 0.0;
          Bl[next] *= in, Br[next] *= in, Bl[prev] *= ip, Br[prev] *= ip;
        }
        const MagneticState ml = magnetic_state(sl, pm, Bl[0], Bl[1], Bl[2]);
        const MagneticState mr = magnetic_state(sr, pm, Br[0], Br[1], Br[2]);
        double ul[kNumMhd], ur[kNumMhd], fl[kNumMhd], fr[kNumMhd], fh[kNumMhd];
        conserved_mhd(sl, ml, ul);
        conserved_mhd(sr, mr, ur);
        flux_mhd(d, sl, ml, pm, ul, fl);
        flux_mhd(d, sr, mr, pm, ur, fr);
        double lml, lpl, lmr, lpr;
        characteristic_speeds_mhd(d, sl, ml, pm, lml, lpl);
        characteristic_speeds_mhd(d, sr, mr, pm, lmr, lpr);
        hll_flux_n<kNumMhd>(ul, ur, fl, fr, lml, lpl, lmr, lpr, fh);
        const std::ptrdiff_t fo = fbase + f * fstride;
        for (int j = 0; j < 3; ++j) fh[kS1 + j] *= flux_weight[j];
        for (int c = 0; c < kNumCons; ++c) fout[c].origin[fo] = fh[c] * psi6;
        ct[kAlphaPlus].origin[fo] = std::max({0.0, lpl, lpr});
        ct[kAlphaMinus].origin[fo] = -std::min({0.0, lml, lmr});
        ct[kVtLeft].origin[fo] = alpha * sl.v[d] - beta[d];
        ct[kVtRight].origin[fo] = alpha * sr.v[d] - beta[d];
        ct[kFluxNext].origin[fo] = fh[kB1 + next] * psi6;
        ct[kFluxPrev].origin[fo] = fh[kB1 + prev] * psi6;
      }
    }
}

template <class E>
void block_fluxes_mhd(const E& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg, Block& b) {
  thread_local MhdLineScratch scratch;
  for (int d = 0; d < 3; ++d)
    if (direction_used(b, d)) sweep_direction_mhd(eos, s, g, mg, b, d, scratch);
}

}  // namespace

void compute_block_fluxes_mhd(const eos::EOS& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg,
                              Block& b) {
  eos.visit([&](const auto& e) { block_fluxes_mhd(e, s, g, mg, b); });
}

}  // namespace remnant::grmhd
