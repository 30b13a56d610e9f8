#include "ct_faces.hpp"

namespace remnant::grmhd {

void CtFaceStorage::bind(Block& b, const Groups& g, CtFaces& views, int first, int last) {
  std::array<std::array<int, 3>, 3> extent;
  for (int d = 0; d < 3; ++d) extent[d] = b.group_extent(g.flux[d]);
  if (extent != extent_ || first != first_ || last != last_ || data_.empty()) {
    std::size_t total = 0;
    for (int d = 0; d < 3; ++d) {
      points_[d] = b.points_per_component(g.flux[d]);
      start_[d] = total;
      total += static_cast<std::size_t>(last - first) * points_[d];
    }
    data_.assign(total, 0.0);
    extent_ = extent;
    first_ = first;
    last_ = last;
  }
  for (int d = 0; d < 3; ++d) {
    const Field flux = b.field(g.flux[d], 0);
    const std::ptrdiff_t origin = flux.origin - b.data(g.flux[d]);
    for (int q = first; q < last; ++q)
      views.f[d][q] = {data_.data() + start_[d] + static_cast<std::size_t>(q - first) * points_[d] + origin, flux.sj,
                       flux.sk};
  }
}

}  // namespace remnant::grmhd
