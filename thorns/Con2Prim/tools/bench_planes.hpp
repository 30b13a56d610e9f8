#pragma once
// The two benchmark planes of the paper (after Siegel et al. 2018): sample states, recover them,
// measure eps_recov, iterations, EOS calls and time.
#include <cstdint>
#include <string>
#include <vector>

#include "Atmosphere/atmosphere.hpp"
#include "Con2Prim/report.hpp"
#include "Con2Prim/state.hpp"
#include "EOS/counter.hpp"
#include "EOS/tabulated.hpp"
#include "bench_options.hpp"

namespace c2p_bench {

struct PlanePoint {
  double x = 0, y = 0;  // the plane's axes (log10 values)
  remnant::con2prim::Primitives orig;
  double T_hint = 0;  // passed to recover() (0: none)
};

struct Plane {
  std::string name;            // "rhoT" or "Wb"
  std::string x_name, y_name;  // TSV column names of the axes
  std::vector<PlanePoint> points;
};

struct PointResult {
  double eps_recov = 0;
  int iterations = 0, evaluations = 0;
  std::uint64_t eos_calls = 0;
  remnant::con2prim::Status status = remnant::con2prim::Status::ok;
  double residual = 0;       // conserved_residual of the returned primitives against the input
  std::uint32_t rules = 0;   // policy rules fired
  bool root_scan = false;
  bool nan = false;
};

struct Summary {
  std::size_t points = 0;
  double mean_eps_recov = 0, max_eps_recov = 0;
  double mean_iterations = 0, mean_evaluations = 0, mean_eos_calls = 0;
  int max_iterations = 0;
  std::size_t failures = 0;        // not converged, no bracket, non-finite, or atmosphere
  std::size_t flagged = 0;         // status inaccurate or ambiguous (a wrong or non-unique root, reported)
  std::size_t silently_wrong = 0;  // status ok and no state-moving policy rule, yet the primitives miss
                                   // the input conserved variables by more than Settings::accuracy
  std::size_t policy = 0;          // status ok, missed by more than the accuracy, but a policy rule that
                                   // moves the state fired (reported by the rule's count, not silent)
  std::size_t nan = 0;             // any returned primitive NaN/inf
  std::size_t imprecise = 0;       // status ok, conserved variables reproduced, but eps_recov > 1e-8:
                                   // the conserved variables do not pin the state down better
  double ns_per_recovery = 0;      // NoCount EOS, averaged over the plane
};

Plane rho_T_plane(const remnant::eos::Tabulated<>& eos, const Options& o);
Plane W_b_plane(const remnant::eos::Tabulated<>& eos, const Options& o);
// --fuzz=N: N states drawn uniformly in log rho, log T, Ye over the whole table, log W in [0, 4],
// log10(b^2/2p) in [-10, 10], v and B in independent random directions (seeded by --seed).
Plane fuzz_states(const remnant::eos::Tabulated<>& eos, const Options& o);
// --hint=F: every point's T_hint = T exp(F u), u uniform in [-1, 1] (seeded by --seed).
void add_hints(Plane& plane, const Options& o);

// eps_recov = (1/5) sum over (rho, v, eps, B, Ye) of |1 - P_recov/P_orig| (vectors: |dP|/|P|).
double eps_recov(const remnant::con2prim::Primitives& got, const remnant::con2prim::Primitives& orig);

std::vector<PointResult> run_counted(const remnant::eos::Tabulated<remnant::eos::CountCalls>& eos,
                                     const remnant::con2prim::Settings& s, const remnant::atmosphere::Atmosphere& atm,
                                     const Plane& plane);
double time_ns_per_recovery(const remnant::eos::Tabulated<>& eos, const remnant::con2prim::Settings& s,
                            const remnant::atmosphere::Atmosphere& atm, const Plane& plane, double min_seconds);

Summary summarise(const std::vector<PointResult>& r, double accuracy);
void write_tsv(const std::string& path, const Plane& plane, const std::vector<PointResult>& r);

}  // namespace c2p_bench
