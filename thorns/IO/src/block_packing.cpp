#include "block_packing.hpp"

#include <algorithm>

namespace remnant::io {

namespace {
std::array<int, 3> counts(const Block& b, const VariableGroupSpec& spec, int dimension) {
  const auto s = staggering(spec.centering);
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    c[ud] = b.n[ud] + (d < dimension ? s[ud] : 0);
  }
  return c;
}

template <class F>
void for_points(Block& b, const VariableGroupSpec& spec, int dimension, F&& f) {
  const auto c = counts(b, spec, dimension);
  for (int comp = 0; comp < spec.ncomp(); ++comp) {
    const Field u = b.field(spec.id, comp);
    for (int k = 0; k < c[2]; ++k)
      for (int j = 0; j < c[1]; ++j) f(&u(0, j, k), static_cast<std::size_t>(c[0]));
  }
}
}  // namespace

std::size_t packed_size(const Block& b, const VariableGroupSpec& spec, int dimension) {
  const auto c = counts(b, spec, dimension);
  return static_cast<std::size_t>(spec.ncomp()) * static_cast<std::size_t>(c[0]) * static_cast<std::size_t>(c[1]) *
         static_cast<std::size_t>(c[2]);
}

void pack(Block& b, const VariableGroupSpec& spec, int dimension, std::vector<double>& out) {
  for_points(b, spec, dimension, [&](double* row, std::size_t n) { out.insert(out.end(), row, row + n); });
}

void unpack(Block& b, const VariableGroupSpec& spec, int dimension, const double* in) {
  for_points(b, spec, dimension, [&](double* row, std::size_t n) {
    std::copy(in, in + n, row);
    in += n;
  });
}

}  // namespace remnant::io
