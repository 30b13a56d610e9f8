// Pass 1 of the MHD right-hand side: the hydro sweep of rhs.cpp with the magnetic terms. Along a
// line in direction d, the transverse cell-centred B^b, B^c (b, c the other two directions; their
// orthonormal components in curvilinear coordinates) are reconstructed with the fluid variables; the normal B^d at a face is the face field itself
// (continuous there, never reconstructed): Bface_d / psi^6. The HLL solve of the nine-component
// state (valencia_mhd.hpp) gives the hydro fluxes (flux_x/y/z, as for hydro) and the face data the
// edge EMFs need (CtFaces, see ct_faces.hpp). The lines cover one ghost layer in the used
// transverse directions, so that every edge of the interior (block edges included) has both
// neighbouring faces of each direction.
#include "mhd_fluxes.hpp"

#include <algorithm>
#include <cmath>

#include "HydroBase/magnetic_field.hpp"
#include "face_kernel_mhd.hpp"
#include "kernel_isa.hpp"
#include "line_scratch.hpp"
#include "line_sweep.hpp"
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

// always_inline: into the portable and the AVX2 wrappers of block_fluxes_mhd, each flattened whole.
template <int D, class E>
[[gnu::always_inline]] inline void sweep_direction_mhd(const E& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg,
                                                      const CtFaces& ctf, Block& b, MhdLineScratch& L,
                                                      const MhdSweepOutputs& outputs) {
  const int n = b.n[D], ng = b.ng[D];
  L.ensure(n, ng);
  const SweepFields<D> fields(b, g);
  const auto& ct = ctf.f[D];
  Field bvec[3];
  for (int c = 0; c < 3; ++c) bvec[c] = b.field(mg.bvec, c);
  const Field bn = b.field(mg.bface[D], 0);
  // The transverse directions in cyclic order: the induction fluxes of B^{next}, B^{prev}.
  constexpr int next = (D + 1) % 3, prev = (D + 2) % 3;
  constexpr int a = SweepFields<D>::first_transverse, c2 = SweepFields<D>::second_transverse;
  const int lo_a = direction_used(b, a) ? -1 : 0, hi_a = b.n[a] + (direction_used(b, a) ? 1 : 0);
  const int lo_c = direction_used(b, c2) ? -1 : 0, hi_c = b.n[c2] + (direction_used(b, c2) ? 1 : 0);
  const CoordinateSystem cs = b.coordinates;
  const bool cartesian = cs == CoordinateSystem::cartesian;
  const PolarTrig trig(b);
  const LineSources src = LineSources::of<E>(fields.prim, fields.met);
  const double* const transverse_field[2] = {bvec[next].origin, bvec[prev].origin};
  double* out[kNumFluxMhd];
  for (int c = 0; c < kNumCons; ++c) out[c] = fields.flux[c].origin;
  for (int c = 0; c < kNumCt; ++c) out[kNumCons + c] = ct[c].origin;
  if (cartesian)
    for (int f = 0; f <= n; ++f) L.work[kWorkInvNext][f] = L.work[kWorkInvPrev][f] = 1.0;

  for (int ic = lo_c; ic < hi_c; ++ic)
    for (int ia = lo_a; ia < hi_a; ++ia) {
      const std::array<int, 3> idx = SweepFields<D>::line_start(ia, ic);
      const std::ptrdiff_t base = fields.cell_offset(idx), fbase = fields.face_offset(idx);
      gather_line<E>(src, transverse_field, base, fields.stride, n, ng, L);
      // Curvilinear: reconstruct the orthonormal components sqrt(f_bb) B^b, smooth through the
      // axis and the origin, not the coordinate components (B^theta ~ 1/r, B^phi ~ 1/R there).
      if (!cartesian) {
        int id[3] = {idx[0], idx[1], idx[2]};
        for (int m = -ng; m < n + ng; ++m) {
          id[D] = m;
          const Point3 h = scale_factors(cs, cell_point(b, id[0], id[1], id[2]), trig.sin_centre(id[1]));
          L.cell[kRecBNext][m] *= h[next];
          L.cell[kRecBPrev][m] *= h[prev];
        }
      }
      // A ghost line of uct_hll gives only speeds: the ideal gas's need no Ye.
      const bool speeds_only = !outputs.ghost_line_fluxes && (ia < 0 || ia >= b.n[a] || ic < 0 || ic >= b.n[c2]);
      reconstruct_line<D, E>(s, b, trig, idx, n, src, base, fields.stride, L, speeds_only && reconstructs_pressure<E>);
      if constexpr (reconstructs_pressure<E>)
        if (s.well_balanced)
          well_balanced_faces(IdealIsentrope{eos.gamma()}, s.reconstruction, s.metric_faces,
                              src.met[Metric::idx::alpha] + base, fields.stride, n, ng, L);

      Point3 x = cell_point(b, idx[0], idx[1], idx[2]);
      // The face field is the sqrt(f)-weighted face mean of B^d; the face states need the point value
      // at the face centre: the orthonormal mean (orthonormal_factor) over the scale factor h_d there.
      // They differ by O(1) in the first cells (B^theta ~ 1/r weighted with r^2: 3/(2 dr) instead of
      // 2/dr), which unbalanced the magnetic stress of a uniform field at the origin.
      double normal_factor = 1.0;
      if (!cartesian) {
        const double h = scale_factors(cs, x, trig.sin_centre(idx[1]))[D];
        if (h != 0) normal_factor = hydrobase::orthonormal_factor(b, D, idx.data()) / h;
      }
      const std::array<double, 3> flux_weight =
          cartesian ? std::array<double, 3>{1.0, 1.0, 1.0} : momentum_flux_weights(b, D, idx.data(), x);
      // The face field keeps the Grid's ghosts, the flux groups fewer (thorn.yaml): its own offsets.
      const double* pbn = bn.origin + (idx[0] + idx[1] * bn.sj + idx[2] * bn.sk);
      const std::ptrdiff_t bn_stride = D == 0 ? 1 : D == 1 ? bn.sj : bn.sk;
      for (int f = 0; f <= n; ++f) L.work[kWorkBNormal][f] = pbn[f * bn_stride] * normal_factor / L.face.psi6[f];
      if (!cartesian)
        for (int f = 0; f <= n; ++f) {
          // Back to coordinate components; on a face on the axis or at the origin (zero factor) the
          // regular field has no such component.
          x[D] = b.face_coordinate(D, f);
          const Point3 h = scale_factors(cs, x, D == 1 ? trig.sin_face(f) : trig.sin_centre(idx[1]));
          L.work[kWorkInvNext][f] = h[next] != 0 ? 1.0 / h[next] : 0.0;
          L.work[kWorkInvPrev][f] = h[prev] != 0 ? 1.0 / h[prev] : 0.0;
        }
      // Straight into the flux groups and the face data (strided across x).
      const auto face_out = line_face_output<D, kNumFluxMhd>(out, fbase, fields.flux_stride);
      if (speeds_only) mhd_face_speeds<D>(eos, n, L, face_out);
      else if (outputs.induction_fluxes) mhd_face_fluxes<D, true>(eos, n, flux_weight, L, face_out);
      else mhd_face_fluxes<D, false>(eos, n, flux_weight, L, face_out);
    }
}

