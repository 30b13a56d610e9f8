#pragma once
// Contiguous line buffers of one direction sweep (cells with ghosts, face states, metric, fluxes),
// shared by the hydro and the MHD sweeps; and the metric at a face from the cell values of a line.
#include <vector>

#include "GRMHD/valencia.hpp"
#include "groups.hpp"

namespace remnant::grmhd {

enum class MetricFaceInterpolation { linear, cubic };

template <int NumRec, int NumFlux>
struct LineScratch {
  int cap = 0;
  std::vector<double> storage;
  double* cell[NumRec];        // cell values, offset so that [0] is the first interior cell
  double* left[NumRec];        // faces 0..n
  double* right[NumRec];
  double* met[Metric::ncomp];  // cell metric along the line
  double* flux[NumFlux];       // face fluxes (weighted)
  double* ppm;                 // reconstruction scratch
  int ng = 0;
  void ensure(int n, int ngh) {
    const int len = n + 2 * ngh + 4;
    if (len <= cap && ngh == ng) return;
    cap = len;
    ng = ngh;
    const int arrays = NumRec * 3 + Metric::ncomp + NumFlux + 1;
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
    for (double*& a : met) a = take(ngh + 1);
    for (double*& a : flux) a = take(1);
    ppm = take(1);
  }
};

inline double face_value(MetricFaceInterpolation m, const double* a, int f) {
  if (m == MetricFaceInterpolation::cubic)
    return (9.0 * (a[f - 1] + a[f]) - (a[f - 2] + a[f + 1])) * (1.0 / 16.0);
  return 0.5 * (a[f - 1] + a[f]);
}

}  // namespace remnant::grmhd
