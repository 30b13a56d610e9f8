#include "factor_cache.hpp"

#include <algorithm>
#include <utility>

namespace remnant::xcfc {

bool FactorCache::zero_k(const ScalarEquation& eq) {
  return std::all_of(eq.k.begin(), eq.k.end(), [](double v) { return v == 0.0; });
}

void FactorCache::swap_with(std::vector<Level>& levels, Slot& s) {
  if (s.levels.size() != levels.size()) {
    // First use: spare arrays of the levels' sizes (a swap never changes a level's array sizes).
    s.levels.resize(levels.size());
    for (std::size_t l = 0; l < levels.size(); ++l) {
      const Level& L = levels[l];
      auto& a = s.levels[l];
      a.w = L.line_w, a.inv = L.line_inv, a.z = L.line_z, a.cyclic = L.line_cyclic, a.c1 = L.end_c1;
    }
  }
  for (std::size_t l = 0; l < levels.size(); ++l) {
    Level& L = levels[l];
    auto& a = s.levels[l];
    std::swap(L.line_w, a.w), std::swap(L.line_inv, a.inv), std::swap(L.line_z, a.z);
    std::swap(L.line_cyclic, a.cyclic), std::swap(L.end_c1, a.c1);
  }
}

bool FactorCache::acquire(std::vector<Level>& levels, const ScalarEquation& eq) {
  pending_ = -1;
  int want = -1;
  if (eligible(eq)) {
    const FactorKey k = key(eq);
    for (std::size_t i = 0; i < slots_.size(); ++i)
      if (slots_[i].key == k) want = static_cast<int>(i);
    if (want < 0 && slots_.size() < kMaxSlots) {
      slots_.push_back(Slot{k, false, {}});
      want = static_cast<int>(slots_.size()) - 1;
    }
  }
  if (held_ >= 0 && held_ != want) {
    swap_with(levels, slots_[static_cast<std::size_t>(held_)]);  // the levels' own arrays back
    held_ = -1;
  }
  if (want < 0) return false;
  Slot& s = slots_[static_cast<std::size_t>(want)];
  if (held_ != want) swap_with(levels, s), held_ = want;  // a slot not yet filled: spares to compute into
  if (!s.filled) {
    pending_ = want;
    return false;
  }
  for (std::size_t l = 0; l < levels.size(); ++l) levels[l].factored = s.levels[l].factored;
  ++hits_;
  return true;
}

void FactorCache::computed(const std::vector<Level>& levels) {
  if (pending_ < 0) return;
  Slot& s = slots_[static_cast<std::size_t>(pending_)];
  for (std::size_t l = 0; l < levels.size(); ++l) s.levels[l].factored = levels[l].factored;
  s.filled = true;
  pending_ = -1;
}

}  // namespace remnant::xcfc
