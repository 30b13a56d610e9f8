#pragma once
// Settings of the primitive recovery; the thorn publishes them as service "con2prim".
#include <string>

#include "Con2Prim/error_policy.hpp"
#include "EOS/types.hpp"

namespace remnant::con2prim {

enum class Method {
  kastaun,     // the paper's scheme: Kastaun et al. 2021 adapted to tabulated EOS
  palenzuela,  // Palenzuela et al. 2015: 1D in x = hW, Brent (Siegel et al. 2018 form)
};

struct Settings {
  Method method = Method::kastaun;
  double tolerance = 5e-9;     // relative bracket width of the master root (the paper's 5e-9)
  int max_iterations = 300;    // of the master root finder
  // eps -> T inside the master function: `exact` inverts the table interpolant directly,
  // `brent` is the paper's Brent in T (more EOS calls, same root up to 1e-14).
  eos::InversionMethod eps_to_T = eos::InversionMethod::exact;
  // Take the root's state at the secant root of Brent's final bracket (free: no EOS call; more
  // accurate by orders of magnitude). false: Brent's best point, as in the paper.
  bool secant_polish = true;
  // Acceptance: a converged result whose conserved variables differ from the input by more than
  // this (conserved_residual, residual.hpp) is a wrong root: root scan, else Status::inaccurate.
  double accuracy = 1e-6;
  PolicySettings policy;
};

inline const char* to_string(Method m) { return m == Method::kastaun ? "kastaun" : "palenzuela"; }
inline bool parse_method(const std::string& s, Method& m) {
  if (s == "kastaun") return m = Method::kastaun, true;
  if (s == "palenzuela") return m = Method::palenzuela, true;
  return false;
}

}  // namespace remnant::con2prim
