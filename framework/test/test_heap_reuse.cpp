// Every test program starts as the executables do (test_main.cpp, run_main: remnant/heap_reuse.hpp):
// a 16 MB array freed stays in the heap (glibc's mallinfo2 counts it as free heap memory) instead
// of being unmapped, so the next xCFC solve's arrays of that size cause no page faults.
#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <vector>

namespace {

TEST(HeapReuse, FreedArraysStayInTheHeap) {
#if !defined(__GLIBC__)
  GTEST_SKIP() << "glibc only";
#else
  constexpr std::size_t bytes = 16u << 20;
  {
    std::vector<char> a(bytes, 1);
    ASSERT_EQ(a[bytes - 1], 1);
  }
  EXPECT_GE(mallinfo2().fordblks, bytes) << "the freed 16 MB left the heap (unmapped or trimmed)";
#endif
}

}  // namespace
