#pragma once
// Index boxes of a block (interior (0,0,0) at the origin, ghosts negative or >= n) and the
// copy kernels between boxes and contiguous buffers. Rows in i are contiguous, so the inner loops
// are plain copies the compiler turns into memmove-like code.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "remnant/grid.hpp"

namespace remnant::grid {

struct Box {
  std::array<int, 3> lo{0, 0, 0};
  std::array<int, 3> hi{0, 0, 0};  // exclusive
  int size(int d) const { return hi[static_cast<std::size_t>(d)] - lo[static_cast<std::size_t>(d)]; }
  std::size_t points() const {
    return static_cast<std::size_t>(size(0)) * static_cast<std::size_t>(size(1)) *
           static_cast<std::size_t>(size(2));
  }
};

inline double* row(const Field& f, const Box& b, int j, int k) {
  return f.origin + b.lo[0] + static_cast<std::ptrdiff_t>(j) * f.sj + static_cast<std::ptrdiff_t>(k) * f.sk;
}

// Copies box `from` of field `src` into box `to` (same shape) of field `dst`.
inline void copy_box(const Field& src, const Box& from, const Field& dst, const Box& to) {
  const int nx = from.size(0), ny = from.size(1), nz = from.size(2);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      std::copy_n(row(src, from, from.lo[1] + j, from.lo[2] + k), nx,
                  row(dst, to, to.lo[1] + j, to.lo[2] + k));
}

// Appends the box of a field to a buffer; returns the position after it.
inline double* pack_box(const Field& src, const Box& b, double* out) {
  const int nx = b.size(0);
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j) out = std::copy_n(row(src, b, j, k), nx, out);
  return out;
}

inline const double* unpack_box(const double* in, const Field& dst, const Box& b) {
  const int nx = b.size(0);
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j) {
      std::copy_n(in, nx, row(dst, b, j, k));
      in += nx;
    }
  return in;
}

}  // namespace remnant::grid
