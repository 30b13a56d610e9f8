// Reflection symmetry of B, a pseudo-vector: a field mirror-symmetric about x = 1/4 (from the test
// potential A_z = A0 sin 2pi x sin 2pi y, even about 1/4) pushing a fluid at rest, evolved on
// [-1/4, 3/4] and on the half [1/4, 3/4] with a reflection plane at x = 1/4: the half run must equal
// the full one there. Wrong ghost parities of the face fields (B^x even, B^y odd across the plane)
// or of Bvec show up as differences of order of the field.
// The `opposite` axial parity (Grid::axial_vector_reflection): the same potential is odd about
// x = 0 and y = 0, so B^x is odd and B^y even across x = 0 (minus the pseudo-vector mirror image,
// as a poloidal field about z across the planes of an octant); the quadrant [0, 1/2]^2 with both
// planes `opposite` must equal the full [-1/2, 1/2]^2 (corner ghosts cross both planes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "mhd_run.hpp"
#include "remnant/vars/HydroBase.hpp"

namespace {

using namespace remnant;
using namespace remnant::grmhd::test;

// (a, global i, global j) -> face value; and the fluid's v^x, v^y by cell.
using Faces = std::map<std::array<long long, 3>, double>;
using FaceKey = std::array<long long, 3>;

// The x and y face fields of the run's blocks under the keys key(b, a, i, j) gives (none: not
// compared), and the largest |v^x|, |v^y| of its cells.
template <class Key>
Faces collect_faces(MhdRun& run, double& vmax, Key key) {
  Faces f;
  using Prim = remnant::vars::HydroBase::prim;
  const int prim = run.group(Prim::full_name);
  vmax = 0;
  for (Block* b : run.blocks()) {
    for (int a = 0; a < 2; ++a) {
      const Field bf = b->field(run.group("HydroBase::Bface" + std::to_string(a + 1)), 0);
      for (int j = 0; j < b->n[1] + (a == 1); ++j)
        for (int i = 0; i < b->n[0] + (a == 0); ++i)
          if (const std::optional<FaceKey> k = key(*b, a, i, j)) f[*k] = bf(i, j, 0);
    }
    const Prim p(*b, prim);
    for_interior(*b, [&](int i, int j, int k) { vmax = std::max({vmax, std::abs(p.vel(0, i, j, k)), std::abs(p.vel(1, i, j, k))}); });
  }
  return f;
}

Faces run_faces(bool half, double& vmax) {
  const std::string grid = std::string("dimension: 2, ncells: [") + (half ? "16" : "32") +
                           ", 16, 1], block_size: [8, 8, 1], xmin: [" + (half ? "0.25" : "-0.25") +
                           ", 0, 0], xmax: [0.75, 1, 1], ghost_zones: 3, "
                           "boundary_lower: [" + (half ? "reflect" : "outflow") + ", periodic, outflow], "
                           "boundary_upper: [outflow, periodic, outflow]";
  MhdRun run(mhd_parfile(grid,
                         "reconstruction: ppm, initial_data: shock_tube, shock_position: 10, "
                         "shock_left: [1.0, 0.0, 0.0, 0.0, 0.1], shock_right: [1.0, 0.0, 0.0, 0.0, 0.1], "
                         "field_potential_amplitude: 0.1",
                         "cfl: 0.4, final_time: 0.3"));
  const long long offset = half ? 16 : 0;  // global x index of x = 1/4 in the full run is 16
  return collect_faces(run, vmax, [offset](const Block& b, int a, int i, int j) -> std::optional<FaceKey> {
    const long long gi = b.index[0] * b.n[0] + i + offset, gj = b.index[1] * b.n[1] + j;
    if (gi < 16) return std::nullopt;
    return FaceKey{a, gi, gj};
  });
}

// The x-y faces of the full square [-1/2, 1/2]^2 (32^2 cells) or of its quadrant [0, 1/2]^2 with
// reflect planes at x = 0 and y = 0 and the given axial parity, keyed by the full run's indices.
Faces run_square(bool quadrant, const std::string& axial, double& vmax, bool refined = false) {
  const std::string lo = quadrant ? "0" : "-0.5", n = quadrant ? "16" : "32";
  const std::string grid = "dimension: 2, ncells: [" + n + ", " + n + ", 1], block_size: [8, 8, 1], xmin: [" + lo +
                           ", " + lo + ", 0], xmax: [0.5, 0.5, 1], ghost_zones: 3, boundary_lower: [" +
                           (quadrant ? "reflect, reflect" : "outflow, outflow") +
                           ", outflow], boundary_upper: [outflow, outflow, outflow], axial_vector_reflection: [" + axial + "]" +
                           (refined ? std::string(", max_level: 1, regions: [box], region_levels: [1], region_bounds: [") +
                                          (quadrant ? "0" : "-0.2") + ", 0.2, " + (quadrant ? "0" : "-0.2") + ", 0.2, 0, 1]"
                                    : std::string());
  MhdRun run(mhd_parfile(grid,
                         "reconstruction: ppm, initial_data: shock_tube, shock_position: 10, "
                         "shock_left: [1.0, 0.0, 0.0, 0.0, 0.1], shock_right: [1.0, 0.0, 0.0, 0.0, 0.1], "
                         "field_potential_amplitude: 0.1",
                         "cfl: 0.4, final_time: 0.2"));
  return collect_faces(run, vmax, [quadrant](const Block& b, int a, int i, int j) -> std::optional<FaceKey> {
    // Keys: the full run's indices on the block's level (level 1: faces of the fine cells).
    const long long offset = quadrant ? 16LL << b.level : 0, half = 16LL << b.level;
    const long long gi = b.index[0] * b.n[0] + i + offset, gj = b.index[1] * b.n[1] + j + offset;
    if (gi < half || gj < half) return std::nullopt;
    return FaceKey{a + 2 * b.level, gi, gj};
  });
}

// Largest difference of the faces both hold, and the largest |value| of `part`.
std::array<double, 2> compare(const Faces& whole, const Faces& part, int& compared) {
  double diff = 0, scale = 0;
  compared = 0;
  for (const auto& [key, value] : part) {
    auto it = whole.find(key);
    if (it == whole.end()) continue;
    diff = std::max(diff, std::abs(it->second - value));
    scale = std::max(scale, std::abs(value));
    ++compared;
  }
  return {diff, scale};
}

}  // namespace

