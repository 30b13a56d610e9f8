// The reconstruction's contract (reconstruction.hpp): left and right are written at faces 0..n only,
// so arrays of exactly n + 1 values are safe (PPM used to write right[-1] and left[n + 1] as
// scratch), and PPM keeps the bits of Colella & Woodward's constraints written with branches.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "GRMHD/reconstruction.hpp"

namespace {

using namespace remnant::grmhd;

constexpr int kCells = 16, kGhosts = 3;
constexpr double kGuard = -12345.0;

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// A line with smooth parts, a jump, an extremum and steep one-sided profiles, ghosts included.
std::vector<double> line(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> q(kCells + 2 * kGhosts);
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double x = double(i);
    q[i] = (i % 7 == 3 ? 5.0 : 1.0) + 0.3 * std::sin(x) + 0.05 * u(rng) + (i > q.size() / 2 ? 2.0 : 0.0);
  }
  return q;
}

// CW84 eqs. 1.10 with branches: the reference for the selects of reconstruct_ppm.
void ppm_with_branches(const double* q, double* left, double* right, int n) {
  std::vector<double> face(n + 3);
  double* a = face.data() + 1;
  for (int f = -1; f <= n + 1; ++f) {
    const double lo = q[f - 1], hi = q[f];
    const double v = (7.0 / 12.0) * (lo + hi) - (1.0 / 12.0) * (q[f - 2] + q[f + 1]);
    a[f] = std::clamp(v, std::min(lo, hi), std::max(lo, hi));
  }
  for (int c = -1; c <= n; ++c) {
    const double qc = q[c];
    double aL = a[c], aR = a[c + 1];
    if ((aR - qc) * (qc - aL) <= 0) {
      aL = aR = qc;
    } else {
      const double d = aR - aL, m6 = 6.0 * (qc - 0.5 * (aL + aR));
      if (d * m6 > d * d) aL = 3.0 * qc - 2.0 * aR;
      else if (-d * d > d * m6) aR = 3.0 * qc - 2.0 * aL;
    }
    if (c >= 0) right[c] = aL;
    if (c < n) left[c + 1] = aR;
  }
}

// left and right of exactly n + 1 values between guard values; PPM's scratch of exactly
// ppm_scratch_size(n) values, also between guards.
TEST(Reconstruction, WritesOnlyTheFacesOfTheLine) {
  for (Reconstruction r : {Reconstruction::ppm, Reconstruction::mc, Reconstruction::minmod, Reconstruction::ppm_ep})
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const std::vector<double> q = line(seed);
      std::vector<double> left(kCells + 3, kGuard), right(kCells + 3, kGuard);
      std::vector<double> scratch(ppm_scratch_size(kCells) + 2, kGuard);
      reconstruct(r, q.data() + kGhosts, left.data() + 1, right.data() + 1, kCells,
                  std::span<double>(scratch.data() + 1, ppm_scratch_size(kCells)));
      for (const std::vector<double>* a : {&left, &right, &scratch}) {
        EXPECT_EQ(a->front(), kGuard) << "reconstruction " << int(r) << ": written below the array";
        EXPECT_EQ(a->back(), kGuard) << "reconstruction " << int(r) << ": written above the array";
      }
      for (int f = 1; f <= kCells + 1; ++f) {
        EXPECT_NE(left[f], kGuard) << "face " << f - 1 << " not written";
        EXPECT_NE(right[f], kGuard) << "face " << f - 1 << " not written";
      }
    }
}

TEST(Reconstruction, PpmHasTheBitsOfTheBranchConstraints) {
  int steep = 0, flat = 0;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const std::vector<double> q = line(seed);
    std::vector<double> left(kCells + 1), right(kCells + 1), ref_left(kCells + 1), ref_right(kCells + 1);
    std::vector<double> scratch(ppm_scratch_size(kCells));
    reconstruct_ppm(q.data() + kGhosts, left.data(), right.data(), kCells, scratch);
    ppm_with_branches(q.data() + kGhosts, ref_left.data(), ref_right.data(), kCells);
    for (int f = 0; f <= kCells; ++f) {
      EXPECT_TRUE(same_bits(left[f], ref_left[f])) << "seed " << seed << " face " << f;
      EXPECT_TRUE(same_bits(right[f], ref_right[f])) << "seed " << seed << " face " << f;
      if (f < kCells) {
        const double qc = q[kGhosts + f];
        flat += right[f] == qc && left[f + 1] == qc;
        steep += right[f] != qc && (right[f] == 3.0 * qc - 2.0 * left[f + 1] || left[f + 1] == 3.0 * qc - 2.0 * right[f]);
      }
    }
  }
  // The lines exercise every branch.
  EXPECT_GT(flat, 0);
  EXPECT_GT(steep, 0);
}

}  // namespace
