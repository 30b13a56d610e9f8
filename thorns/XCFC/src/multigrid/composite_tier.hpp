#pragma once
// One level ("tier") of the composite multigrid: its patches (Levels with one ghost layer), their
// placement, covered cells and parents, the runs of patches relaxed as single 2D line Levels, and
// the split of the relaxation between MPI ranks (units dealt out by cells, interiors exchanged
// after each pass).
#include <mpi.h>

#include <array>
#include <unordered_map>
#include <utility>
#include <vector>

#include "level.hpp"
#include "level_ops.hpp"

namespace remnant::xcfc {

using Cell = std::array<long long, 3>;

struct Tier {
  GridShape shape;                        // the whole domain on this level
  std::array<int, 3> nb{1, 1, 1};          // cells per patch
  std::array<long long, 3> blocks{1, 1, 1};  // patches per direction if the level were full
  std::vector<Level> patches;
  std::vector<Cell> corner;
  std::unordered_map<long long, int> find;
  std::vector<std::vector<char>> covered;  // interior, per patch
  std::vector<int> parent;                  // patch of tier - 1 holding the footprint
  std::vector<std::vector<double>> ubar, corr, scratch;  // ghosted, ghosted, interior
  std::vector<std::size_t> window_size;
  std::vector<std::array<int, 3>> window_n;
  // Line relaxation (2D, 3D cylindrical and spherical): the patches of each row (direction d) that
  // follow each other without a gap form a run, relaxed as one Level so that lines cross patch
  // boundaries (a run around the whole phi ring is periodic: cyclic lines).
  struct Run {
    std::vector<int> patches;  // in order along d
    Level level;
    std::vector<std::array<int, 3>> offset;  // each patch's first cell in the run's Level
  };
  std::array<std::vector<Run>, 3> runs;
  // 3D spherical: the complete shells of patches next to the origin (every theta and phi block of
  // the innermost radial blocks) as one Level, for the plane relaxation of shell_relaxation.
  std::vector<Run> shell;
  // The split of the relaxation between the ranks: units (single patches for point smoothing,
  // runs of direction d for lines) in contiguous chunks balanced by cells; after a pass the
  // updated interiors are exchanged (MPI_Allgatherv), so every rank again holds the whole tier.
  struct Split {
    std::vector<std::vector<int>> units;  // patches of each unit
    std::vector<std::size_t> first;       // first unit of each rank (nranks + 1 entries)
    std::vector<int> counts, displs;      // doubles per rank
    // The same for one red-black colour's cells (exchange_units), built on first use.
    mutable std::array<std::vector<int>, 2> colour_counts, colour_displs;
  };
  Split points;
  std::array<Split, 3> lines;
  std::vector<double> exchange_buffer;  // exchange_units' gather, kept between passes
};


// Relaxation units dealt out to `nranks` ranks in contiguous chunks balanced by cells.
Tier::Split make_split(const Tier& T, std::vector<std::vector<int>> units, int nranks);
// This rank's units [first, last).
inline std::pair<std::size_t, std::size_t> owned_units(const Tier::Split& S, int rank) {
  return {S.first[static_cast<std::size_t>(rank)], S.first[static_cast<std::size_t>(rank) + 1]};
}
// After a pass: every rank receives the patch interiors its partners updated (MPI_Allgatherv);
// colour >= 0: only the cells of that red-black colour ((i + j + k) % 2 in the patch). Returns the
// bytes this rank received.
long long exchange_units(Tier& T, const Tier::Split& S, MPI_Comm comm, int rank, int nranks, int colour = -1);
// The runs of every direction of a tier (2D, and 3D cylindrical or spherical), and a 3D spherical
// tier's origin shells.
void build_runs(Tier& T);

// Copies between a unit (a run or the shell Level) and its patches: interior cells, and with
// `ghosts` (towards the unit only) the patches' face ghosts that are the unit's own ghosts. `array`
// is Level::u (ghosted) or an interior array.
template <bool ToUnit>
void copy_unit(Tier& T, Tier::Run& R, std::vector<double> Level::*array, bool ghosts) {
  Level& U = R.level;
  const auto& un = U.shape.n;
  for (std::size_t m = 0; m < R.patches.size(); ++m) {
    Level& P = T.patches[static_cast<std::size_t>(R.patches[m])];
    const auto& n = P.shape.n;
    const auto& o = R.offset[m];
    const std::array<int, 3> g{ghosts ? P.g[0] : 0, ghosts ? P.g[1] : 0, ghosts ? P.g[2] : 0};
    for (int k = -g[2]; k < n[2] + g[2]; ++k)
      for (int j = -g[1]; j < n[1] + g[1]; ++j)
        for (int i = -g[0]; i < n[0] + g[0]; ++i) {
          const int out = (i < 0 || i >= n[0]) + (j < 0 || j >= n[1]) + (k < 0 || k >= n[2]);
          if (out > 1) continue;  // edges and corners: no stencil reads them
          const int a = o[0] + i, b = o[1] + j, c = o[2] + k;
          const bool in_unit = a >= 0 && a < un[0] && b >= 0 && b < un[1] && c >= 0 && c < un[2];
          if (out == 1 && in_unit) continue;  // another patch's interior cell
          if (array == &Level::u) {
            double& x = P.u[static_cast<std::size_t>(P.at(i, j, k))];
            double& y = U.u[static_cast<std::size_t>(U.at(a, b, c))];
            if constexpr (ToUnit) y = x; else if (out == 0) x = y;
          } else if (out == 0) {
            double& x = (P.*array)[P.cell(i, j, k)];
            double& y = (U.*array)[U.cell(a, b, c)];
            if constexpr (ToUnit) y = x; else x = y;
          }
        }
  }
}

}  // namespace remnant::xcfc
