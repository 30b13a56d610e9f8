#include "HandOff/source_data.hpp"

namespace remnant::handoff {

double reflection_parity(const std::string& v, int d) {
  const char axis = static_cast<char>('x' + d);
  auto vector_index = [&](const std::string& prefix) -> int {
    if (v.size() == prefix.size() + 3 && v.compare(0, prefix.size(), prefix) == 0 && v[prefix.size()] == '[')
      return v[prefix.size() + 1] - '0';
    return -1;
  };
  for (const char* p : {"vel", "Bvec", "St"}) {
    const int c = vector_index(p);
    if (c >= 0) return c == d ? -1.0 : 1.0;
  }
  if (v.size() == 5 && v.compare(0, 4, "beta") == 0) return v[4] == axis ? -1.0 : 1.0;
  if (v.size() == 3 && v[0] == 'g' && v[1] >= 'x' && v[1] <= 'z' && v[2] >= 'x' && v[2] <= 'z')
    return ((v[1] == axis) != (v[2] == axis)) ? -1.0 : 1.0;
  return 1.0;
}

}  // namespace remnant::handoff
