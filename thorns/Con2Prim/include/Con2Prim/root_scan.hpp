#pragma once
// Every root of a master function on its bracket, for the rare recovery whose first root does not
// reproduce the conserved variables (an acausal or non-monotonic table can give several roots; see
// residual.hpp). The bracket is sampled at kScanIntervals + 1 points, uniform in the master variable,
// and Brent solves each interval with a sign change. Costs about kScanIntervals EOS inversions: taken only
// where the cheap path failed its acceptance test (or the root lies in an acausal cell).
// Each root is handed to on_root as soon as Brent has it; on_root returns true when the caller's
// outcome is settled (e.g. a second state reproducing the conserved variables: ambiguous whatever
// else the bracket holds), and the scan stops there. Up to that point the evaluations are those of
// the full scan, so the roots handed over are bit for bit the same.
#include "Con2Prim/root_finding.hpp"
#include "Con2Prim/root_solution.hpp"
#include "Con2Prim/settings.hpp"

namespace remnant::con2prim {

inline constexpr int kScanIntervals = 128;
inline constexpr int kMaxScanRoots = 8;

// Calls on_root(const RootSolution&) -> bool (stop) for each root found, at most kMaxScanRoots
// times, in increasing master variable; returns the number of roots found.
template <class Solver, class OnRoot>
int scan_roots(Solver& solver, const Settings& s, OnRoot&& on_root) {
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
      ++n;
      if (on_root(solver.solution(root, far, st, s, base))) break;
    }
    a = b;
  }
  return n;
}

}  // namespace remnant::con2prim
