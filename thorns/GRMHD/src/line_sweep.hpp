#pragma once
// The set-up the hydro sweep (rhs.cpp) and the MHD sweep (mhd_fluxes.cpp) share around a line of
// cells in direction D: the fields they read and write with their strides, the cells of a line, its
// reconstruction with the face metric, and where its face fluxes go. Templates, resolved at
// compile time, so the sweeps keep their operations (and bits).
#include "GRMHD/reconstruction.hpp"
#include "line_scratch.hpp"
#include "rhs.hpp"

namespace remnant::grmhd {

// The primitive, metric and flux fields of a sweep along D over one block.
template <int D>
struct SweepFields {
  // The two transverse directions.
  static constexpr int first_transverse = D == 0 ? 1 : 0, second_transverse = D == 2 ? 1 : 2;
  Field prim[Prim::ncomp], met[Metric::ncomp], flux[kNumCons];
  std::ptrdiff_t stride, flux_stride;  // along D in the cell and the face arrays

  SweepFields(Block& b, const Groups& g) {
    for (int c = 0; c < Prim::ncomp; ++c) prim[c] = b.field(g.prim, c);
    for (int c = 0; c < Metric::ncomp; ++c) met[c] = b.field(g.metric, c);
    for (int c = 0; c < kNumCons; ++c) flux[c] = b.field(g.flux[D], c);
    stride = D == 0 ? 1 : D == 1 ? prim[0].sj : prim[0].sk;
    flux_stride = D == 0 ? 1 : D == 1 ? flux[0].sj : flux[0].sk;
  }
  // The cell indices of the line's first cell (index 0 along D) at transverse indices (ia, ic).
  static std::array<int, 3> line_start(int ia, int ic) {
    std::array<int, 3> idx;
    idx[D] = 0;
    idx[first_transverse] = ia;
    idx[second_transverse] = ic;
    return idx;
  }
  // The line's offsets in the cell and the face arrays.
  std::ptrdiff_t cell_offset(const std::array<int, 3>& idx) const { return idx[0] + idx[1] * prim[0].sj + idx[2] * prim[0].sk; }
  std::ptrdiff_t face_offset(const std::array<int, 3>& idx) const { return idx[0] + idx[1] * flux[0].sj + idx[2] * flux[0].sk; }
};

// Reconstructs the gathered line (the slots E reconstructs) and sets its face metric; along x with
// the stride known at compile time. without_ye: Ye is not reconstructed (a line whose face states
// give only speeds, with an EOS whose thermodynamics at the faces needs no Ye: the ideal gas).
template <int D, class E, int NumRec, int NumFlux>
inline void reconstruct_line(const RhsSettings& s, const Block& b, const PolarTrig& trig, const std::array<int, 3>& idx,
                             int n, const LineSources& src, std::ptrdiff_t base, std::ptrdiff_t stride,
                             LineScratch<NumRec, NumFlux>& L, bool without_ye = false) {
  for (int q = 0; q < NumRec; ++q)
    if (reconstructed_slot<E>(q) && !(without_ye && q == kRecYe))
      reconstruct(s.reconstruction, L.cell[q], L.left[q], L.right[q], n, L.ppm_scratch());
  if constexpr (D == 0) set_face_metric(b, trig, s.metric_faces, D, idx.data(), n, src, base, UnitStride{}, L);
  else set_face_metric(b, trig, s.metric_faces, D, idx.data(), n, src, base, stride, L);
}

// Where a line's face kernel writes: straight into the flux (and ct) groups, strided across x.
template <int D, int NumFlux>
inline auto line_face_output(double* const* out, std::ptrdiff_t base, std::ptrdiff_t stride) {
  if constexpr (D == 0) return face_output<NumFlux>(out, base, UnitStride{});
  else return face_output<NumFlux>(out, base, stride);
}

}  // namespace remnant::grmhd
