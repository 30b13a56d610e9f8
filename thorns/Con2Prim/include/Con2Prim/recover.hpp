#pragma once
// The pointwise primitive recovery, steps (i)-(vi) of the paper, for any EOS type of the EOS thorn
// (template: no virtual call per cell; dispatch the eos::EOS variant once per loop with eos.visit).
//
//   (i)   Ye = DYe/D within [Ye_min, Ye_max]; D < D_thr = rho_thr: atmosphere, nothing else done
//   (ii)-(iv)  master function root (Kastaun: kastaun.hpp; or Palenzuela: palenzuela.hpp)
//   (v)   velocity from the root; atmosphere check rho < rho_thr; error policy (error_policy.hpp)
//   (vi)  one EOS call at (rho, T, Ye) for p, cs2 (no further eps -> T inversion); the conserved
//         variables are recomputed from the corrected primitives and written back into `cons`.
//   acceptance: a converged result must reproduce the input conserved variables to
//         Settings::accuracy (residual.hpp) unless the policy moved it on purpose. Otherwise, and
//         wherever the table is acausal (cs2 > 1: several roots possible), every root
//         of the master function is tried (root_scan.hpp): Status::inaccurate when none reproduces
//         them, Status::ambiguous when several do.
//
// `cons` is NOT densitised (see state.hpp). NaN/inf input or D < 0 gives an atmosphere cell with
// Status::invalid_input; the output is never NaN. B^i is copied to prim.B (non-finite B: set to 0).
#include <cmath>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/error_policy.hpp"
#include "Con2Prim/kastaun.hpp"
#include "Con2Prim/palenzuela.hpp"
#include "Con2Prim/prim_to_cons.hpp"
#include "Con2Prim/report.hpp"
#include "Con2Prim/residual.hpp"
#include "Con2Prim/root_scan.hpp"
#include "Con2Prim/settings.hpp"
#include "Con2Prim/state.hpp"

