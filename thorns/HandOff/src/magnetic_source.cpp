#include "magnetic_source.hpp"

#include <cmath>

#include "remnant/error.hpp"

namespace remnant::handoff {

bool has_magnetic_field(const SourceData& src) { return src.has("Bvec[0]") && src.has("Bvec[1]") && src.has("Bvec[2]"); }

void add_magnetic_source(SourceData& src) {
  static const char* g_names[6] = {"gxx", "gxy", "gxz", "gyy", "gyz", "gzz"};
  bool metric = true;
  for (const char* g : g_names) metric = metric && src.has(g);
  for (auto& L : src.levels) {
    const std::size_t n = L.size();
    const double* B[3] = {L.fields.at("Bvec[0]").data(), L.fields.at("Bvec[1]").data(), L.fields.at("Bvec[2]").data()};
    const double* g[6] = {};
    if (metric)
      for (int a = 0; a < 6; ++a) g[a] = L.fields.at(g_names[a]).data();
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
          double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
          if (metric) {
            m[0][0] = g[0][q], m[0][1] = m[1][0] = g[1][q], m[0][2] = m[2][0] = g[2][q];
            m[1][1] = g[3][q], m[1][2] = m[2][1] = g[4][q], m[2][2] = g[5][q];
          }
          const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
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