template <class E>
[[gnu::always_inline]] inline void block_fluxes_mhd_body(const E& eos, const RhsSettings& s, const Groups& g,
                                                         const MhdGroups& mg, const CtFaces& ct, Block& b,
                                                         const MhdSweepOutputs& outputs, MhdLineScratch& scratch) {
  if (direction_used(b, 0)) sweep_direction_mhd<0>(eos, s, g, mg, ct, b, scratch, outputs);
  if (direction_used(b, 1)) sweep_direction_mhd<1>(eos, s, g, mg, ct, b, scratch, outputs);
  if (direction_used(b, 2)) sweep_direction_mhd<2>(eos, s, g, mg, ct, b, scratch, outputs);
}
template <class E>
[[gnu::flatten]] void block_fluxes_mhd_portable(const E& eos, const RhsSettings& s, const Groups& g,
                                                const MhdGroups& mg, const CtFaces& ct, Block& b,
                                                const MhdSweepOutputs& outputs, MhdLineScratch& scratch) {
  block_fluxes_mhd_body(eos, s, g, mg, ct, b, outputs, scratch);
}
#if REMNANT_HAVE_AVX2_KERNELS
template <class E>
REMNANT_AVX2_KERNEL void block_fluxes_mhd_avx2(const E& eos, const RhsSettings& s, const Groups& g,
                                               const MhdGroups& mg, const CtFaces& ct, Block& b,
                                               const MhdSweepOutputs& outputs, MhdLineScratch& scratch) {
  block_fluxes_mhd_body(eos, s, g, mg, ct, b, outputs, scratch);
}
#endif
template <class E>
void block_fluxes_mhd(const E& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg, const CtFaces& ct,
                      Block& b, const MhdSweepOutputs& outputs) {
  thread_local MhdLineScratch scratch;
#if REMNANT_HAVE_AVX2_KERNELS
  if (avx2_kernels()) return block_fluxes_mhd_avx2(eos, s, g, mg, ct, b, outputs, scratch);
#endif
  block_fluxes_mhd_portable(eos, s, g, mg, ct, b, outputs, scratch);
}

}  // namespace

MhdSweepOutputs MhdSweepOutputs::for_emfs(EmfScheme emfs, const Block& b) {
  MhdSweepOutputs o;
  if (emfs != EmfScheme::uct_hll) return o;
  o.ghost_line_fluxes = false;
  // uct_hll reads an induction flux only at edges with one transverse direction unused (its 1D flux).
  o.induction_fluxes = !(direction_used(b, 0) && direction_used(b, 1) && direction_used(b, 2));
  return o;
}

void compute_block_fluxes_mhd(const eos::EOS& eos, const RhsSettings& s, const Groups& g, const MhdGroups& mg,
                              const CtFaces& ct, Block& b, EmfScheme emfs) {
  const MhdSweepOutputs outputs = MhdSweepOutputs::for_emfs(emfs, b);
  eos.visit([&](const auto& e) { block_fluxes_mhd(e, s, g, mg, ct, b, outputs); });
}

}  // namespace remnant::grmhd
