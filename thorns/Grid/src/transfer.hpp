#pragma once
// One piece of ghost filling: points of a destination block computed from a source block of the
// same level (copy), the next finer one (restriction) or the next coarser one (prolongation),
// through a boundary map. The kernels read the source through a Field, so that the source may be
// the block itself or a message buffer holding the packed source box: same bits either way.
#include <array>
#include <cstdint>

#include "boundary_map.hpp"
#include "box.hpp"
#include "level_geometry.hpp"

namespace remnant::grid {

enum class TransferKind : std::uint8_t { copy, restrict, prolong };

struct Transfer {
  TransferKind kind = TransferKind::copy;
  std::int64_t src_gid = -1, dst_gid = -1;
  int src_level = 0, dst_level = 0;
  Range src_origin{};  // global index (on src_level) of the source block's point (0, 0, 0)
  Range dst_origin{};  // global index (on dst_level) of the destination block's point (0, 0, 0)
  Box dst_box;         // destination-local points to fill
  Box src_box;         // source-local points read (what a message carries)
  IndexMap map;        // destination global index -> image global index, both on dst_level
};

// A Field whose (i, j, k) address the points of `box` stored contiguously at `data`.
inline Field buffer_field(double* data, const Box& box) {
  Field f;
  f.sj = box.size(0);
  f.sk = static_cast<std::ptrdiff_t>(box.size(0)) * box.size(1);
  f.origin = data - (box.lo[0] + box.lo[1] * f.sj + box.lo[2] * f.sk);
  return f;
}

// dst(p) = sign * (copy | restrict | prolong of src)(map(p)) for every p in t.dst_box.
// Cell-centred (stagger 0): volume-weighted restriction, conservative slope-limited (MC) linear
// prolongation about the sqrt(f) centroids. Face-centred: area-weighted restriction, prolongation
// linear in the normal and constant in the tangential directions (ghosts; new blocks of a regrid
// get face-normal vectors from face_prolongation.hpp). Edge-centred: the mean over the fine edges
// along (with their 1D weights), prolongation bilinear across and constant along.
void apply_transfer(const Transfer& t, const Field& src, const Field& dst, double sign,
                    const std::array<int, 3>& stagger, int dimension, const LevelGeometry& geometry);

}  // namespace remnant::grid

namespace remnant::grid {
// The staggering of a centering in the used directions (unused ones have a single point).
inline std::array<int, 3> effective_stagger(Centering c, int dimension) {
  auto s = staggering(c);
  for (int d = dimension; d < 3; ++d) s[static_cast<std::size_t>(d)] = 0;
  return s;
}
}  // namespace remnant::grid
