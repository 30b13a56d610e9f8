#pragma once
// The matter side of the xCFC sequence on the local blocks: the sources from HydroBase's densitised
// conserved variables and the conserved variables of given primitives (initial data), through the
// generated views. (The primitive recovery with the new psi is the matter thorn's, scheduled in the
// group XCFC_RecoverPrimitives.)
#include <cstdint>

#include "remnant/context.hpp"

namespace remnant::xcfc {

struct MatterGroups {
  int cons = -1, prim = -1, metric = -1;
  static MatterGroups of(const Context& ctx);
};

// cons = psi^6 * cons(prim, psi^4 f) on the interior.
void conserved_from_primitives(Context& ctx, const MatterGroups& g);
// S~ = psi^6 S = S^_i v^i + 3 psi^6 p per cell (S^_i the densitised momentum), on one block.
struct DensitisedStressTrace {
  Field psi, S[3], v[3], press;
  DensitisedStressTrace(Block& b, const MatterGroups& g);
  double operator()(int i, int j, int k) const;
};

}  // namespace remnant::xcfc
