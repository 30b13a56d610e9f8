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
#include "EOS/types.hpp"

namespace remnant::con2prim {

inline constexpr int kScanIntervals = 128;
inline constexpr int kMaxScanRoots = 8;
// Samples jumped at once over a stretch proven clamped by rule 9 (KastaunSolver::clamped_high_between).
inline constexpr int kScanJump = 8;

// Calls on_root(const RootSolution&) -> bool (stop) for each root found, at most kMaxScanRoots
// times, in increasing master variable; returns the number of roots found.
template <class Solver, class OnRoot>
int scan_roots(Solver& solver, const Settings& s, OnRoot&& on_root) {
  using Eval = typename Solver::Eval;
  RootSolution base;
  Eval lo, hi;
  if (!solver.bracket(lo, hi, base)) return 0;
  auto sample = [&](int k) {
    return k == kScanIntervals ? hi : solver(lo.x + (hi.x - lo.x) * k / kScanIntervals);
  };
  int n = 0;
  Eval a = lo, ahead;  // ahead: the sample at k_ahead, evaluated for a jump that was not proven
  int k_ahead = -1;
  for (int k = 0; k < kScanIntervals && n < kMaxScanRoots;) {
    if constexpr (requires { solver.clamped_high_between(a, a); }) {
      // A run of samples clamped by rule 9 (the hot end of LS220's bracket, about half its samples)
      // holds no acceptable root: jump over it where the solver proves the whole stretch clamped.
      // After a jump not proven, none is tried before its sample is reached (kept for then):
      // samples out of order cost longer T searches (shorter jumps tried then cost more calls).
      if (k_ahead < k && (a.inv_flags & eos::kInvAboveEpsHigh)) {
        const int far = std::min(k + kScanJump, kScanIntervals);
        const Eval c = sample(far);
        if (solver.clamped_high_between(a, c)) {
          a = c, k = far;
          continue;  // a root inside (a sign change) would be clamped: never accepted
        }
        ahead = c, k_ahead = far;
      }
    }
    const Eval b = k + 1 == k_ahead ? ahead : sample(k + 1);
    if ((a.f <= 0) != (b.f <= 0) || a.f == 0) {
      Eval root, far_end;
      const RootStats st = brent_root(solver, a, b, s.tolerance, s.max_iterations, root, far_end);
      ++n;
      if (on_root(solver.solution(root, far_end, st, s, base))) break;
    }
    a = b, ++k;
  }
  return n;
}

}  // namespace remnant::con2prim
