#pragma once
// Compile-time policy counting table evaluations. NoCount compiles to nothing; CountCalls adds
// one integer increment per evaluation (for benchmarks and con2prim statistics).
#include <cstdint>

namespace remnant::eos {

struct NoCount {
  static constexpr bool enabled = false;
  void add(std::uint64_t = 1) const noexcept {}
  std::uint64_t count() const noexcept { return 0; }
  void reset() const noexcept {}
};

struct CountCalls {
  static constexpr bool enabled = true;
  mutable std::uint64_t n = 0;
  void add(std::uint64_t k = 1) const noexcept { n += k; }
  std::uint64_t count() const noexcept { return n; }
  void reset() const noexcept { n = 0; }
};

}  // namespace remnant::eos
