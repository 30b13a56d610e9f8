#pragma once
// Contiguous line buffers of one direction sweep (cells with ghosts, face states, metric, fluxes),
// shared by the hydro and the MHD sweeps: the gather of a line (gather_line) and the metric at its
// faces (set_face_metric), both stored as one array per quantity so that the face loops vectorise.
#include <span>
#include <type_traits>
#include <vector>

#include "GRMHD/face_thermo.hpp"
#include "GRMHD/valencia.hpp"
#include "groups.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {

enum class MetricFaceInterpolation { linear, cubic };

// The reconstructed variables every sweep shares, in this order; the MHD sweep appends its two
// transverse field components. kRecPress: the pressure beside the temperature of a non-ideal-gas EOS
// (face_thermo.hpp).
enum LineVariable : int { kRecRho = 0, kRecWv1 = 1, kRecThermal = 4, kRecYe = 5, kRecPress = 6 };
inline constexpr int kNumRecHydro = 7;
// The slots a sweep with EOS E gathers and reconstructs: the hydro slots 0 .. kHydroSlots<E> - 1, then
// the extra ones. The ideal gas's thermal variable is the pressure, so its list stops before
// kRecPress, the last hydro slot.
static_assert(kRecPress == kNumRecHydro - 1, "the slot the ideal gas leaves out is the last hydro slot");
template <class E>
inline constexpr int kHydroSlots = reconstructs_pressure<E> ? kRecPress : kNumRecHydro;
template <class E>
inline constexpr bool reconstructed_slot(int q) {
  return q < kHydroSlots<E> || q >= kNumRecHydro;
}

// The metric at the faces of a line (f = 0..n): what the face states and fluxes need of it.
struct FaceMetricLine {
  double* psi6;      // psi^6, the densitisation of the fluxes
  double* alpha;
  double* beta[3];
  double* g_dn[3];   // gamma_ii = psi^4 f_ii
  double* g_up_d;    // gamma^dd of the sweep direction d
};
inline constexpr int kFaceMetricArrays = 9;
// The stride of a line along x, known at compile time.
using UnitStride = std::integral_constant<std::ptrdiff_t, 1>;
// Per-face work arrays of a face kernel (the thermodynamics of both sides, ...).
inline constexpr int kNumWork = 12;

template <int NumRec, int NumFlux>
struct LineScratch {
  int cap = 0;
  std::vector<double> storage;
  double* cell[NumRec];        // cell values, offset so that [0] is the first interior cell
  double* left[NumRec];        // faces 0..n
  double* right[NumRec];
  double* flux[NumFlux];       // face fluxes (weighted)
  double* ppm;                 // reconstruction scratch (ppm_scratch())
  FaceMetricLine face;         // face metric
  double* work[kNumWork];      // faces 0..n
  int ng = 0;
  // The whole reconstruction scratch (at least ppm_scratch_size(n) after ensure(n, ...)).
  std::span<double> ppm_scratch() const { return {ppm, static_cast<std::size_t>(cap - 1)}; }
  void ensure(int n, int ngh) {
    const int len = n + 2 * ngh + 4;
    if (len <= cap && ngh == ng) return;
    cap = len;
    ng = ngh;
    const int arrays = NumRec * 3 + NumFlux + 1 + kFaceMetricArrays + kNumWork;
    storage.assign(static_cast<std::size_t>(arrays) * static_cast<std::size_t>(len), 0.0);
    double* p = storage.data();
    auto take = [&](int offset) {
      double* q = p + offset;
      p += len;
      return q;
    };
    for (double*& a : cell) a = take(ngh + 1);
    for (double*& a : left) a = take(1);
    for (double*& a : right) a = take(1);
    for (double*& a : flux) a = take(1);
    ppm = take(1);
    face.psi6 = take(1);
    face.alpha = take(1);
    for (double*& a : face.beta) a = take(1);
    for (double*& a : face.g_dn) a = take(1);
    face.g_up_d = take(1);
    for (double*& a : work) a = take(1);
  }
};

// Where a face kernel writes its outputs: component c of face f at p[c][f * stride] (the flux
// groups themselves, strided across x; UnitStride along x or into LineScratch::flux).
template <int NumFlux, class Stride>
struct FaceOutput {
  double* p[NumFlux];
  Stride stride;
  double& operator()(int c, int f) const { return p[c][f * static_cast<std::ptrdiff_t>(stride)]; }
};
template <int NumFlux, class Stride>
inline FaceOutput<NumFlux, Stride> face_output(double* const* out, std::ptrdiff_t base, Stride stride) {
  FaceOutput<NumFlux, Stride> o{{}, stride};
  for (int c = 0; c < NumFlux; ++c) o.p[c] = out[c] + base;
  return o;
}
template <int NumRec, int NumFlux>
inline FaceOutput<NumFlux, UnitStride> face_output(const LineScratch<NumRec, NumFlux>& L) {
  return face_output<NumFlux>(L.flux, 0, UnitStride{});
}

inline double face_value(MetricFaceInterpolation m, const double* a, int f) {
  if (m == MetricFaceInterpolation::cubic)
    return (9.0 * (a[f - 1] + a[f]) - (a[f - 2] + a[f + 1])) * (1.0 / 16.0);
  return 0.5 * (a[f - 1] + a[f]);
}

