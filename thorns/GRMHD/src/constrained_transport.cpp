#include "constrained_transport.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "GRMHD/reconstruction.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "emf_contact.hpp"
#include "groups.hpp"
#include "kernel_isa.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {
namespace {

// Index arithmetic of one field: the offset of (i, j, k) and the stride of direction d.
struct Strided {
  Field f;
  std::ptrdiff_t at(const int* id) const { return id[0] + id[1] * f.sj + id[2] * f.sk; }
  std::ptrdiff_t stride(int d) const { return d == 0 ? 1 : d == 1 ? f.sj : f.sk; }
  double operator[](std::ptrdiff_t o) const { return f.origin[o]; }
};

// The HLL average of the product vt B across an edge from its two sides (low, high), with the
// dissipation on B: (a+ vt_l B_l + a- vt_h B_h - a+ a- (B_h - B_l)) / (a+ + a-).
inline double hll_product(double ap, double am, double vl, double vh, double bl, double bh) {
  const double w = ap + am;
  if (!(w > 0)) return 0.5 * (vl * bl + vh * bh);
  return (ap * vl * bl + am * vh * bh - ap * am * (bh - bl)) / w;
}

// The two states at an edge between cells -1 and 0 from the face values q[-3..2] (q points at
// cell 0): MC- or minmod-limited (q[-2..1] read) or PPM, classic or extremum-preserving
// (reconstruction.hpp on the six values; GRMHD::emf_reconstruction).
inline void edge_states(Reconstruction r, const double* q, double& low, double& high) {
  if (ghosts_needed(r) == 3) {
    double left[1], right[1], face[ppm_scratch_size(0)];
    reconstruct(r, q, left, right, 0, face);
    low = left[0];
    high = right[0];
    return;
  }
  const double qm2 = q[-2], qm1 = q[-1], q0 = q[0], qp1 = q[1];
  const bool mc = r == Reconstruction::mc;
  low = qm1 + 0.5 * (mc ? detail::mc_slope(qm1 - qm2, q0 - qm1) : detail::minmod(qm1 - qm2, q0 - qm1));
  high = q0 - 0.5 * (mc ? detail::mc_slope(q0 - qm1, qp1 - q0) : detail::minmod(q0 - qm1, qp1 - q0));
}

// One direction's part -/+ HLL_a(vt^a B^b) of an edge: the two a-faces adjacent along b (ct_a at
// offsets oa - sb and oa), and B^b of the b-face through the edge reconstructed along a from the
// face values q[-3..2] of the cells a-3 .. a+2 (q points at cell a).
inline double upwind_part(const Strided* ct, std::ptrdiff_t oa, std::ptrdiff_t sb, Reconstruction r, const double* q) {
  const std::ptrdiff_t lo = oa - sb;
  const double ap = std::max(ct[kAlphaPlus][lo], ct[kAlphaPlus][oa]);
  const double am = std::max(ct[kAlphaMinus][lo], ct[kAlphaMinus][oa]);
  const double vl = 0.5 * (ct[kVtLeft][lo] + ct[kVtLeft][oa]);
  const double vh = 0.5 * (ct[kVtRight][lo] + ct[kVtRight][oa]);
  double bl, bh;
  edge_states(r, q, bl, bh);
  return hll_product(ap, am, vl, vh, bl, bh);
}

// The face values q[-w..w-1] of the faces normal to b through cells a-w .. a+w-1 of the edge at id
// (b-face index id[b]; w = 2 for MC and minmod, 3 for PPM; q points at cell a). Curvilinear: as orthonormal face means (orthonormal_factor of each face's cell
// extent), smooth through the axis and the origin, then divided by the signed scale factor h_b at
// the edge, so that the upwind dissipation sees no spurious jumps of the coordinate components
// (B^theta ~ 1/r near the origin); zero on the axis and at the origin (h_b = 0, zero-length edges).
inline void face_values_along(const Block& blk, const Strided& bf, int a, int b, const int* id, bool curvilinear,
                              int w, double* q) {
  const std::ptrdiff_t o = bf.at(id), sa = bf.stride(a);
  for (int m = -w; m < w; ++m) q[m] = bf[o + m * sa];
  if (!curvilinear) return;
  int cell[3] = {id[0], id[1], id[2]};
  Point3 x{};
  for (int d = 0; d < 3; ++d) x[d] = d == a || d == b ? blk.face_coordinate(d, id[d]) : blk.x(d, id[d]);
  const double h = blk.coordinates == CoordinateSystem::cylindrical ? (b == 2 ? x[0] : 1.0)
                   : b == 0                                         ? 1.0
                   : b == 1                                         ? x[0]
                                                                    : x[0] * std::sin(x[1]);
  const double ih = h != 0 ? 1.0 / h : 0.0;
  for (int m = -w; m < w; ++m) {
    cell[a] = id[a] + m;
    q[m] *= hydrobase::orthonormal_factor(blk, b, cell) * ih;
  }
}

// The Cartesian uct_hll EMFs of a row of edges along x (id: the row's first edge), the operations
// of upwind_part and hll_product in the same order with their branches as selects, so that the
// row vectorises: mc_slope's zero for dm dp <= 0, std::max / std::min({...}) as the first extreme
// value, hll_product's mean for a zero width.
[[gnu::always_inline]] inline double mc_slope_select(double dm, double dp) {
  const double s = dm > 0 ? 1.0 : -1.0;
  double m = 2.0 * std::abs(dm);
  const double b = 2.0 * std::abs(dp), c = 0.5 * std::abs(dm + dp);
  m = b < m ? b : m;
  m = c < m ? c : m;
  return dm * dp <= 0 ? 0.0 : s * m;
}
// upwind_part's faces: the four ct components of the faces of one direction along a row.
struct CtRow {
  const double* __restrict alpha_plus;
  const double* __restrict alpha_minus;
  const double* __restrict vt_left;
  const double* __restrict vt_right;
  CtRow(const Strided* ct, std::ptrdiff_t o)
      : alpha_plus(ct[kAlphaPlus].f.origin + o), alpha_minus(ct[kAlphaMinus].f.origin + o),
        vt_left(ct[kVtLeft].f.origin + o), vt_right(ct[kVtRight].f.origin + o) {}
};
// slope: mc_slope_select of q along sq at every point (mc_slopes), computed once per face value
// instead of once for each of the two edges that read it (the same operations, so the same bits).
[[gnu::always_inline]] inline double upwind_part_select(const CtRow& ct, std::ptrdiff_t oa, std::ptrdiff_t sb,
                                                        const double* __restrict q,
                                                        const double* __restrict slope, std::ptrdiff_t sq) {
  const std::ptrdiff_t lo = oa - sb;
  const double apl = ct.alpha_plus[lo], aph = ct.alpha_plus[oa], aml = ct.alpha_minus[lo], amh = ct.alpha_minus[oa];
  const double ap = apl < aph ? aph : apl;  // std::max(apl, aph)
  const double am = aml < amh ? amh : aml;
  const double vl = 0.5 * (ct.vt_left[lo] + ct.vt_left[oa]);
  const double vh = 0.5 * (ct.vt_right[lo] + ct.vt_right[oa]);
  const double qm1 = q[oa - sq], q0 = q[oa];
  const double bl = qm1 + 0.5 * slope[oa - sq];
  const double bh = q0 - 0.5 * slope[oa];
  const double w = ap + am;
  const double hll = (ap * vl * bl + am * vh * bh - ap * am * (bh - bl)) / w;
  const double mean = 0.5 * (vl * bl + vh * bh);
  return !(w > 0) ? mean : hll;
}

// The MC slopes of the face values q along stride sq, mc_slope_select(q - q[-sq], q[+sq] - q), into
// `out` (indexed as q) at the points lo .. hi - 1 of the field's index space (sj, sk: its strides).
[[gnu::always_inline]] inline void mc_slopes_body(const double* q, std::ptrdiff_t sj, std::ptrdiff_t sk,
                                                 std::ptrdiff_t sq, const int* lo, const int* hi, double* out) {
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j) {
      const std::ptrdiff_t o = lo[0] + j * sj + k * sk;
      const double* __restrict p = q + o;
      double* __restrict s = out + o;
      for (int i = 0; i < hi[0] - lo[0]; ++i) s[i] = mc_slope_select(p[i] - p[i - sq], p[i + sq] - p[i]);
    }
}

