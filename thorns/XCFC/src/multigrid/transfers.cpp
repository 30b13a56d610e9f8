#include "transfers.hpp"

#include <array>

namespace remnant::xcfc {

void restrict_interior(const Level& F, const Level& C, const std::vector<double>& fine, std::vector<double>& coarse,
                       const Range& RF, const Range& RC) {
  coarse.assign(C.stored_cells, 0.0);
  const GridShape& s = F.shape;
  for (int k = RF.k0; k < RF.k1; ++k)
    for (int j = RF.j0; j < RF.j1; ++j)
      for (int i = 0; i < s.n[0]; ++i) {
        const std::size_t q = F.cell(i, j, k);
        coarse[C.cell(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2])] += F.volume[q] * fine[q];
      }
  for_cells(C, RC, [&](std::size_t q, std::ptrdiff_t) { coarse[q] /= C.restrict_volume[q]; });
}
void restrict_ghosted(const Level& F, const Level& C, const std::vector<double>& fine, std::vector<double>& coarse,
                      const Range& RF, const Range& RC) {
  coarse.assign(C.stored_ghosted, 0.0);
  const GridShape& s = F.shape;
  for (int k = RF.k0; k < RF.k1; ++k)
    for (int j = RF.j0; j < RF.j1; ++j)
      for (int i = 0; i < s.n[0]; ++i)
        coarse[static_cast<std::size_t>(C.at(i / F.ratio[0], j / F.ratio[1], k / F.ratio[2]))] +=
            F.volume[F.cell(i, j, k)] * fine[static_cast<std::size_t>(F.at(i, j, k))];
  for_cells(C, RC,
            [&](std::size_t q, std::ptrdiff_t p) { coarse[static_cast<std::size_t>(p)] /= C.restrict_volume[q]; });
}
void prolong(const Level& C, const Level& F, const std::vector<double>& coarse, std::vector<double>& fine, bool replace,
             const Range& RF) {
  const GridShape& s = F.shape;
  for (int k = RF.k0; k < RF.k1; ++k)
    for (int j = RF.j0; j < RF.j1; ++j)
      for (int i = 0; i < s.n[0]; ++i) {
        const std::array<int, 3> f{i, j, k};
        std::array<int, 3> c{};
        for (int d = 0; d < 3; ++d) c[d] = f[d] / F.ratio[d];
        const std::ptrdiff_t pc = C.at(c[0], c[1], c[2]);
        double v = coarse[static_cast<std::size_t>(pc)];
        for (int d = 0; d < 3; ++d) {
          if (F.ratio[d] != 2) continue;
          const double sign = (f[d] & 1) ? 0.125 : -0.125;
          v += sign * (coarse[static_cast<std::size_t>(pc + C.st[d])] - coarse[static_cast<std::size_t>(pc - C.st[d])]);
        }
        double& out = fine[static_cast<std::size_t>(F.at(i, j, k))];
        out = replace ? v : out + v;
      }
}

}  // namespace remnant::xcfc