TEST(MHDSymmetry, OppositeAxialParityQuadrantMatchesTheFullDomain) {
  double v_full, v_opposite, v_mirror;
  const Faces full = run_square(false, "mirror, mirror, mirror", v_full);
  const Faces opposite = run_square(true, "opposite, opposite, mirror", v_opposite);
  const Faces mirror = run_square(true, "mirror, mirror, mirror", v_mirror);
  int n_opposite = 0, n_mirror = 0;
  const auto [d_opposite, s_opposite] = compare(full, opposite, n_opposite);
  const auto [d_mirror, s_mirror] = compare(full, mirror, n_mirror);
  std::printf("quadrant vs full domain, odd potential: %d faces, max |dB| %.2e (opposite), %.2e (mirror) of max |B| %.2e; "
              "max |v| %.2e (full) %.2e (opposite)\n",
              n_opposite, d_opposite, d_mirror, s_opposite, v_full, v_opposite);
  ASSERT_GT(n_opposite, 400);
  EXPECT_GT(v_full, 1e-3) << "the field must move the fluid";
  EXPECT_LT(d_opposite, 1e-12 * s_opposite);
  EXPECT_GT(d_mirror, 1e-3 * s_mirror) << "the mirror parity must not fit an odd field (the test would not see the setting)";
}

// The same with a refined box around the corner: faces prolonged into ghosts across the planes.
TEST(MHDSymmetry, OppositeAxialParityRefinedQuadrantMatchesTheFullDomain) {
  double v_full, v_opposite;
  const Faces full = run_square(false, "mirror, mirror, mirror", v_full, true);
  const Faces opposite = run_square(true, "opposite, opposite, mirror", v_opposite, true);
  int n = 0, fine = 0;
  const auto [diff, scale] = compare(full, opposite, n);
  for (const auto& [key, value] : opposite) fine += key[0] >= 2 && full.count(key);
  std::printf("refined quadrant vs full domain: %d faces (%d fine), max |dB| %.2e of max |B| %.2e\n", n, fine, diff, scale);
  ASSERT_GT(fine, 200);
  EXPECT_LT(diff, 1e-12 * scale);
}

TEST(MHDSymmetry, ReflectionPlaneMatchesTheFullDomain) {
  double v_full, v_half;
  const Faces full = run_faces(false, v_full), half = run_faces(true, v_half);
  double diff = 0, scale = 0;
  int compared = 0;
  for (const auto& [key, value] : half) {
    auto it = full.find(key);
    if (it == full.end()) continue;
    diff = std::max(diff, std::abs(it->second - value));
    scale = std::max(scale, std::abs(value));
    ++compared;
  }
  std::printf("reflection plane vs full domain: %d faces, max |dB| %.2e of max |B| %.2e; max |v| %.2e (full) %.2e (half)\n",
              compared, diff, scale, v_full, v_half);
  ASSERT_GT(compared, 500);
  EXPECT_GT(v_full, 1e-3) << "the field must move the fluid";
  EXPECT_LT(diff, 1e-12 * scale);
}
