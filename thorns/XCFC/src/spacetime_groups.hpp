#pragma once
// The groups an xCFC solve reads and writes: Spacetime's metric and the densitised matter sources
// that a matter thorn fills in XCFC's source and recovery groups (thorn.yaml). XCFC reads no
// matter variables of its own.
#include "remnant/context.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::xcfc {

struct SpacetimeGroups {
  int metric = -1, sources = -1;
  static SpacetimeGroups of(const Context& ctx) {
    return {vars::Spacetime::metric::id(ctx), vars::Spacetime::matter_sources::id(ctx)};
  }
};

}  // namespace remnant::xcfc
