// Building a Multigrid makes the heap keep freed memory for reuse (src/multigrid/heap_reuse.hpp):
// a 16 MB array freed after that stays in the heap (glibc's mallinfo2 counts it as free heap
// memory) instead of being unmapped, so the next solve's arrays of that size cause no page faults.
#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <vector>

#include "XCFC/multigrid/multigrid.hpp"

namespace {

using namespace remnant::xcfc;

TEST(XCFCHeapReuse, FreedArraysStayInTheHeap) {
#if !defined(__GLIBC__)
  GTEST_SKIP() << "glibc only";
#else
  GridShape s;
  s.dimension = 1;
  s.n = {8, 1, 1};
  const Multigrid mg(s);
  constexpr std::size_t bytes = 16u << 20;
  {
    std::vector<char> a(bytes, 1);
    ASSERT_EQ(a[bytes - 1], 1);
  }
  EXPECT_GE(mallinfo2().fordblks, bytes) << "the freed 16 MB left the heap (unmapped or trimmed)";
#endif
}

}  // namespace
