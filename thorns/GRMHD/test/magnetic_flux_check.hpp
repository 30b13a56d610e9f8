#pragma once
// The divergence constraint of a finished run, globally: (1) every cell's discrete divergence
// relative to the fluxes through its faces; (2) every face shared by two blocks of one level has
// the same flux in both; (3) every coarse face covered by finer faces carries their summed flux.
// (2) and (3) are what the per-block divergence cannot see: a mismatch between neighbours is a
// magnetic monopole on the block boundary.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <span>

#include "constrained_transport.hpp"
#include "interior_faces.hpp"
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd::test {

struct FluxCheck {
  double cell = 0;         // max relative divergence of a cell
  double shared = 0;       // max relative difference of one face's flux seen by two blocks
  double coarse_fine = 0;  // max relative difference of a coarse face's flux and its fine faces' sum
  int coarse_faces = 0;    // coarse faces compared with fine ones
};

// periodic_cells: level-0 cells of each periodic direction (0 elsewhere): faces on the upper
// periodic boundary are keyed as the lower ones, so that a coarse/fine interface through the
// periodic seam is compared too.
inline FluxCheck check_magnetic_flux(const MhdGroups& g, std::span<Block* const> blocks,
                                     std::array<long long, 3> periodic_cells = {0, 0, 0}) {
  FluxCheck r;
  using Key = std::array<long long, 5>;  // direction, level, global face indices
  std::map<Key, double> flux;
  double scale = 0;
  for (Block* b : blocks) {
    r.cell = std::max(r.cell, relative_divergence(g, *b));
    for (int a = 0; a < 3; ++a) {
      const Field f = b->field(g.bface[a], 0);
      for_interior_faces(*b, a, [&](int i, int j, int k) {
        Key key{a, b->level, b->index[0] * b->n[0] + i, b->index[1] * b->n[1] + j, b->index[2] * b->n[2] + k};
        const long long wrap = periodic_cells[static_cast<std::size_t>(a)] << b->level;
        if (wrap > 0 && key[2 + a] == wrap) key[2 + a] = 0;
        const double phi = b->face_area(a, i, j, k) * f(i, j, k);
        scale = std::max(scale, std::abs(phi));
        auto [it, fresh] = flux.emplace(key, phi);
        if (!fresh) r.shared = std::max(r.shared, std::abs(it->second - phi));
      });
    }
  }
  for (const auto& [key, phi] : flux) {
    const int a = static_cast<int>(key[0]);
    double sum = 0;
    int found = 0;
    // The fine faces: index 2I along a, 2J + {0, 1} across (one where the direction is unused:
    // detected by probing the second one).
    for (int q = 0; q < 4; ++q) {
      Key fine{key[0], key[1] + 1, 2 * key[2], 2 * key[3], 2 * key[4]};
      int bit = 0;
      for (int d = 0; d < 3; ++d) {
        if (d == a) continue;
        fine[2 + d] += (q >> bit) & 1;
        ++bit;
      }
      auto it = flux.find(fine);
      if (q == 0 && it == flux.end()) break;
      if (it != flux.end()) {
        sum += it->second;
        ++found;
      }
    }
    if (found == 0) continue;
    ++r.coarse_faces;
    r.coarse_fine = std::max(r.coarse_fine, std::abs(sum - phi));
  }
  if (scale > 0) {
    r.shared /= scale;
    r.coarse_fine /= scale;
  }
  return r;
}

}  // namespace remnant::grmhd::test
