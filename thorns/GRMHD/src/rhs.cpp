// GRMHD right-hand side. Pass 1: for each direction, lines of cells are gathered into contiguous
// buffers, reconstructed (rho, W v^i, p or T and p, Ye), completed by the EOS and turned into HLL flux
// densities psi^6 F at the faces. Pass 2 (after the Grid's flux correction): flux divergence with
// exact face areas and volumes, plus sources, cell by cell with i fastest.
#include "rhs.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "GRMHD/face_thermo.hpp"
#include "GRMHD/sources.hpp"
#include "GRMHD/sources_mhd.hpp"
#include "GRMHD/valencia.hpp"
#include "centroid_derivative.hpp"
#include "face_kernel.hpp"
#include "kernel_isa.hpp"
#include "line_scratch.hpp"
#include "line_sweep.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {
namespace {

using HydroLineScratch = LineScratch<kNumRecHydro, kNumCons>;

// always_inline: into the portable and the AVX2 wrappers of block_fluxes, each flattened whole.
template <int D, class E>
[[gnu::always_inline]] inline void sweep_direction(const E& eos, const RhsSettings& s, const Groups& g, Block& b, HydroLineScratch& L) {
  const int n = b.n[D], ng = b.ng[D];
  L.ensure(n, ng);
  const SweepFields<D> fields(b, g);
  const LineSources src = LineSources::of<E>(fields.prim, fields.met);
  double* out[kNumCons];
  for (int c = 0; c < kNumCons; ++c) out[c] = fields.flux[c].origin;
  const PolarTrig trig(b);

  for (int ic = 0; ic < b.n[SweepFields<D>::second_transverse]; ++ic)
    for (int ia = 0; ia < b.n[SweepFields<D>::first_transverse]; ++ia) {
      const std::array<int, 3> idx = SweepFields<D>::line_start(ia, ic);
      const std::ptrdiff_t base = fields.cell_offset(idx), fbase = fields.face_offset(idx);
      gather_line<E>(src, nullptr, base, fields.stride, n, ng, L);
      reconstruct_line<D, E>(s, b, trig, idx, n, src, base, fields.stride, L);
      if constexpr (reconstructs_pressure<E>)
        if (s.well_balanced)
          well_balanced_faces(IdealIsentrope{eos.gamma()}, s.reconstruction, s.metric_faces,
                              src.met[Metric::idx::alpha] + base, fields.stride, n, ng, L);
      hydro_face_fluxes<D>(eos, n, L, line_face_output<D, kNumCons>(out, fbase, fields.flux_stride));
    }
}

// The flux divergence of pass 2 for a row of cells (i fastest), summed as the per-cell loop did:
// from 0.0, d = 0, 1, 2, each term (A+ F+ - A- F-) / V subtracted; one loop per direction and
// component, which vectorises. Along x the face factors and volumes change with i.
void subtract_divergence_x(double* __restrict out, const double* __restrict F, const double* __restrict area,
                           const double* __restrict volume, int n) {
  for (int i = 0; i < n; ++i) out[i] -= (area[i + 1] * F[i + 1] - area[i] * F[i]) * (1.0 / volume[i]);
}
void subtract_divergence_transverse(double* __restrict out, const double* __restrict F_plus,
                                    const double* __restrict F_minus, double ap, double am, double iv, int n) {
  for (int i = 0; i < n; ++i) out[i] -= (ap * F_plus[i] - am * F_minus[i]) * iv;
}

// The sources of a row of 3D Cartesian cells from o0 on (f = 1, no Christoffels, every direction
// used): the per-cell code of divergence_and_sources with its coordinate, direction and shift
// branches resolved outside the loop, and
// flattened (every pointwise function inlined), so that the row vectorises; the same operations.
// The flux divergence of such a row, as subtract_divergence_x / _transverse compute it from 0.0:
// the fluxes of the row's faces and its face factors and volume weights.
struct RowDivergence {
  const double* x[kNumCons];  // x faces 0..n
  const double* minus[2][kNumCons];  // y and z faces below and above the row
  const double* plus[2][kNumCons];
  const double* area_x;
  const double* volume_x;
  double area_plus[2], area_minus[2], inv_volume[2];
};

// The metric of cell o, and its centred differences along the directions `used` (the shift's only
// with `shift`). The vectorised Cartesian rows (every direction used, constant flags) and the
// per-cell loop share them, so both take the same operations.
struct CellMetric {
  double psi, alpha;
  std::array<double, 3> beta;
};
[[gnu::always_inline]] inline CellMetric metric_at(const Field* met, std::ptrdiff_t o) {
  return {met[Metric::idx::psi].origin[o], met[Metric::idx::alpha].origin[o],
          {met[Metric::idx::beta].origin[o], met[Metric::idx::beta2].origin[o], met[Metric::idx::beta3].origin[o]}};
}
[[gnu::always_inline]] inline MetricDerivatives metric_derivatives_at(const Field* met, std::ptrdiff_t o,
                                                                      const std::array<std::ptrdiff_t, 3>& st,
                                                                      const std::array<double, 3>& inv2dx,
                                                                      const std::array<bool, 3>& used, bool shift) {
  MetricDerivatives dm;
#pragma GCC unroll 3
  for (int d = 0; d < 3; ++d) {
    if (!used[d]) continue;
    const std::ptrdiff_t s = st[d];
    dm.dpsi[d] = (met[Metric::idx::psi].origin[o + s] - met[Metric::idx::psi].origin[o - s]) * inv2dx[d];
    dm.dalpha[d] = (met[Metric::idx::alpha].origin[o + s] - met[Metric::idx::alpha].origin[o - s]) * inv2dx[d];
    if (shift)
      for (int c = 0; c < 3; ++c)
        dm.dbeta[d][c] = (met[Metric::idx::beta + c].origin[o + s] - met[Metric::idx::beta + c].origin[o - s]) * inv2dx[d];
  }
  return dm;
}
// Adds w (f(i+1) - 2 f(i) + f(i-1)) to the centred differences: the derivative at the centroid
// (centroid_derivative.hpp); w = 0 along Cartesian-like directions, which keep their bits.
inline void move_derivatives_to_centroid(MetricDerivatives& dm, const Field* met, std::ptrdiff_t o,
                                         const std::array<std::ptrdiff_t, 3>& st, const CentroidOffsets& centroid,
                                         const int* id, const std::array<bool, 3>& used, bool shift) {
  for (int d = 0; d < 3; ++d) {
    const double w = centroid.weight(d, id[d]);
    if (!used[d] || w == 0.0) continue;
    const std::ptrdiff_t s = st[d];
    const auto curvature = [&](int var) {
      const double* f = met[var].origin + o;
      return w * (f[s] - 2.0 * f[0] + f[-s]);
    };
    dm.dpsi[d] += curvature(Metric::idx::psi);
    dm.dalpha[d] += curvature(Metric::idx::alpha);
    if (shift)
      for (int c = 0; c < 3; ++c) dm.dbeta[d][c] += curvature(Metric::idx::beta + c);
  }
}

// The fluid state of cell o from the primitives, with v_i and v^2 from the point metric.
[[gnu::always_inline]] inline FluidState fluid_state_at(const Field* prim, std::ptrdiff_t o, const PointMetric& pm) {
  FluidState fs;
  fs.rho = prim[Prim::idx::rho].origin[o];
  fs.press = prim[Prim::idx::press].origin[o];
  fs.eps = prim[Prim::idx::eps].origin[o];
  fs.h = 1.0 + fs.eps + fs.press / fs.rho;
  fs.W = prim[Prim::idx::W].origin[o];
  for (int c = 0; c < 3; ++c) {
    fs.v[c] = prim[Prim::idx::vel + c].origin[o];
    fs.v_dn[c] = pm.g_dn[c] * fs.v[c];
  }
  fs.v2 = fs.v[0] * fs.v_dn[0] + fs.v[1] * fs.v_dn[1] + fs.v[2] * fs.v_dn[2];
  return fs;
}

template <bool Mhd, bool Shift>
[[gnu::always_inline]] inline void sources_row_body(const Field* prim, const Field* met, const Field* bf,
                                                   double* const* rhs, const RowDivergence& dv, std::ptrdiff_t o0,
                                                   const std::array<std::ptrdiff_t, 3>& st,
                                                   const std::array<double, 3>& inv2dx, int n) {
  const std::array<std::array<double, 3>, 3> df{};
  // ivdep: the rhs fields are written, the others only read (too many pairs for run-time alias checks).
#pragma GCC ivdep
  for (int i = 0; i < n; ++i) {
    const std::ptrdiff_t o = o0 + i;
    double out[kNumCons];
#pragma GCC unroll 6
    for (int c = 0; c < kNumCons; ++c) {
      double r = 0.0;
      r -= (dv.area_x[i + 1] * dv.x[c][i + 1] - dv.area_x[i] * dv.x[c][i]) * (1.0 / dv.volume_x[i]);
      r -= (dv.area_plus[0] * dv.plus[0][c][i] - dv.area_minus[0] * dv.minus[0][c][i]) * dv.inv_volume[0];
      r -= (dv.area_plus[1] * dv.plus[1][c][i] - dv.area_minus[1] * dv.minus[1][c][i]) * dv.inv_volume[1];
      out[c] = r;
    }
    const CellMetric cm = metric_at(met, o);
    const double psi = cm.psi;
    const PointMetric pm = point_metric_cartesian(psi, cm.alpha, cm.beta);
    const MetricDerivatives dm = metric_derivatives_at(met, o, st, inv2dx, {true, true, true}, Shift);
    const FluidState fs = fluid_state_at(prim, o, pm);
    double src[kNumCons];
    if constexpr (Mhd) {
      const MagneticState ms = magnetic_state(fs, pm, bf[0].origin[o], bf[1].origin[o], bf[2].origin[o]);
      gravity_sources_mhd(fs, ms, pm, psi, dm, df, nullptr, Shift, src, true);
    } else {
      gravity_sources(fs, pm, psi, dm, df, nullptr, Shift, src);
    }
    const double p2 = psi * psi, psi6 = p2 * p2 * p2;
    rhs[kD][i] = out[kD];
    rhs[kDYe][i] = out[kDYe];
    for (int c = kS1; c <= kTau; ++c) rhs[c][i] = out[c] + psi6 * src[c];
  }
}
template <bool Mhd, bool Shift>
[[gnu::flatten]] void cartesian_sources_row(const Field* prim, const Field* met, const Field* bf, double* const* rhs,
                                            const RowDivergence& dv, std::ptrdiff_t o0,
                                            const std::array<std::ptrdiff_t, 3>& st,
                                            const std::array<double, 3>& inv2dx, int n) {
  sources_row_body<Mhd, Shift>(prim, met, bf, rhs, dv, o0, st, inv2dx, n);
}
#if REMNANT_HAVE_AVX2_KERNELS
template <bool Mhd, bool Shift>
REMNANT_AVX2_KERNEL void cartesian_sources_row_avx2(const Field* prim, const Field* met, const Field* bf,
                                                    double* const* rhs, const RowDivergence& dv, std::ptrdiff_t o0,
                                                    const std::array<std::ptrdiff_t, 3>& st,
                                                    const std::array<double, 3>& inv2dx, int n) {
  sources_row_body<Mhd, Shift>(prim, met, bf, rhs, dv, o0, st, inv2dx, n);
}
#endif
// The row function of the instruction set avx2_kernels() chooses.
template <bool Mhd, bool Shift>
auto* sources_row_function() {
#if REMNANT_HAVE_AVX2_KERNELS
  if (avx2_kernels()) return &cartesian_sources_row_avx2<Mhd, Shift>;
#endif
  return &cartesian_sources_row<Mhd, Shift>;
}

// Pass 2 over the cells of a block, i fastest. Mhd: the magnetised sources with the cell-centred
// field of group `bvec` (B^i, not densitised); the hydro instantiation never touches it.
// The static pressure part of the momentum source along d of cell o (psi^6 left out, as the sources),
// replaced by the flux divergence of the cell's own isentropic equilibrium pressure at its two faces
// (well_balanced.hpp): the correction to add to src[kS1 + d]. Zero where that equilibrium's h - 1 at
// a face leaves a factor 2 of the cell's (the atmosphere and the surface keep the plain sources), or
// where a neighbour's K differs by more than 2x (hot, diluted cells outside a star).
inline double well_balanced_correction(const WellBalancedSources& wb, const Field* prim, const Field* met,
                                       std::ptrdiff_t o, std::ptrdiff_t s, const FluidState& fs, double psi,
                                       double alpha, double dalpha, double dpsi, double area_minus,
                                       double area_plus, double volume, bool curvilinear) {
  const IdealIsentrope& is = wb.isentrope;
  const double* rho = prim[Prim::idx::rho].origin + o;
  const double* press = prim[Prim::idx::press].origin + o;
  const double* lapse = met[Metric::idx::alpha].origin + o;
  for (int m = -1; m <= 1; ++m)
    if (!equilibrium_cell(is, wb.faces, rho[m * s], press[m * s], lapse, s, m) ||
        !same_isentrope(is, rho[0], press[0], rho[m * s], press[m * s]))
      return 0.0;
  const double q = fs.h * alpha, K = is.entropy(fs.rho, fs.press);
  const FaceLapsePsi6 fm =
      cell_face_metric(wb.faces, met[Metric::idx::alpha].origin + o, met[Metric::idx::psi].origin + o, s);
  double rho_m, p_m, rho_p, p_p;
  if (!is.state_near(q / fm.alpha_minus, fs.h, K, rho_m, p_m) || !is.state_near(q / fm.alpha_plus, fs.h, K, rho_p, p_p))
    return 0.0;
  const double p2 = psi * psi, psi6 = p2 * p2 * p2;
  const double balanced = (area_plus * (fm.psi6_plus * fm.alpha_plus * p_p) - area_minus * (fm.psi6_minus * fm.alpha_minus * p_m)) /
                          volume / psi6;
  double plain = -(fs.rho * fs.h - fs.press) * dalpha + 6.0 * alpha * fs.press * dpsi / psi;
  if (curvilinear) plain += alpha * fs.press * (area_plus - area_minus) / volume;
  return balanced - plain;
}

template <bool Mhd>
void divergence_and_sources(const Groups& g, Block& b, int bvec, bool cartesian_rows = true,
                            const WellBalancedSources& wb = {}) {
  Field prim[Prim::ncomp], met[Metric::ncomp], rhs[kNumCons], flux[3][kNumCons], bf[3];
  if constexpr (Mhd)
    for (int c = 0; c < 3; ++c) bf[c] = b.field(bvec, c);
  for (int c = 0; c < Prim::ncomp; ++c) prim[c] = b.field(g.prim, c);
  for (int c = 0; c < Metric::ncomp; ++c) met[c] = b.field(g.metric, c);
  for (int c = 0; c < kNumCons; ++c) rhs[c] = b.field(g.cons_rhs, c);
  const CoordinateSystem cs = b.coordinates;
  const bool cartesian = cs == CoordinateSystem::cartesian;
  std::array<bool, 3> used{};
  std::array<double, 3> inv2dx{0, 0, 0};
  const std::array<std::ptrdiff_t, 3> st{1, met[0].sj, met[0].sk};
  std::array<std::ptrdiff_t, 3> fst{};
  for (int d = 0; d < 3; ++d) {
    used[d] = direction_used(b, d);
    if (!used[d]) continue;
    inv2dx[d] = 0.5 / b.dx[d];
    for (int c = 0; c < kNumCons; ++c) flux[d][c] = b.field(g.flux[d], c);
    fst[d] = d == 0 ? 1 : d == 1 ? flux[d][0].sj : flux[d][0].sk;
  }
  // The shift terms cost a Christoffel evaluation: only where beta is not zero in this block.
  bool shift = false;
  {
    // In chunks, OR-ing the bits without the sign (p != 0.0, -0.0 included), which vectorises; the
    // whole array is read when beta = 0.
    const std::size_t np = b.points_per_component(g.metric);
    const double* p = b.data(g.metric) + static_cast<std::size_t>(Metric::idx::beta) * np;
    constexpr std::size_t chunk = 256;
    for (std::size_t i0 = 0; i0 < 3 * np && !shift; i0 += chunk) {
      const std::size_t end = std::min(i0 + chunk, 3 * np);
      std::uint64_t bits = 0;
      for (std::size_t i = i0; i < end; ++i) bits |= std::bit_cast<std::uint64_t>(p[i]) << 1;
      shift = bits != 0;
    }
  }
  const bool cartesian_3d = cartesian_rows && !wb.on && cartesian && used[0] && used[1] && used[2];
  const double* ff[3] = {b.face_factors(0), b.face_factors(1), b.face_factors(2)};
  const double* vw[3] = {b.volume_weights(0), b.volume_weights(1), b.volume_weights(2)};
  std::array<std::array<double, 3>, 3> df{};
  Point3 fd{1.0, 1.0, 1.0};
  Christoffels gam{};
  const PolarTrig trig(b);
  const CentroidOffsets centroid(b, used);
  thread_local std::vector<double> row_storage;
  row_storage.resize(static_cast<std::size_t>(kNumCons) * static_cast<std::size_t>(b.n[0]));
  const auto row_function = shift ? sources_row_function<Mhd, true>() : sources_row_function<Mhd, false>();
  double* row[kNumCons];
  for (int c = 0; c < kNumCons; ++c) row[c] = row_storage.data() + static_cast<std::size_t>(c) * b.n[0];
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j) {
      // cons_rhs holds fewer ghosts than the metric and primitives (thorn.yaml): its own rows.
      double* rhs_row[kNumCons];
      for (int c = 0; c < kNumCons; ++c) rhs_row[c] = &rhs[c](0, j, k);
      if (cartesian_3d) {
        RowDivergence dv;
        for (int d = 0; d < 3; ++d) {
          const std::ptrdiff_t fo = j * flux[d][0].sj + k * flux[d][0].sk;
          const int id = d == 1 ? j : k;
          for (int c = 0; c < kNumCons; ++c) {
            const double* F = flux[d][c].origin + fo;
            if (d == 0) {
              dv.x[c] = F;
            } else {
              dv.minus[d - 1][c] = F;
              dv.plus[d - 1][c] = F + fst[d];
            }
          }
          if (d > 0) {
            dv.area_plus[d - 1] = ff[d][id + 1];
            dv.area_minus[d - 1] = ff[d][id];
            dv.inv_volume[d - 1] = 1.0 / vw[d][id];
          }
        }
        dv.area_x = ff[0];
        dv.volume_x = vw[0];
        const std::ptrdiff_t o0 = j * met[0].sj + k * met[0].sk;
        row_function(prim, met, bf, rhs_row, dv, o0, st, inv2dx, b.n[0]);
        continue;
      }
      // Flux divergence: (A+ F+ - A- F-) / V with A/V reduced to the 1D factors of direction d.
      for (int c = 0; c < kNumCons; ++c) std::fill(row[c], row[c] + b.n[0], 0.0);
      for (int d = 0; d < 3; ++d) {
        if (!used[d]) continue;
        const std::ptrdiff_t fo = j * flux[d][0].sj + k * flux[d][0].sk;
        const int id = d == 1 ? j : k;
        for (int c = 0; c < kNumCons; ++c) {
          const double* F = flux[d][c].origin + fo;
          if (d == 0) subtract_divergence_x(row[c], F, ff[0], vw[0], b.n[0]);
          else subtract_divergence_transverse(row[c], F + fst[d], F, ff[d][id + 1], ff[d][id], 1.0 / vw[d][id], b.n[0]);
        }
      }
      for (int i = 0; i < b.n[0]; ++i) {
        const int id[3] = {i, j, k};
        const std::ptrdiff_t o = i + j * met[0].sj + k * met[0].sk;
        double out[kNumCons];
        for (int c = 0; c < kNumCons; ++c) out[c] = row[c][i];
        const CellMetric cm = metric_at(met, o);
        const double psi = cm.psi, alpha = cm.alpha;
        if (!cartesian) {
          const Point3 x = cell_point(b, i, j, k);
          fd = coords::metric_diagonal(cs, x, trig.sin_centre(j));
          gam = coords::christoffels(cs, x, trig.sin_centre(j), trig.cos_centre(j));
          df = metric_diagonal_derivatives(fd, gam);
        }
        // Cartesian: f = 1, the same bits with one division instead of three.
        const PointMetric pm =
            cartesian ? point_metric_cartesian(psi, alpha, cm.beta) : point_metric(psi, alpha, cm.beta, fd);
        MetricDerivatives dm = metric_derivatives_at(met, o, st, inv2dx, used, shift);
        // At the centroid, where the pressure balance of the flux divergence sits (centroid_derivative.hpp).
        if (!cartesian) move_derivatives_to_centroid(dm, met, o, st, centroid, id, used, shift);
        const FluidState fs = fluid_state_at(prim, o, pm);
        double src[kNumCons];
        double ptot = fs.press;
        [[maybe_unused]] MagneticState ms;
        if constexpr (Mhd) {
          ms = magnetic_state(fs, pm, bf[0].origin[o], bf[1].origin[o], bf[2].origin[o]);
          gravity_sources_mhd(fs, ms, pm, psi, dm, df, cartesian ? nullptr : &gam, shift, src, cartesian);
          ptot = total_pressure(fs, ms);
        } else {
          gravity_sources(fs, pm, psi, dm, df, cartesian ? nullptr : &gam, shift, src);
        }
        // Pressure part of the geometric source with the exact cell average of d_d ln sqrt(f),
        // (A+ - A-) / V, which balances a uniform pressure in the divergence to round-off.
        if (!cartesian) {
          const double ap = alpha * ptot;
          for (int d = 0; d < 3; ++d)
            if (used[d]) {
              // (ap * dA) / V, the hydro association: its bits must not change.
              src[kS1 + d] += ap * (ff[d][id[d] + 1] - ff[d][id[d]]) / vw[d][id[d]];
              if constexpr (Mhd) {
                const double log_area = (ff[d][id[d] + 1] - ff[d][id[d]]) / vw[d][id[d]];
                src[kS1 + d] += magnetic_geometric_source(d, fs, ms, pm, fd, df, log_area);
              }
            }
        }
        if (wb.on)
          for (int d = 0; d < 3; ++d)
            if (used[d])
              src[kS1 + d] += well_balanced_correction(wb, prim, met, o, st[d], fs, psi, alpha, dm.dalpha[d], dm.dpsi[d],
                                                       ff[d][id[d]], ff[d][id[d] + 1], vw[d][id[d]], !cartesian);
        const double p2 = psi * psi, psi6 = p2 * p2 * p2;
        rhs_row[kD][i] = out[kD];
        rhs_row[kDYe][i] = out[kDYe];
        for (int c = kS1; c <= kTau; ++c) rhs_row[c][i] = out[c] + psi6 * src[c];
      }
    }
}

