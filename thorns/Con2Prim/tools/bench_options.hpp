#pragma once
// Command-line options of remnant-c2p-bench.
#include <cstddef>
#include <string>
#include <vector>

#include "Con2Prim/settings.hpp"
#include "EOS/types.hpp"

namespace c2p_bench {

struct Range {
  double lo = 0, hi = 0;
  int n = 0;
};

struct Options {
  std::string table;
  std::string out_dir = "c2p_bench";
  bool plane_rho_T = true, plane_W_b = true;
  std::vector<remnant::con2prim::Method> methods{remnant::con2prim::Method::kastaun,
                                                 remnant::con2prim::Method::palenzuela};
  // rho-T plane (paper Fig. "Kc2p_performance"): the table's range, at fixed W, b^2/2p, Ye.
  int n_rho = 100, n_T = 100;
  double W = 2, b2p = 1e-3, ye = 0.1;
  double rho_T_max_cgs = 0;  // > 0: upper end of the rho range instead of the table's (g/cm^3)
  // W-b^2/2p plane (paper Fig. "fixedTrho"): at fixed rho, T, Ye; log10(W - 1) and log10(b^2/2p) ranges.
  double rho_cgs = 1e11, T = 5;
  Range log_Wm1{-5.5, 3.0, 52}, log_b2p{-5.0, 9.0, 57};
  bool random_B = false;  // false: B antiparallel to v (Siegel et al. 2018); true: independent direction
  unsigned seed = 1;
  remnant::con2prim::Settings settings;  // tolerance 5e-9 etc.
  double rho_thr = 1e-300;               // atmosphere threshold (none inside the table by default)
  double min_time = 0.5;                 // seconds per timing
  bool time_it = true;
  std::size_t fuzz = 0;                  // > 0: N random states over the whole table instead of the planes
  double hint = -1;                      // >= 0: each recovery gets T_hint = T exp(hint u), u uniform in [-1, 1]
};

// Parses argv; on --help or an error prints usage and returns false (`ok` says which).
bool parse_options(int argc, char** argv, Options& o, bool& ok);

// The options that must lie inside the table (Ye; rho and T of the W-b plane; --rho-max): throws
// std::runtime_error naming the option, its value and the table's range.
void check_against_table(const Options& o, const remnant::eos::Bounds& b);

}  // namespace c2p_bench
