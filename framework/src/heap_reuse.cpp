#include "remnant/heap_reuse.hpp"

#include <mutex>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace remnant {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // arrays below 32 MB from the heap, not from mmap
    mallopt(M_TRIM_THRESHOLD, 1 << 30);   // and the heap's free top kept (up to 1 GB)
    mallopt(M_TOP_PAD, 64 << 20);         // grown in steps of 64 MB (address space, not memory)
  });
#endif
}

}  // namespace remnant
