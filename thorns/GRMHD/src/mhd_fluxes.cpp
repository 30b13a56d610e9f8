// Pass 1 of the MHD right-hand side: the hydro sweep of rhs.cpp with the magnetic terms. Along a
// line in direction d, the transverse cell-centred B^b, B^c (b, c the other two directions) are
// reconstructed with the fluid variables; the normal B^d at a face is the face field itself
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
#include "line_scratch.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {
namespace {

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
      }
      for (int q = 0; q < kNumRecMhd; ++q) reconstruct(s.reconstruction, L.cell[q], L.left[q], L.right[q], n, L.ppm);

      Point3 x = cell_point(b, idx[0], idx[1], idx[2]);
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
        Bl[d] = Br[d] = bn.origin[fbase + f * fstride] / psi6;
        Bl[next] = L.left[6][f];
        Br[next] = L.right[6][f];
        Bl[prev] = L.left[7][f];
        Br[prev] = L.right[7][f];
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
