#pragma once
// A 64-bit checksum of a block of doubles (FNV-1a over 8-byte words): detects a flipped or
// zeroed region of a checkpoint; not a cryptographic hash.
#include <cstdint>
#include <cstring>
#include <cstddef>
#include <string>

namespace remnant::io {

inline std::uint64_t checksum(const double* data, std::size_t n) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t w;
    std::memcpy(&w, data + i, sizeof w);
    h = (h ^ w) * 1099511628211ull;
    h ^= h >> 29;  // spread high bits down, so nearby words do not cancel
  }
  return h ^ n;
}

inline std::uint64_t checksum(const std::string& s) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h ^ s.size();
}

}  // namespace remnant::io