void mc_slopes(const double* q, std::ptrdiff_t sj, std::ptrdiff_t sk, std::ptrdiff_t sq, const int* lo, const int* hi,
               double* out) {
  mc_slopes_body(q, sj, sk, sq, lo, hi, out);
}
#if REMNANT_HAVE_AVX2_KERNELS
// The same in AVX2 (kernel_isa.hpp; the same bits).
REMNANT_AVX2_KERNEL void mc_slopes_avx2(const double* q, std::ptrdiff_t sj, std::ptrdiff_t sk, std::ptrdiff_t sq,
                                        const int* lo, const int* hi, double* out) {
  mc_slopes_body(q, sj, sk, sq, lo, hi, out);
}
#endif

// The slopes a row of edges reads: of q = face field `f` along direction d, for the edges
// 0 .. ext - 1 (points -1 .. ext - 1 along d), in `storage` (resized to the field's group).
const double* edge_slopes(Block& b, int group, const Strided& f, int d, const int* ext, std::vector<double>& storage) {
  storage.resize(b.size(group));
  double* out = storage.data() + (f.f.origin - b.data(group));
  int lo[3] = {0, 0, 0}, hi[3] = {ext[0], ext[1], ext[2]};
  lo[d] = -1;
#if REMNANT_HAVE_AVX2_KERNELS
  if (avx2_kernels()) {
    mc_slopes_avx2(f.f.origin, f.f.sj, f.f.sk, f.stride(d), lo, hi, out);
    return out;
  }
#endif
  mc_slopes(f.f.origin, f.f.sj, f.f.sk, f.stride(d), lo, hi, out);
  return out;
}

