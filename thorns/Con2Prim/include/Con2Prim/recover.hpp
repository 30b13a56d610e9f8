#pragma once
// The pointwise primitive recovery, steps (i)-(vi) of the paper, for any EOS type of the EOS thorn
// (template: no virtual call per cell; dispatch the eos::EOS variant once per loop with eos.visit).
//
//   (i)   Ye = DYe/D within [Ye_min, Ye_max]; D < D_thr = rho_thr: atmosphere, nothing else done
//   (ii)-(iv)  master function root (Kastaun: kastaun.hpp; or Palenzuela: palenzuela.hpp)
//   (v)   velocity from the root; atmosphere check rho < rho_thr; error policy (error_policy.hpp)
//   (vi)  one EOS call at (rho, T, Ye) for p, cs2 (no further eps -> T inversion); the conserved
//         variables are recomputed from the corrected primitives and written back into `cons`.
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
#include "Con2Prim/settings.hpp"
#include "Con2Prim/state.hpp"

namespace remnant::con2prim {

namespace detail {

inline bool finite(const Vec3& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
inline bool finite(const Primitives& p) {
  return std::isfinite(p.rho) && std::isfinite(p.W) && std::isfinite(p.eps) && std::isfinite(p.press) &&
         std::isfinite(p.T) && std::isfinite(p.ye) && finite(p.v);
}

template <class E>
RootSolution solve_master(const E& eos, const Settings& s, const Metric3& g, const Conserved& c, double ye) {
  if (s.method == Method::palenzuela) return PalenzuelaSolver<E>(eos, s, g, c, ye).solve(s);
  return KastaunSolver<E>(eos, s, g, c, ye).solve(s);
}

}  // namespace detail

template <class E>
Report recover(const E& eos, const Settings& s, const atmosphere::Atmosphere& atm, const Metric3& g,
               Conserved& cons, Primitives& prim) {
  const auto calls0 = eos.counter().count();
  Report rep;
  auto finish = [&] {
    cons = prim_to_cons(prim, g);
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
  if (prim.ye < b.ye_min) prim.ye = b.ye_min, rep.rules |= kRuleYeBelowMin;
  if (prim.ye > b.ye_max) prim.ye = b.ye_max, rep.rules |= kRuleYeAboveMax;

  // (ii)-(iv)
  RootSolution sol = detail::solve_master(eos, s, g, cons, prim.ye);
  rep.iterations = sol.iterations;
  rep.evaluations = sol.evaluations;
  rep.aux_iterations = sol.aux_iterations;
  if (!sol.bracketed) return to_atmosphere(Status::no_bracket);
  if (!sol.converged) rep.status = Status::not_converged;

  // (v)
  match_speed_to_W(g, sol.W, sol.v);
  prim.rho = sol.rho;
  prim.W = sol.W;
  prim.v = sol.v;
  prim.eps = sol.eps;
  prim.T = sol.T;
  if constexpr (E::has_temperature) rep.rules |= rules_from_inversion(sol.inversion_flags);
  if (atm.is_atmosphere(prim.rho)) return to_atmosphere(Status::atmosphere);
  const double rho_recovered = prim.rho;
  rep.rules |= apply_error_policy(eos, s.policy, prim, ThermoInput::consistent);

  // (vi)
  const eos::Thermo th = eos.thermo(prim.rho, prim.T, prim.ye);
  prim.press = th.press;
  prim.cs2 = th.cs2;
  if (prim.rho != rho_recovered) prim.eps = th.eps;  // rule 10 moved rho: eps follows (rho, T, Ye)
  if (!detail::finite(prim)) return to_atmosphere(Status::non_finite);
  return finish();
}

// The same for the shared EOS handle: one std::visit per call. In loops, visit once outside instead.
template <class AnyEos>
  requires requires(const AnyEos& e) { e.visit([](const auto&) {}); }
Report recover_any(const AnyEos& eos, const Settings& s, const atmosphere::Atmosphere& atm, const Metric3& g,
                   Conserved& cons, Primitives& prim) {
  return eos.visit([&](const auto& e) { return recover(e, s, atm, g, cons, prim); });
}

}  // namespace remnant::con2prim
