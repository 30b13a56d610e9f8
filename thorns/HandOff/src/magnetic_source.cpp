#include "magnetic_source.hpp"

#include <cmath>

#include "point_metric.hpp"
#include "remnant/error.hpp"

namespace remnant::handoff {

bool has_magnetic_field(const SourceData& src) { return src.has("Bvec[0]") && src.has("Bvec[1]") && src.has("Bvec[2]"); }

void add_magnetic_source(SourceData& src) {
  const bool metric = has_metric_fields(src);
  for (auto& L : src.levels) {
    const std::size_t n = L.size();
    const double* B[3] = {L.fields.at("Bvec[0]").data(), L.fields.at("Bvec[1]").data(), L.fields.at("Bvec[2]").data()};
    const LevelMetric g(L, metric);
    std::vector<double>* Bt[3];
    for (int a = 0; a < 3; ++a) (Bt[a] = &L.fields[densitised_field_names()[static_cast<std::size_t>(a)]])->assign(n, 0.0);
    auto& emag = L.fields["Emag"];
    auto& emag_tor = L.fields["Emagtor"];
    emag.assign(n, 0.0), emag_tor.assign(n, 0.0);
    for (int k = 0; k < L.n[2]; ++k)
      for (int j = 0; j < L.n[1]; ++j)
        for (int i = 0; i < L.n[0]; ++i) {
          const std::size_t q = L.index(i, j, k);
          if (!L.valid[q]) continue;
          const auto [m, det] = metric_at(g, q);
          if (!(det > 0)) continue;  // add_conserved has refused such a metric already
          const double sg = std::sqrt(det);
          double B2 = 0;
          for (int a = 0; a < 3; ++a) {
            (*Bt[a])[q] = sg * B[a][q];
            for (int c = 0; c < 3; ++c) B2 += m[a][c] * B[a][q] * B[c][q];
          }
          emag[q] = 0.5 * sg * B2;
          const double x = L.x(0, i), y = L.x(1, j), w2 = x * x + y * y;
          if (w2 > 0) {
            const double bphi = -y * B[0][q] + x * B[1][q];
            emag_tor[q] = 0.5 * sg * std::cbrt(det) * bphi * bphi / w2;
          }
        }
  }
}

}  // namespace remnant::handoff
