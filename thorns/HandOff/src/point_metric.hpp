#pragma once
// The data's 3-metric at a source point, as the conserved variables (source_quantities.cpp) and the
// magnetic field (magnetic_source.cpp) read it: ADMBase::gxx..gzz as a symmetric matrix, flat
// where the data have none, and its determinant.
#include <array>
#include <cstddef>

#include "HandOff/source_data.hpp"

namespace remnant::handoff {

inline constexpr std::array<const char*, 6> kMetricFieldNames = {"gxx", "gxy", "gxz", "gyy", "gyz", "gzz"};

// True when the data hold all six components.
inline bool has_metric_fields(const SourceData& src) {
  bool metric = true;
  for (const char* g : kMetricFieldNames) metric = metric && src.has(g);
  return metric;
}

// gxx..gzz of one level; all null where the data have no metric (then every point is flat).
struct LevelMetric {
  const double* g[6] = {};
  LevelMetric(const SourceLevel& L, bool metric) {
    if (metric)
      for (std::size_t a = 0; a < 6; ++a) g[a] = L.fields.at(kMetricFieldNames[a]).data();
  }
};

struct PointMetric3 {
  double m[3][3];  // gamma_ij
  double det;
};

inline PointMetric3 metric_at(const LevelMetric& lm, std::size_t q) {
  PointMetric3 p{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 0};
  auto& m = p.m;
  if (lm.g[0]) {
    const double* const* g = lm.g;
    m[0][0] = g[0][q], m[0][1] = m[1][0] = g[1][q], m[0][2] = m[2][0] = g[2][q];
    m[1][1] = g[3][q], m[1][2] = m[2][1] = g[4][q], m[2][2] = g[5][q];
  }
  p.det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return p;
}

}  // namespace remnant::handoff