template <int C>
[[gnu::always_inline]] inline void uct_hll_row_body(const Strided* cta, const Strided* ctb, const Strided& Ba,
                                                   const Strided& Bb, const double* slope_a, const double* slope_b,
                                                   const int* id, int len, const double* ffa, const double* ffb,
                                                   const double* vwc, double len_c, const Strided& e) {
  constexpr int a = (C + 1) % 3, bb = (C + 2) % 3;
  const CtRow ra(cta, cta[0].at(id)), rb(ctb, ctb[0].at(id));
  const std::ptrdiff_t sb = cta[0].stride(bb), sa = ctb[0].stride(a);
  const double* __restrict qb = Bb.f.origin + Bb.at(id);  // B^bb along a
  const double* __restrict qa = Ba.f.origin + Ba.at(id);  // B^a along bb
  const double* __restrict slb = slope_b + Bb.at(id);  // their MC slopes
  const double* __restrict sla = slope_a + Ba.at(id);
  const std::ptrdiff_t sqb = Bb.stride(a), sqa = Ba.stride(bb);
  double* __restrict out = e.f.origin + e.at(id);
  // The factors that vary along x (direction 0) are read at i, the others at the row's index.
  const double* __restrict fa = a == 0 ? ffa : ffa + id[a];
  const double* __restrict fb = bb == 0 ? ffb : ffb + id[bb];
  const double* __restrict fc = C == 0 ? vwc : vwc + id[C];
  // ivdep: out (an EMF group) is only written, the face data (scratch) only read.
#pragma GCC ivdep
  for (int i = 0; i < len; ++i) {
    const double emf = -upwind_part_select(ra, i, sb, qb, slb, sqb) + upwind_part_select(rb, i, sa, qa, sla, sqa);
    out[i] = emf * fa[a == 0 ? i : 0] * fb[bb == 0 ? i : 0] * fc[C == 0 ? i : 0] / len_c;
  }
}
template <int C>
void uct_hll_row_cartesian(const Strided* cta, const Strided* ctb, const Strided& Ba, const Strided& Bb,
                           const double* slope_a, const double* slope_b, const int* id, int len, const double* ffa,
                           const double* ffb, const double* vwc, double len_c, const Strided& e) {
  uct_hll_row_body<C>(cta, ctb, Ba, Bb, slope_a, slope_b, id, len, ffa, ffb, vwc, len_c, e);
}
#if REMNANT_HAVE_AVX2_KERNELS
template <int C>
REMNANT_AVX2_KERNEL void uct_hll_row_cartesian_avx2(const Strided* cta, const Strided* ctb, const Strided& Ba,
                                                    const Strided& Bb, const double* slope_a, const double* slope_b,
                                                    const int* id, int len, const double* ffa, const double* ffb,
                                                    const double* vwc, double len_c, const Strided& e) {
  uct_hll_row_body<C>(cta, ctb, Ba, Bb, slope_a, slope_b, id, len, ffa, ffb, vwc, len_c, e);
}
#endif
// The row function of component C for the instruction set avx2_kernels() chooses.
template <int C>
auto* uct_hll_row_function() {
#if REMNANT_HAVE_AVX2_KERNELS
  if (avx2_kernels()) return &uct_hll_row_cartesian_avx2<C>;
#endif
  return &uct_hll_row_cartesian<C>;
}

}  // namespace

