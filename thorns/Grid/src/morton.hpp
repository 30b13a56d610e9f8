#pragma once
// Morton (Z-order) keys: interleaved bits of the block index, i in the lowest bit. Blocks close
// on the curve are close in space, so contiguous chunks of it make compact rank domains.
#include <array>
#include <cstdint>

namespace remnant::grid {

// Spreads the low 21 bits of v so that bit b lands at bit 3b.
constexpr std::uint64_t spread_bits_3(std::uint64_t v) {
  v &= 0x1fffffULL;
  v = (v | (v << 32)) & 0x1f00000000ffffULL;
  v = (v | (v << 16)) & 0x1f0000ff0000ffULL;
  v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
  v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x1249249249249249ULL;
  return v;
}

// Valid for indices below 2^21 in each direction.
constexpr std::uint64_t morton_key(const std::array<std::int64_t, 3>& index) {
  return spread_bits_3(static_cast<std::uint64_t>(index[0])) |
         (spread_bits_3(static_cast<std::uint64_t>(index[1])) << 1) |
         (spread_bits_3(static_cast<std::uint64_t>(index[2])) << 2);
}

static_assert(morton_key({1, 0, 0}) == 1 && morton_key({0, 1, 0}) == 2 && morton_key({0, 0, 1}) == 4);
static_assert(morton_key({2, 0, 0}) == 8 && morton_key({3, 3, 3}) == 63);

}  // namespace remnant::grid