template <class E>
[[gnu::always_inline]] inline void block_fluxes_body(const E& eos, const RhsSettings& s, const Groups& g, Block& b,
                                                     HydroLineScratch& scratch) {
  if (direction_used(b, 0)) sweep_direction<0>(eos, s, g, b, scratch);
  if (direction_used(b, 1)) sweep_direction<1>(eos, s, g, b, scratch);
  if (direction_used(b, 2)) sweep_direction<2>(eos, s, g, b, scratch);
}
template <class E>
[[gnu::flatten]] void block_fluxes_portable(const E& eos, const RhsSettings& s, const Groups& g, Block& b, HydroLineScratch& scratch) {
  block_fluxes_body(eos, s, g, b, scratch);
}
#if REMNANT_HAVE_AVX2_KERNELS
template <class E>
REMNANT_AVX2_KERNEL void block_fluxes_avx2(const E& eos, const RhsSettings& s, const Groups& g, Block& b,
                                           HydroLineScratch& scratch) {
  block_fluxes_body(eos, s, g, b, scratch);
}
#endif
template <class E>
void block_fluxes(const E& eos, const RhsSettings& s, const Groups& g, Block& b) {
  thread_local HydroLineScratch scratch;
#if REMNANT_HAVE_AVX2_KERNELS
  if (avx2_kernels()) return block_fluxes_avx2(eos, s, g, b, scratch);
#endif
  block_fluxes_portable(eos, s, g, b, scratch);
}

}  // namespace

void compute_block_fluxes(const eos::EOS& eos, const RhsSettings& s, const Groups& g, Block& b) {
  eos.visit([&](const auto& e) { block_fluxes(e, s, g, b); });
}

void compute_block_rhs(const Groups& g, Block& b, const WellBalancedSources& wb) {
  divergence_and_sources<false>(g, b, -1, true, wb);
}

void compute_block_rhs_mhd(const Groups& g, int bvec, Block& b, const WellBalancedSources& wb) {
  divergence_and_sources<true>(g, b, bvec, true, wb);
}

void compute_block_rhs_per_cell(const Groups& g, Block& b) { divergence_and_sources<false>(g, b, -1, false); }

void compute_block_rhs_mhd_per_cell(const Groups& g, int bvec, Block& b) {
  divergence_and_sources<true>(g, b, bvec, false);
}

}  // namespace remnant::grmhd
