#pragma once
// What one recovery reports, and the counters a grid-level caller accumulates from the reports
// (per status, per policy rule, iterations, EOS calls). Filling a Report costs a few integer stores;
// EOS calls are counted only when the EOS type carries eos::CountCalls (NoCount compiles to nothing).
#include <algorithm>
#include <array>
#include <cstdint>

#include "Con2Prim/error_policy.hpp"

namespace remnant::con2prim {

enum class Status : std::uint8_t {
  ok = 0,
  atmosphere,     // D < D_thr (step i) or rho < rho_thr after recovery (step v): atmosphere set
  invalid_input,  // D negative or NaN/inf in any conserved variable: atmosphere set, flagged
  not_converged,  // the master root finder hit max_iterations: its best estimate is used
  no_bracket,     // the master function did not change sign on its bracket: atmosphere set
  non_finite,     // the recovery produced NaN/inf (never seen; a safety net): atmosphere set
  inaccurate,     // the result does not reproduce the conserved variables to Settings::accuracy
                  // (a wrong root, e.g. where the table is acausal): the closest state found is kept
  ambiguous,      // more than one state reproduces the conserved variables: the table is acausal
                  // there (cs2 > 1); the first root found is kept
};
inline constexpr int kNumStatus = 8;

inline const char* to_string(Status s) {
  switch (s) {
    case Status::ok: return "ok";
    case Status::atmosphere: return "atmosphere";
    case Status::invalid_input: return "invalid_input";
    case Status::not_converged: return "not_converged";
    case Status::no_bracket: return "no_bracket";
    case Status::non_finite: return "non_finite";
    case Status::inaccurate: return "inaccurate";
    case Status::ambiguous: return "ambiguous";
  }
  return "?";
}

struct Report {
  Status status = Status::ok;
  std::uint32_t rules = 0;      // PolicyRule bits fired in this cell (steps i, iv, v)
  int iterations = 0;           // root-finder steps on the master function
  int evaluations = 0;          // master-function evaluations (the steps plus the bracket ends)
  int aux_iterations = 0;       // Newton steps on the auxiliary function f_a (Kastaun only)
  std::uint64_t eos_calls = 0;  // EOS evaluations; 0 unless the EOS counts them
  double residual = 0;          // conserved_residual of the result (residual.hpp); 0 where not checked
  bool root_scan = false;       // the first root was wrong and a scan of the master function was needed
  bool fatal() const { return is_fatal(rules); }
  bool failed() const {
    return status == Status::not_converged || status == Status::no_bracket || status == Status::non_finite ||
           status == Status::inaccurate || status == Status::ambiguous;
  }
};

// Grid diagnostics: what a sweep over cells did. Accumulate per block, merge across blocks/ranks.
struct Diagnostics {
  std::uint64_t cells = 0;
  std::array<std::uint64_t, kNumStatus> status{};
  std::array<std::uint64_t, kNumRules> rules{};  // cells in which rule i+1 fired
  std::uint64_t fatal_cells = 0;
  std::uint64_t iterations = 0, evaluations = 0, eos_calls = 0;
  std::uint64_t root_scans = 0;  // recoveries saved by the root scan (counted besides their status)
  int max_iterations = 0;

  // A policy application outside the recovery (import, reconstruction, prolongation).
  void add_rules(std::uint32_t fired) {
    for (int i = 0; i < kNumRules; ++i) rules[i] += (fired >> i) & 1u;
    fatal_cells += is_fatal(fired);
  }
  void add(const Report& r) {
    ++cells;
    ++status[static_cast<int>(r.status)];
    add_rules(r.rules);
    iterations += r.iterations;
    evaluations += r.evaluations;
    eos_calls += r.eos_calls;
    root_scans += r.root_scan;
    max_iterations = std::max(max_iterations, r.iterations);
  }
  void merge(const Diagnostics& o) {
    cells += o.cells;
    for (int i = 0; i < kNumStatus; ++i) status[i] += o.status[i];
    for (int i = 0; i < kNumRules; ++i) rules[i] += o.rules[i];
    fatal_cells += o.fatal_cells;
    iterations += o.iterations;
    evaluations += o.evaluations;
    eos_calls += o.eos_calls;
    root_scans += o.root_scans;
    max_iterations = std::max(max_iterations, o.max_iterations);
  }
  std::uint64_t count(Status s) const { return status[static_cast<int>(s)]; }
};

}  // namespace remnant::con2prim
