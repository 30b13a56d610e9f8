#pragma once
// Every root of a master function on its bracket, for the rare recovery whose first root does not
// reproduce the conserved variables (an acausal or non-monotonic table can give several roots; see
// residual.hpp). The bracket is sampled at kScanIntervals + 1 points, uniform in the master variable,
// and Brent solves each interval with a sign change. Costs about kScanIntervals EOS inversions: taken only
// where the cheap path failed its acceptance test.
#include "Con2Prim/root_finding.hpp"
#include "Con2Prim/root_solution.hpp"
#include "Con2Prim/settings.hpp"

namespace remnant::con2prim {

inline constexpr int kScanIntervals = 128;
inline constexpr int kMaxScanRoots = 8;

// Fills out[0..n) with the solutions at the roots found (at most kMaxScanRoots) and returns n.
template <class Solver>
int scan_roots(Solver& solver, const Settings& s, RootSolution (&out)[kMaxScanRoots]) {
  using Eval = typename Solver::Eval;
  RootSolution base;
  Eval lo, hi;
  if (!solver.bracket(lo, hi, base)) return 0;
  int n = 0;
  Eval a = lo;
  for (int k = 1; k <= kScanIntervals && n < kMaxScanRoots; ++k) {
    const Eval b = k == kScanIntervals ? hi : solver(lo.x + (hi.x - lo.x) * k / kScanIntervals);
    if ((a.f <= 0) != (b.f <= 0) || a.f == 0) {
      Eval root, far;
      const RootStats st = brent_root(solver, a, b, s.tolerance, s.max_iterations, root, far);
      out[n++] = solver.solution(root, far, st, s, base);
    }
    a = b;
  }
  return n;
}

}  // namespace remnant::con2prim
