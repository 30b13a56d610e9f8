#include "remnant/group_view.hpp"

#include <string>

namespace remnant {

void GroupView::bind(Block& b, int group, int ncomp) {
  const std::size_t points = b.points_per_component(group);
  if (points == 0 || b.size(group) != points * static_cast<std::size_t>(ncomp))
    throw RunError("variable view of group " + std::to_string(group) + " expects " + std::to_string(ncomp) +
                   " components, but the block holds " + std::to_string(points ? b.size(group) / points : 0) +
                   ": the generated view header is older than the thorn.yaml the executable was built with");
  const Field f = b.field(group, 0);
  origin_ = f.origin;
  sj_ = f.sj;
  sk_ = f.sk;
  cs_ = static_cast<std::ptrdiff_t>(points);
  group_ = group;
}

}  // namespace remnant