namespace remnant::con2prim {

namespace detail {

inline bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
inline bool finite(const Primitives& p) {
  return std::isfinite(p.rho) && std::isfinite(p.W) && std::isfinite(p.eps) && std::isfinite(p.press) &&
         std::isfinite(p.T) && std::isfinite(p.ye) && finite(p.v);
}

// Policy rules that move the state away from the conserved variables on purpose: their residual is
// the policy's doing, not a wrong root.
inline constexpr std::uint32_t kRulesMovingState =
    kRuleEpsBelowMin | kRuleTBelowMin | kRuleEpsBelowLow | kRuleEpsAboveHigh | kRuleWAboveMax | kFatalRules;

template <class E>
bool acausal_at(const E& eos, const Primitives& p) {
  if constexpr (requires { eos.acausal(p.rho, p.ye); }) return eos.acausal(p.rho, p.ye);
  return false;
}

// One candidate root carried through steps (v)-(vi).
struct Candidate {
  Primitives prim;
  Conserved cons;  // prim_to_cons(prim) where the residual was computed (has_cons)
  std::uint32_t rules = 0;
  bool atmosphere = false, finite = true, has_cons = false;
  signed char acausal = -1;  // the table's acausal flag at prim, known from the final EOS call (-1: not known)
  double residual = INFINITY;
  bool clean() const { return !atmosphere && finite && !(rules & kRulesMovingState); }
};

template <class E>
bool acausal_at(const E& eos, const Candidate& c) {
  return c.acausal >= 0 ? c.acausal != 0 : acausal_at(eos, c.prim);
}

// (v) velocity, atmosphere check, error policy; (vi) the final EOS call; the residual against `input`.
template <class E>
Candidate complete(const E& eos, const Settings& s, const atmosphere::Atmosphere& atm, const Metric3& g,
                   const Conserved& input, RootSolution sol, Primitives prim, std::uint32_t rules) {
  Candidate c;
  match_speed_to_W(g, sol.W, sol.v);
  prim.rho = sol.rho;
  prim.W = sol.W;
  prim.v = sol.v;
  prim.eps = sol.eps;
  prim.T = sol.T;
  if constexpr (E::has_temperature) rules |= rules_from_inversion(sol.inversion_flags);
  if (atm.is_atmosphere(prim.rho)) {
    c.atmosphere = true, c.rules = rules, c.prim = prim;
    return c;
  }
  const double rho_recovered = prim.rho, T_recovered = prim.T;
  rules |= apply_error_policy(eos, s.policy, prim, ThermoInput::consistent);
  if constexpr (eos::is_tabulated_v<E>) {
    // The root's (rho, T) kept by the policy: p and cs2 at its ln T (no ln T -> T -> ln T round trip,
    // no eps or entropy, which are not needed).
    if (prim.rho == rho_recovered && prim.T == T_recovered && std::isfinite(sol.lnT)) {
      const eos::PressCs2 pc = eos.press_cs2(prim.rho, sol.lnT, prim.ye);
      prim.press = pc.press;
      prim.cs2 = pc.cs2;
      c.acausal = pc.acausal;
    } else {
      const eos::Thermo th = eos.thermo(prim.rho, prim.T, prim.ye);
      prim.press = th.press;
      prim.cs2 = th.cs2;
      if (prim.rho != rho_recovered) prim.eps = th.eps;  // rule 10 moved rho: eps follows (rho, T, Ye)
    }
  } else {
    const eos::Thermo th = eos.thermo(prim.rho, prim.T, prim.ye);
    prim.press = th.press;
    prim.cs2 = th.cs2;
    if (prim.rho != rho_recovered) prim.eps = th.eps;  // rule 10 moved rho: eps follows (rho, T, Ye)
  }
  c.prim = prim;
  c.rules = rules;
  c.finite = finite(prim);
  // Barotropic EOS: the system is over-determined (eps follows rho, tau enters the master function
  // but cannot be matched), so there is nothing to accept or reject: residual 0.
  if constexpr (E::has_temperature)
    if (c.finite) {
      c.cons = prim_to_cons(prim, g);
      c.has_cons = true;
      c.residual = conserved_residual(c.cons, input, g);
    }
  if constexpr (!E::has_temperature) c.residual = 0;
  return c;
}

// Out of line: inlined, the rare scan path changed how the hot path is compiled (SFHo, no scans:
// +4 % instructions per recovery in the master function).
template <class Solver, class E, class OnRoot>
[[gnu::noinline]] int scan(const E& eos, const Settings& s, const Metric3& g, const Conserved& c, double ye,
                           OnRoot&& on_root) {
  Solver solver(eos, s, g, c, ye);
  return scan_roots(solver, s, on_root);
}

template <class E>
RootSolution solve_master(const E& eos, const Settings& s, const Metric3& g, const Conserved& c, double ye,
                          double T_hint, bool early_stop = true) {
  if (s.method == Method::palenzuela) return PalenzuelaSolver<E>(eos, s, g, c, ye, T_hint).solve(s);
  return KastaunSolver<E>(eos, s, g, c, ye, T_hint).solve(s, early_stop);
}

}  // namespace detail

// T_hint (MeV, optional; <= 0 or not finite: none): a temperature near the answer, e.g. the cell's
// T from the previous step. With a table and the exact inversion it is where the first evaluation's
// T search starts in cells where eps rises with T; it changes the cost only, never the root found
// (the root scans start without it). Without it the recovery is bit-identical to before.
template <class E>
Report recover(const E& eos, const Settings& s, const atmosphere::Atmosphere& atm, const Metric3& g,
               Conserved& cons, Primitives& prim, double T_hint = 0) {
  const auto calls0 = eos.counter().count();
  const Conserved input = cons;
  Report rep;
  auto finish = [&](const Conserved* known = nullptr) {
    cons = known ? *known : prim_to_cons(prim, g);
    rep.eos_calls = eos.counter().count() - calls0;
    return rep;
  };
  auto to_atmosphere = [&](Status st) {
    atm.set(prim);
    rep.status = st;
    return finish();
  };

  if (!detail::finite(cons.B)) cons.B = {0, 0, 0};
  prim.B = cons.B;
  const bool finite_input = std::isfinite(cons.D) && std::isfinite(cons.tau) && std::isfinite(cons.DYe) &&
                            detail::finite(cons.S);
  if (!finite_input || cons.D < 0) return to_atmosphere(Status::invalid_input);

  // (i)
  if (atm.is_atmosphere(cons.D)) return to_atmosphere(Status::atmosphere);
  const eos::Bounds& b = eos.bounds();
  prim.ye = cons.DYe / cons.D;
  std::uint32_t ye_rules = 0;
  if (prim.ye < b.ye_min) prim.ye = b.ye_min, ye_rules |= kRuleYeBelowMin;
  if (prim.ye > b.ye_max) prim.ye = b.ye_max, ye_rules |= kRuleYeAboveMax;

  // (ii)-(iv)
  RootSolution sol = detail::solve_master(eos, s, g, cons, prim.ye, T_hint);
  rep.iterations = sol.iterations;
  rep.evaluations = sol.evaluations;
  rep.aux_iterations = sol.aux_iterations;
  if (!sol.bracketed) return rep.rules = ye_rules, to_atmosphere(Status::no_bracket);
  if (!sol.converged) rep.status = Status::not_converged;

  // (v)-(vi), and the acceptance test: the result must reproduce the conserved variables. Where it
  // does not (and the policy did not move it on purpose), or where the table is acausal and the
  // root may not be the only one, every root of the master function is tried.
  detail::Candidate best = detail::complete(eos, s, atm, g, input, sol, prim, ye_rules);
  if (sol.early_stop && !(best.residual <= s.tolerance) &&
      !(sol.inversion_flags & (eos::kInvBelowEpsLow | eos::kInvAboveEpsHigh))) {
    // Brent's early stop (tables) not confirmed by the conserved variables to the root tolerance:
    // solve again with the bracket closed, as without the early stop. (A root clamped by rules 8/9
    // is not: its residual is the clamp's, which the root scan below handles as before.)
    sol = detail::solve_master(eos, s, g, cons, prim.ye, T_hint, false);
    rep.iterations += sol.iterations;
    rep.evaluations += sol.evaluations;
    rep.status = sol.converged ? Status::ok : Status::not_converged;
    best = detail::complete(eos, s, atm, g, input, sol, prim, ye_rules);
  }
  // A clamp by rules 8/9 does not excuse a residual here: raising eps to eps_low can create a root
  // beside the physical one (LS220 above ~5e15 g/cm^3), so a clean root is looked for first.
  const bool wrong = best.finite && !best.atmosphere && best.residual > s.accuracy &&
                     (!(best.rules & detail::kRulesMovingState & ~(kRuleEpsBelowLow | kRuleEpsAboveHigh)) ||
                      detail::acausal_at(eos, best));
  if (rep.status == Status::ok && (wrong || (best.clean() && detail::acausal_at(eos, best)))) {
    int good = best.clean() && best.residual <= s.accuracy;
    // Two states reproducing the conserved variables settle the outcome (ambiguous, the first one
    // kept): the scan stops there (issue 21: LS220's ambiguous states stopped scanning half way).
    auto on_root = [&](const RootSolution& root) {
      const detail::Candidate c = detail::complete(eos, s, atm, g, input, root, prim, ye_rules);
      if (!(c.clean() && c.residual <= s.accuracy)) return false;
      // A second state reproducing the conserved variables (not the first one found again).
      if (good && std::abs(c.prim.rho - best.prim.rho) <= 1e-6 * best.prim.rho &&
          std::abs(c.prim.eps - best.prim.eps) <= 1e-6 * (std::abs(best.prim.eps) + 1e-10))
        return false;
      if (!good) best = c, rep.root_scan = true;
      return ++good > 1;
    };
    if (s.method == Method::palenzuela) detail::scan<PalenzuelaSolver<E>>(eos, s, g, cons, prim.ye, on_root);
    else detail::scan<KastaunSolver<E>>(eos, s, g, cons, prim.ye, on_root);
    if constexpr (eos::is_tabulated_v<E>)
      if (!good && s.method == Method::kastaun) {
        // Several roots, none of those found clean (the scan's 128 intervals can miss a close pair):
        // Kastaun from mu_+ (the bracket before issue 21's nearer upper end) may reach another root.
        const RootSolution alt = KastaunSolver<E>(eos, s, g, cons, prim.ye, T_hint).solve(s, false, false);
        if (alt.bracketed && alt.converged) {
          const detail::Candidate c = detail::complete(eos, s, atm, g, input, alt, prim, ye_rules);
          if (c.clean() && c.residual <= s.accuracy) best = c, rep.root_scan = true, good = 1;
        }
      }
    if (good > 1) rep.status = Status::ambiguous;
  }
  prim = best.prim;
  rep.rules = best.rules;
  rep.residual = best.residual;
  if (best.atmosphere) return to_atmosphere(Status::atmosphere);
  if (!best.finite) return to_atmosphere(Status::non_finite);
  if (rep.status == Status::ok && best.residual > s.accuracy &&
      (!(best.rules & detail::kRulesMovingState) || detail::acausal_at(eos, best)))
    rep.status = Status::inaccurate;
  return finish(best.has_cons ? &best.cons : nullptr);
}

// The same for the shared EOS handle: one std::visit per call. In loops, visit once outside instead.
template <class AnyEos>
  requires requires(const AnyEos& e) { e.visit([](const auto&) {}); }
Report recover_any(const AnyEos& eos, const Settings& s, const atmosphere::Atmosphere& atm, const Metric3& g,
                   Conserved& cons, Primitives& prim, double T_hint = 0) {
  return eos.visit([&](const auto& e) { return recover(e, s, atm, g, cons, prim, T_hint); });
}

}  // namespace remnant::con2prim
