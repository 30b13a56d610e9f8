#pragma once
// The loop over a block's interior faces normal to one direction (block faces included), shared by
// the face-field initial data (alfven_wave.cpp, shock_tube_field.cpp) and the tests' flux checks.
#include "remnant/cell_geometry.hpp"

namespace remnant::grmhd {

// Calls f(i, j, k) for every face normal to direction a of the block's interior, i fastest: n + 1
// faces along a where a is used, n across.
template <class F>
inline void for_interior_faces(const Block& b, int a, F&& f) {
  const bool used = direction_used(b, a);
  for (int k = 0; k < b.n[2] + (used && a == 2); ++k)
    for (int j = 0; j < b.n[1] + (used && a == 1); ++j)
      for (int i = 0; i < b.n[0] + (used && a == 0); ++i) f(i, j, k);
}

}  // namespace remnant::grmhd
