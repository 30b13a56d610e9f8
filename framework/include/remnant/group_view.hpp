#pragma once
// Typed access to one variable group on one block. The named views that `remnant-genviews`
// generates from each thorn.yaml (<remnant/vars/<Thorn>.hpp>) derive from GroupView, so a kernel
// writes `prim.rho(i, j, k)` or `metric.psi(i, j, k)` and never a component number by hand.
#include <cstddef>
#include <string_view>

#include "remnant/context.hpp"
#include "remnant/grid.hpp"

namespace remnant {

// Position of the symmetric rank-2 component (a, b) in the order 11 12 13 22 23 33.
constexpr int symmetric_index(int a, int b) {
  const int lo = a < b ? a : b, hi = a < b ? b : a;
  return lo == 0 ? hi : (lo == 1 ? 2 + hi : 5);
}

class GroupView {
 public:
  GroupView() = default;
  // Unchecked: for code that already holds the group id (tests, benchmarks, callbacks).
  GroupView(Block& b, int group, int ncomp) { bind(b, group, ncomp); }
  // Checked: resolves `full_name`, verifies its component count against the generated header and,
  // in --debug runs, that the running scheduled function declares the group in reads:/writes:.
  GroupView(const Context& ctx, Block& b, std::string_view full_name, int ncomp) {
    const int group = ctx.var(std::string(full_name));
    ctx.check_access(group);
    bind(b, group, ncomp);
  }

  // Component c at (i, j, k); (0, 0, 0) is the first interior point.
  double& operator()(int c, int i, int j, int k) const { return origin_[c * cs_ + i + j * sj_ + k * sk_]; }
  // One component as a Field, for hot loops that hoist it.
  Field field(int c) const { return Field{origin_ + c * cs_, sj_, sk_}; }
  int group() const { return group_; }

 private:
  void bind(Block& b, int group, int ncomp);

  double* origin_ = nullptr;
  std::ptrdiff_t cs_ = 0, sj_ = 0, sk_ = 0;
  int group_ = -1;
};

}  // namespace remnant
