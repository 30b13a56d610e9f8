#pragma once
// Bit-for-bit equality of two solves' outputs (a reused cache against a fresh solver, several ranks
// against one, a regrid against a new solver): the same sizes and the same bytes.
#include <cstring>
#include <vector>

#include "XCFC/multigrid/composite_multigrid.hpp"

namespace remnant::xcfc::test {

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

inline bool same_bits(const CompositeField& a, const CompositeField& b) {
  if (a.part.size() != b.part.size()) return false;
  for (std::size_t n = 0; n < a.part.size(); ++n)
    if (!same_bits(a.part[n], b.part[n])) return false;
  return true;
}

}  // namespace remnant::xcfc::test