void edge_emfs(EmfScheme scheme, const MhdGroups& g, const CtFaces& ct, Block& b, Reconstruction edge_reconstruction) {
  if (scheme == EmfScheme::uct_contact) throw std::logic_error("edge_emfs: uct_contact needs the hydro groups");
  edge_emfs(scheme, g, Groups{}, ct, b, edge_reconstruction);
}

void edge_emfs(EmfScheme scheme, const MhdGroups& g, const Groups& hydro, const CtFaces& ct, Block& b,
               Reconstruction edge_reconstruction) {
  const int w = ghosts_needed(edge_reconstruction);
  std::optional<ContactEmfFields> contact;
  if (scheme == EmfScheme::uct_contact) contact.emplace(g, hydro, b);
  bool used[3];
  for (int d = 0; d < 3; ++d) used[d] = direction_used(b, d);
  const bool curvilinear = b.coordinates != CoordinateSystem::cartesian;
  for (int c = 0; c < 3; ++c) {
    const int a = (c + 1) % 3, bb = (c + 2) % 3;  // (a, bb, c) cyclic: E_c = vt^bb B^a - vt^a B^bb
    const Strided e{b.field(g.emf[c], 0)};
    Strided cta[kNumCt], ctb[kNumCt];
    if (used[a])
      for (int q = 0; q < kNumCt; ++q) cta[q] = {ct.f[a][q]};
    if (used[bb])
      for (int q = 0; q < kNumCt; ++q) ctb[q] = {ct.f[bb][q]};
    const Strided Ba{b.field(g.bface[a], 0)}, Bb{b.field(g.bface[bb], 0)};
    const double* ffa = b.face_factors(a);
    const double* ffb = b.face_factors(bb);
    const double* vwc = b.volume_weights(c);
    const double len_c = used[c] ? b.dx[c] : 1.0;
    const int ext[3] = {used[0] && c != 0 ? b.n[0] + 1 : b.n[0], used[1] && c != 1 ? b.n[1] + 1 : b.n[1],
                        used[2] && c != 2 ? b.n[2] + 1 : b.n[2]};
    int id[3];
    // The vectorised Cartesian rows hard-code the MC edge slopes: other edge reconstructions
    // (GRMHD::emf_reconstruction) take the general loop.
    if (scheme == EmfScheme::uct_hll && edge_reconstruction == Reconstruction::mc && !curvilinear && used[a] && used[bb]) {
      thread_local std::vector<double> slope_storage[2];
      const double* slope_b = edge_slopes(b, g.bface[bb], Bb, a, ext, slope_storage[0]);  // B^bb along a
      const double* slope_a = edge_slopes(b, g.bface[a], Ba, bb, ext, slope_storage[1]);  // B^a along bb
      const auto row = c == 0 ? uct_hll_row_function<0>() : c == 1 ? uct_hll_row_function<1>() : uct_hll_row_function<2>();
      for (id[2] = 0; id[2] < ext[2]; ++id[2])
        for (id[1] = 0; id[1] < ext[1]; ++id[1]) {
          id[0] = 0;
          row(cta, ctb, Ba, Bb, slope_a, slope_b, id, ext[0], ffa, ffb, vwc, len_c, e);
        }
      continue;
    }
    for (id[2] = 0; id[2] < ext[2]; ++id[2])
      for (id[1] = 0; id[1] < ext[1]; ++id[1])
        for (id[0] = 0; id[0] < ext[0]; ++id[0]) {
          double emf = 0;  // psi^6 (vt^bb B^a - vt^a B^bb) at the edge
          if (used[a] && used[bb]) {
            const std::ptrdiff_t oa = cta[0].at(id), ob = ctb[0].at(id);
            if (scheme == EmfScheme::uct_hll) {
              double qb_store[6], qa_store[6];
              double* qb = qb_store + 3;
              double* qa = qa_store + 3;
              face_values_along(b, Bb, a, bb, id, curvilinear, w, qb);
              face_values_along(b, Ba, bb, a, id, curvilinear, w, qa);
              emf = -upwind_part(cta, oa, cta[0].stride(bb), edge_reconstruction, qb) +
                    upwind_part(ctb, ob, ctb[0].stride(a), edge_reconstruction, qa);
            } else if (scheme == EmfScheme::uct_contact) {
              const std::ptrdiff_t sb = cta[0].stride(bb), sa = ctb[0].stride(a);
              const double ea[2] = {-cta[kFluxNext][oa - sb], -cta[kFluxNext][oa]};
              const double eb[2] = {ctb[kFluxPrev][ob - sa], ctb[kFluxPrev][ob]};
              emf = contact_emf(*contact, a, bb, id, ea, eb);
            } else {
              const std::ptrdiff_t sb = cta[0].stride(bb), sa = ctb[0].stride(a);
              emf = 0.25 * (-cta[kFluxNext][oa - sb] - cta[kFluxNext][oa] + ctb[kFluxPrev][ob - sa] + ctb[kFluxPrev][ob]);
            }
          } else if (used[a]) {
            emf = -cta[kFluxNext][cta[0].at(id)];
          } else if (used[bb]) {
            emf = ctb[kFluxPrev][ctb[0].at(id)];
          }
          e.f.origin[e.at(id)] = emf * ffa[id[a]] * ffb[id[bb]] * vwc[id[c]] / len_c;
        }
  }
}