// The primitive and metric fields a line gather reads, resolved once per sweep.
struct LineSources {
  const double* rho;
  const double* W;
  const double* vel[3];
  const double* thermal;  // p (ideal gas) or T (face_thermo.hpp)
  const double* ye;
  const double* press;
  const double* met[Metric::ncomp];
  template <class E>
  static LineSources of(const Field* prim, const Field* metric) {
    LineSources s;
    s.rho = prim[Prim::idx::rho].origin;
    s.W = prim[Prim::idx::W].origin;
    s.vel[0] = prim[Prim::idx::vel].origin;
    s.vel[1] = prim[Prim::idx::vel2].origin;
    s.vel[2] = prim[Prim::idx::vel3].origin;
    s.thermal = (reconstructs_pressure<E> ? prim[Prim::idx::press] : prim[Prim::idx::temperature]).origin;
    s.ye = prim[Prim::idx::Ye].origin;
    s.press = prim[Prim::idx::press].origin;
    for (int c = 0; c < Metric::ncomp; ++c) s.met[c] = metric[c].origin;
    return s;
  }
};

// Copies the line at offset `base` (stride `stride`, n cells and ng ghosts each side) into L:
// rho, W v^1..3, thermal, Ye and, where E reconstructs it, p into cell[0..6] (set_face_metric reads
// the metric in place); the NumRec - 7 fields of `extra` (the MHD sweep's transverse B; nullptr for
// the hydro sweep) into cell[7..], read at the same points.
template <class E, int NumRec, int NumFlux>
inline void gather_line(const LineSources& src, const double* const* extra, std::ptrdiff_t base, std::ptrdiff_t stride,
                        int n, int ng, LineScratch<NumRec, NumFlux>& L) {
  constexpr int NumExtra = NumRec - kNumRecHydro;
  static_assert(NumExtra >= 0, "the extra variables follow the hydro ones");
  const double* pr = src.rho + base;
  const double* pw = src.W + base;
  const double* pv0 = src.vel[0] + base;
  const double* pv1 = src.vel[1] + base;
  const double* pv2 = src.vel[2] + base;
  const double* pth = src.thermal + base;
  const double* pye = src.ye + base;
  [[maybe_unused]] const double* ppr = src.press + base;  // read only where E reconstructs p
  for (int m = -ng; m < n + ng; ++m) {
    const std::ptrdiff_t o = m * stride;
    const double W = pw[o];
    L.cell[0][m] = pr[o];
    L.cell[1][m] = W * pv0[o];
    L.cell[2][m] = W * pv1[o];
    L.cell[3][m] = W * pv2[o];
    L.cell[4][m] = pth[o];
    L.cell[5][m] = pye[o];
    if constexpr (reconstructed_slot<E>(kRecPress)) L.cell[kRecPress][m] = ppr[o];
  }
  for (int e = 0; e < NumExtra; ++e) {
    const double* px = extra[e] + base;
    double* out = L.cell[kNumRecHydro + e];
    for (int m = -ng; m < n + ng; ++m) out[m] = px[m * stride];
  }
}

// The face metric of the line in direction d whose cells have the transverse indices of `idx`:
// psi, alpha, beta interpolated to the faces (linear or cubic) straight from the metric fields
// (offset `base`, stride `stride`; a std::integral_constant along x), psi^6, gamma_ii = psi^4 f_ii
// and gamma^dd, with the bits of point_metric / point_metric_cartesian (valencia.hpp).
template <int NumRec, int NumFlux, class Stride>
inline void set_face_metric(const Block& b, const PolarTrig& trig, MetricFaceInterpolation interp, int d,
                            const int* idx, int n, const LineSources& src, std::ptrdiff_t base, Stride stride,
                            LineScratch<NumRec, NumFlux>& L) {
  const FaceMetricLine& fm = L.face;
  const double* mpsi = src.met[Metric::idx::psi] + base;
  const double* malpha = src.met[Metric::idx::alpha] + base;
  const double* mbeta[3] = {src.met[Metric::idx::beta] + base, src.met[Metric::idx::beta2] + base,
                            src.met[Metric::idx::beta3] + base};
  const bool cartesian = b.coordinates == CoordinateSystem::cartesian;
  // Cartesian: gamma^dd = 1 / psi^4 in the same loop.
  const auto fill = [&](auto face, auto is_cartesian) {
    for (int f = 0; f <= n; ++f) {
      const double psi = face(mpsi, f);
      const double p2 = psi * psi;
      const double psi4 = p2 * p2;
      fm.psi6[f] = p2 * p2 * p2;
      fm.alpha[f] = face(malpha, f);
      for (int c = 0; c < 3; ++c) fm.beta[c][f] = face(mbeta[c], f);
      for (int c = 0; c < 3; ++c) fm.g_dn[c][f] = psi4;
      if constexpr (is_cartesian) fm.g_up_d[f] = 1.0 / psi4;
    }
  };
  const auto cubic = [stride](const double* a, int f) {
    const std::ptrdiff_t s = stride;
    return (9.0 * (a[(f - 1) * s] + a[f * s]) - (a[(f - 2) * s] + a[(f + 1) * s])) * (1.0 / 16.0);
  };
  const auto linear = [stride](const double* a, int f) {
    const std::ptrdiff_t s = stride;
    return 0.5 * (a[(f - 1) * s] + a[f * s]);
  };
  if (interp == MetricFaceInterpolation::cubic) {
    if (cartesian) fill(cubic, std::true_type{});
    else fill(cubic, std::false_type{});
  } else {
    if (cartesian) fill(linear, std::true_type{});
    else fill(linear, std::false_type{});
  }
  if (cartesian) return;
  Point3 x = cell_point(b, idx[0], idx[1], idx[2]);
  for (int f = 0; f <= n; ++f) {
    x[d] = b.face_coordinate(d, f);
    const Point3 fd = coords::metric_diagonal(b.coordinates, x, d == 1 ? trig.sin_face(f) : trig.sin_centre(idx[1]));
    for (int c = 0; c < 3; ++c) fm.g_dn[c][f] *= fd[c];
    fm.g_up_d[f] = 1.0 / fm.g_dn[d][f];
  }
}

}  // namespace remnant::grmhd
