#pragma once
// Group ids and component layout of the GRMHD variables (thorn.yaml) and of Spacetime::metric.
#include <array>

#include "remnant/context.hpp"

namespace remnant::grmhd {

// Components of GRMHD::prim.
enum PrimIndex : int { kRho = 0, kVel1 = 1, kVel2 = 2, kVel3 = 3, kEps = 4, kPress = 5, kTemp = 6, kYe = 7, kLorentz = 8, kCs2 = 9 };
inline constexpr int kNumPrim = 10;
// Components of Spacetime::metric.
enum MetricIndex : int { kPsi = 0, kAlpha = 1, kBeta1 = 2, kBeta2 = 3, kBeta3 = 4 };
inline constexpr int kNumMetric = 5;

struct Groups {
  int cons = -1, cons_rhs = -1, prim = -1, metric = -1;
  std::array<int, 3> flux{-1, -1, -1};
  int budget = -1, budget_rhs = -1;  // GRMHD::mass_budget (outflow, source) and its rhs
  static Groups of(const Context& ctx) {
    Groups g;
    g.cons = ctx.var("GRMHD::cons");
    g.cons_rhs = ctx.var("GRMHD::cons_rhs");
    g.prim = ctx.var("GRMHD::prim");
    g.metric = ctx.var("Spacetime::metric");
    g.flux = {ctx.var("GRMHD::flux_x"), ctx.var("GRMHD::flux_y"), ctx.var("GRMHD::flux_z")};
    g.budget = ctx.var("GRMHD::mass_budget");
    g.budget_rhs = ctx.var("GRMHD::mass_budget_rhs");
    return g;
  }
};

}  // namespace remnant::grmhd
