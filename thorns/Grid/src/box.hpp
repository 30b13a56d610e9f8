#pragma once
// Index boxes of a block (interior (0,0,0) at the origin, ghosts negative or >= n) and the
// copy kernels between boxes and contiguous buffers. Rows in i are contiguous, so the inner loops
// are plain contiguous copies.
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

// The exchange is memory-bound (stores miss the cache); how a row is copied hardly matters.
inline void copy_row(const double* __restrict src, int n, double* __restrict dst) {
  for (int i = 0; i < n; ++i) dst[i] = src[i];
}

inline double* row(const Field& f, const Box& b, int j, int k) {
  return f.origin + b.lo[0] + static_cast<std::ptrdiff_t>(j) * f.sj + static_cast<std::ptrdiff_t>(k) * f.sk;
}

// Where the components of a group live in any block of the same shape, found once per
// synchronisation instead of once per box and component.
struct GroupLayout {
  int group = 0;
  int ncomp = 0;
  std::ptrdiff_t origin = 0;       // offset of interior (0,0,0) in a component
  std::ptrdiff_t comp_stride = 0;  // points per component
  std::ptrdiff_t sj = 0, sk = 0;

  GroupLayout(Block& b, int g, int n) : group(g), ncomp(n) {
    const Field f = b.field(g, 0);
    origin = f.origin - b.data(g);
    comp_stride = static_cast<std::ptrdiff_t>(b.points_per_component(g));
    sj = f.sj;
    sk = f.sk;
  }
  Field field(Block& b, int comp) const {
    return Field{b.data(group) + origin + comp * comp_stride, sj, sk};
  }
};

// Copies box `from` of field `src` into box `to` (same shape) of field `dst`.
inline void copy_box(const Field& src, const Box& from, const Field& dst, const Box& to) {
  const int nx = from.size(0), ny = from.size(1), nz = from.size(2);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      copy_row(row(src, from, from.lo[1] + j, from.lo[2] + k), nx, row(dst, to, to.lo[1] + j, to.lo[2] + k));
}

// Appends the box of a field to a buffer; returns the position after it.
inline double* pack_box(const Field& src, const Box& b, double* out) {
  const int nx = b.size(0);
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j) {
      copy_row(row(src, b, j, k), nx, out);
      out += nx;
    }
  return out;
}

inline const double* unpack_box(const double* in, const Field& dst, const Box& b) {
  const int nx = b.size(0);
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j) {
      copy_row(in, nx, row(dst, b, j, k));
      in += nx;
    }
  return in;
}

}  // namespace remnant::grid
