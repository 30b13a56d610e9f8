#pragma once
// The paper's ten error-handling rules ("Error-handling policy") as one reusable pointwise function.
// It is applied at five places: after importing initial data, before the eps -> T inversion, after
// primitive recovery, after reconstruction, after restriction/prolongation. It returns the bitmask of
// the rules that fired; fatal rules (1, 3, 5) only mark, the caller stops the run.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "Con2Prim/state.hpp"
#include "EOS/types.hpp"
#include "EOS/units.hpp"

namespace remnant::con2prim {

enum PolicyRule : std::uint32_t {
  kRuleRhoAboveMax = 1u << 0,   // 1: rho > rho_max            -> fatal
  kRuleEpsBelowMin = 1u << 1,   // 2: eps < eps_min            -> eps = eps_min
  kRuleEpsAboveMax = 1u << 2,   // 3: eps > eps_max            -> fatal
  kRuleTBelowMin = 1u << 3,     // 4: T < T_min                -> T = T_min
  kRuleTAboveMax = 1u << 4,     // 5: T > T_max                -> fatal
  kRuleYeBelowMin = 1u << 5,    // 6: Ye < Ye_min              -> Ye = Ye_min
  kRuleYeAboveMax = 1u << 6,    // 7: Ye > Ye_max              -> Ye = Ye_max
  kRuleEpsBelowLow = 1u << 7,   // 8: eps <= eps(rho, T_min)   -> eps = eps_low, T = T_min (in eps -> T)
  kRuleEpsAboveHigh = 1u << 8,  // 9: eps >= eps(rho, T_max)   -> eps = eps_high, T = T_max (in eps -> T)
  kRuleWAboveMax = 1u << 9,     // 10: W > W_max, rho <= rho_W_limit -> W = W_max, rho = D / W_max
};
inline constexpr int kNumRules = 10;
inline constexpr std::uint32_t kFatalRules = kRuleRhoAboveMax | kRuleEpsAboveMax | kRuleTAboveMax;
inline bool is_fatal(std::uint32_t rules) { return (rules & kFatalRules) != 0; }

// "1: rho > rho_max (fatal)" etc., for rule index 0..9.
inline const char* rule_name(int i) {
  static const char* const names[kNumRules] = {
      "1: rho > rho_max (fatal)", "2: eps < eps_min", "3: eps > eps_max (fatal)", "4: T < T_min",
      "5: T > T_max (fatal)",     "6: Ye < Ye_min",   "7: Ye > Ye_max",           "8: eps <= eps_low(rho, Ye)",
      "9: eps >= eps_high(rho, Ye)", "10: W > W_max at rho <= W_max_rho_limit"};
  return i >= 0 && i < kNumRules ? names[i] : "?";
}

struct PolicySettings {
  double W_max = 1e3;                                   // the paper gives no value
  // Rule 10 applies only for rho <= this, in code units (parameter Con2Prim::W_max_rho_limit); the
  // default is the paper's 1e11 g/cm^3. Dimensionless problems (densities ~1) need their own value.
  double rho_W_limit = 1e11 * units::rho_cgs_to_code;
};

// Why rule 10 can never fire with these settings, or "" where it can: it needs rho <= rho_W_limit, and
// every cell that is not atmosphere has rho >= rho_thr (Atmosphere::rho_thr).
inline std::string rule10_never_applies(const PolicySettings& s, double rho_thr) {
  if (s.rho_W_limit >= rho_thr) return "";
  char msg[320];
  std::snprintf(msg, sizeof msg,
                "Con2Prim::W_max_rho_limit = %g (code units, %g g/cm^3) is below Atmosphere::rho_thr = %g: "
                "error-policy rule 10 (W > W_max = %g) can never apply; raise W_max_rho_limit (code units) "
                "to the density below which W is to be capped",
                s.rho_W_limit, s.rho_W_limit / units::rho_cgs_to_code, rho_thr, s.W_max);
  return msg;
}

// Which thermodynamic variable of the input state is trusted.
enum class ThermoInput {
  eps,          // eps: rules 2/3, then T from the eps -> T inversion (rules 8/9), then rules 4/5
  temperature,  // T: rules 4/5 (eps then follows from an EOS call by the caller)
  consistent,   // eps and T already agree (after recovery, whose inversion applied 8/9): rules 2-5
};

// Rules 8/9 from the EOS inversion flags.
inline std::uint32_t rules_from_inversion(std::uint32_t inv_flags) {
  return ((inv_flags & eos::kInvBelowEpsLow) ? kRuleEpsBelowLow : 0u) |
         ((inv_flags & eos::kInvAboveEpsHigh) ? kRuleEpsAboveHigh : 0u);
}

// Rule 10 alone: keeps D = rho W, limits W and the speed, rho = D / W_max.
inline std::uint32_t limit_lorentz_factor(const PolicySettings& s, Primitives& p) {
  if (!(p.W > s.W_max && p.rho <= s.rho_W_limit)) return 0;
  const double D = p.rho * p.W;
  const double v = std::sqrt((p.W - 1) * (p.W + 1)) / p.W;
  const double v_max = std::sqrt((s.W_max - 1) * (s.W_max + 1)) / s.W_max;
  const double scale = v > 0 ? v_max / v : 0.0;
  for (double& vi : p.v) vi *= scale;
  p.W = s.W_max;
  p.rho = D / s.W_max;
  return kRuleWAboveMax;
}

// Applies rules 1-10 to p (rho, eps, T, Ye, W, v^i). Does not touch press or cs2: the caller makes
// the final EOS call with the corrected (rho, T, Ye). Barotropic EOS (no temperature) never report
// rules 8/9: their eps always follows from rho.
template <class E>
std::uint32_t apply_error_policy(const E& eos, const PolicySettings& s, Primitives& p, ThermoInput input,
                                 eos::InversionMethod method = eos::InversionMethod::exact) {
  const eos::Bounds& b = eos.bounds();
  std::uint32_t fired = 0;
  if (p.rho > b.rho_max) fired |= kRuleRhoAboveMax;
  if (p.ye < b.ye_min) p.ye = b.ye_min, fired |= kRuleYeBelowMin;
  if (p.ye > b.ye_max) p.ye = b.ye_max, fired |= kRuleYeAboveMax;
  fired |= limit_lorentz_factor(s, p);

  auto check_eps = [&] {
    if (p.eps < b.eps_min) p.eps = b.eps_min, fired |= kRuleEpsBelowMin;
    if (p.eps > b.eps_max) fired |= kRuleEpsAboveMax;
  };
  auto check_T = [&] {
    if (p.T < b.T_min) p.T = b.T_min, fired |= kRuleTBelowMin;
    if (p.T > b.T_max) fired |= kRuleTAboveMax;
  };
  switch (input) {
    case ThermoInput::eps: {
      check_eps();
      const eos::Inversion inv = eos.temperature(p.rho, p.eps, p.ye, p.T, method);
      if constexpr (E::has_temperature) fired |= rules_from_inversion(inv.flags);
      p.T = inv.T;
      p.eps = inv.eps;
      check_T();
      break;
    }
    case ThermoInput::temperature:
      check_T();
      break;
    case ThermoInput::consistent:
      check_eps();
      check_T();
      break;
  }
  return fired;
}

}  // namespace remnant::con2prim
