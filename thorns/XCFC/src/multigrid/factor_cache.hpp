#pragma once
// Line factors kept between solves for operators that depend on the geometry only. A linear
// equation without a matter coefficient (eq.k empty: the vector components, whose point term is the
// angular mode's geometry, and chi) has the same line matrices on every level in every solve, so
// their Thomas factors (and line ends) are computed once per equation kind and swapped in (O(1))
// instead of refactored per solve. The bits are those of a fresh factorisation.
#include <array>
#include <vector>

#include "level.hpp"

namespace remnant::xcfc {

// What the factors of an eligible equation depend on besides the grid.
struct FactorKey {
  AngularMode mode = AngularMode::none;
  Parities parity = kEven;
  double falloff = 1.0;
  bool operator==(const FactorKey&) const = default;
};

class FactorCache {
 public:
  // Whether an equation's factors depend on the geometry only.
  // (k empty or zero: the composite solver passes its base level's zeros.)
  static bool eligible(const ScalarEquation& eq) { return zero_k(eq) && !eq.nonlinear() && !eq.dirichlet; }
  static bool zero_k(const ScalarEquation& eq);
  static FactorKey key(const ScalarEquation& eq) { return {eq.mode, eq.parity, eq.falloff}; }

  // Makes the levels hold the factors of `eq`. Returns true when they are cached (line ends,
  // factors and the factored flags now in place: nothing to compute); false when the caller must
  // compute them (set_line_ends, factor_lines*) and then call computed().
  bool acquire(std::vector<Level>& levels, const ScalarEquation& eq);
  // The factors just computed for the equation of the last acquire() are now cached.
  void computed(const std::vector<Level>& levels);
  long long hits() const { return hits_; }

 private:
  struct Slot {
    FactorKey key;
    bool filled = false;
    // Per level: the arrays swapped with the level's (same sizes), and the factored flag.
    struct Arrays {
      std::array<std::vector<double>, 3> w, inv;
      std::vector<double> z, cyclic;
      std::array<std::array<std::vector<double>, 2>, 3> c1;
      bool factored = false;
    };
    std::vector<Arrays> levels;
  };
  void swap_with(std::vector<Level>& levels, Slot& s);
  static constexpr std::size_t kMaxSlots = 8;  // x, y, z components and chi need 4
  std::vector<Slot> slots_;
  int held_ = -1;     // the slot whose factors the levels hold (its arrays: the levels' spares)
  int pending_ = -1;  // the slot of the last acquire() that missed
  long long hits_ = 0;
};

}  // namespace remnant::xcfc