void face_rhs(const MhdGroups& g, Block& b) {
  bool used[3];
  for (int d = 0; d < 3; ++d) used[d] = direction_used(b, d);
  for (int a = 0; a < 3; ++a) {
    const int bb = (a + 1) % 3, c = (a + 2) % 3;
    const Strided r{b.field(g.bface_rhs[a], 0)};
    const Strided ec{b.field(g.emf[c], 0)}, eb{b.field(g.emf[bb], 0)};
    const double len_c = used[c] ? b.dx[c] : 1.0, len_b = used[bb] ? b.dx[bb] : 1.0;
    const int ext[3] = {used[0] && a == 0 ? b.n[0] + 1 : b.n[0], used[1] && a == 1 ? b.n[1] + 1 : b.n[1],
                        used[2] && a == 2 ? b.n[2] + 1 : b.n[2]};
    // Block::face_area(a, i, j, k) = 1 * g_0 * g_1 * g_2 (the face factor in direction a, the volume
    // weights in the others), multiplied in that order.
    const double* g_of[3];
    for (int d = 0; d < 3; ++d) g_of[d] = d == a ? b.face_factors(d) : b.volume_weights(d);
    const std::ptrdiff_t sec = ec.stride(bb), seb = eb.stride(c);
    int id[3];
    for (id[2] = 0; id[2] < ext[2]; ++id[2])
      for (id[1] = 0; id[1] < ext[1]; ++id[1]) {
        id[0] = 0;
        const double g1 = g_of[1][id[1]], g2 = g_of[2][id[2]];
        const double* pec = ec.f.origin + ec.at(id);
        const double* peb = eb.f.origin + eb.at(id);
        double* out = r.f.origin + r.at(id);
        for (int i = 0; i < ext[0]; ++i) {
          const double area = 1.0 * g_of[0][i] * g1 * g2;
          double circulation = 0;
          // d_t (A B^a) = -[(E_c(b+1) - E_c(b)) dx_c - (E_b(c+1) - E_b(c)) dx_b]; an unused transverse
          // direction has one edge on both sides: no contribution.
          if (used[bb]) circulation += (pec[i + sec] - pec[i]) * len_c;
          if (used[c]) circulation -= (peb[i + seb] - peb[i]) * len_b;
          out[i] = area > 0 ? -circulation / area : 0.0;
        }
      }
  }
}

double relative_divergence(const MhdGroups& g, Block& b) {
  double worst = 0;
  for_interior(b, [&](int i, int j, int k) {
    double sum = 0, scale = 0;
    for (int a = 0; a < 3; ++a) {
      if (!direction_used(b, a)) continue;
      const Field bf = b.field(g.bface[a], 0);
      int up[3] = {i, j, k};
      ++up[a];
      const double fm = b.face_area(a, i, j, k) * bf(i, j, k);
      const double fp = b.face_area(a, up[0], up[1], up[2]) * bf(up[0], up[1], up[2]);
      sum += fp - fm;
      scale += std::abs(fp) + std::abs(fm);
    }
    if (scale > 0) worst = std::max(worst, std::abs(sum) / scale);
  });
  return worst;
}

}  // namespace remnant::grmhd
