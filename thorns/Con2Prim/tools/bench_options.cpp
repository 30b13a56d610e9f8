// remnant-c2p-bench command line.
#include "bench_options.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace c2p_bench {

namespace {

const char* kUsage =
    "usage: remnant-c2p-bench TABLE [options]\n"
    "  The paper's two primitive-recovery benchmarks on a tabulated EOS; writes TSV maps and a summary.\n"
    "  --test=both|rho-T|W-b          which plane(s) (default both)\n"
    "  --method=both|kastaun|palenzuela\n"
    "  --out=DIR                      output folder (default c2p_bench)\n"
    "  rho-T plane (whole table range, cell-centred samples in log rho, log T):\n"
    "  --n-rho=N --n-T=N              samples (default 100 x 100)\n"
    "  --rho-max=X                    upper end of rho [g/cm^3] instead of the table's (e.g. its causal part)\n"
    "  --W=X --b2p=X --ye=X           Lorentz factor, b^2/(2p), Ye (default 2, 1e-3, 0.1)\n"
    "  W-b plane:\n"
    "  --rho=X --T=X                  rho [g/cm^3], T [MeV] (default 1e11, 5; Ye from --ye)\n"
    "  --log-Wm1=LO:HI:N              log10(W - 1) samples (default -5.5:3:52)\n"
    "  --log-b2p=LO:HI:N              log10(b^2/2p) samples (default -5:9:57)\n"
    "  --random-B                     B in a random direction (default: antiparallel to v)\n"
    "  recovery:\n"
    "  --tol=X                        tolerance (default 5e-9)\n"
    "  --max-iter=N                   master root-finder steps (default 300)\n"
    "  --eps-to-T=exact|brent         eps -> T inversion (default exact)\n"
    "  --no-polish                    Brent's best point instead of the secant polish (paper-literal)\n"
    "  --w-max=X                      error-policy W_max (default: none)\n"
    "  --rho-thr=X                    atmosphere threshold, code units (default: none)\n"
    "  --seed=N                       directions of v and B (default 1)\n"
    "  --min-time=S                   seconds per timing run (default 0.5); --no-timing skips it\n";

double number(const std::string& key, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end) throw std::runtime_error("option " + key + ": not a number: '" + v + "'");
  return x;
}

Range range(const std::string& key, const std::string& v) {
  const auto a = v.find(':'), b = v.rfind(':');
  if (a == std::string::npos || a == b) throw std::runtime_error("option " + key + ": expected LO:HI:N");
  Range r{number(key, v.substr(0, a)), number(key, v.substr(a + 1, b - a - 1)), int(number(key, v.substr(b + 1)))};
  if (r.n < 1) throw std::runtime_error("option " + key + ": N must be >= 1");
  return r;
}

}  // namespace

bool parse_options(int argc, char** argv, Options& o, bool& ok) {
  using remnant::con2prim::Method;
  ok = false;
  o.settings.policy.W_max = 1e300;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "-h" || arg == "--help") {
        std::fputs(kUsage, stdout);
        return false;
      }
      if (arg.rfind("--", 0) != 0) {
        if (!o.table.empty()) throw std::runtime_error("more than one table given: " + arg);
        o.table = arg;
        continue;
      }
      const auto eq = arg.find('=');
      const std::string key = arg.substr(0, eq), val = eq == std::string::npos ? "" : arg.substr(eq + 1);
      if (key == "--test") {
        if (val != "both" && val != "rho-T" && val != "W-b") throw std::runtime_error("--test: both, rho-T or W-b");
        o.plane_rho_T = val != "W-b";
        o.plane_W_b = val != "rho-T";
      } else if (key == "--method") {
        Method m;
        if (val == "both") o.methods = {Method::kastaun, Method::palenzuela};
        else if (remnant::con2prim::parse_method(val, m)) o.methods = {m};
        else throw std::runtime_error("--method: both, kastaun or palenzuela");
      } else if (key == "--out") o.out_dir = val;
      else if (key == "--n-rho") o.n_rho = int(number(key, val));
      else if (key == "--n-T") o.n_T = int(number(key, val));
      else if (key == "--rho-max") o.rho_T_max_cgs = number(key, val);
      else if (key == "--W") o.W = number(key, val);
      else if (key == "--b2p") o.b2p = number(key, val);
      else if (key == "--ye") o.ye = number(key, val);
      else if (key == "--rho") o.rho_cgs = number(key, val);
      else if (key == "--T") o.T = number(key, val);
      else if (key == "--log-Wm1") o.log_Wm1 = range(key, val);
      else if (key == "--log-b2p") o.log_b2p = range(key, val);
      else if (key == "--random-B") o.random_B = true;
      else if (key == "--tol") o.settings.tolerance = number(key, val);
      else if (key == "--max-iter") o.settings.max_iterations = int(number(key, val));
      else if (key == "--eps-to-T") {
        if (val == "exact") o.settings.eps_to_T = remnant::eos::InversionMethod::exact;
        else if (val == "brent") o.settings.eps_to_T = remnant::eos::InversionMethod::brent;
        else throw std::runtime_error("--eps-to-T: exact or brent");
      } else if (key == "--no-polish") o.settings.secant_polish = false;
      else if (key == "--w-max") o.settings.policy.W_max = number(key, val);
      else if (key == "--rho-thr") o.rho_thr = number(key, val);
      else if (key == "--seed") o.seed = unsigned(number(key, val));
      else if (key == "--min-time") o.min_time = number(key, val);
      else if (key == "--no-timing") o.time_it = false;
      else throw std::runtime_error("unknown option " + key);
    }
    if (o.table.empty()) throw std::runtime_error("no table given");
    if (o.n_rho < 1 || o.n_T < 1) throw std::runtime_error("--n-rho and --n-T must be >= 1");
    if (!(o.W >= 1)) throw std::runtime_error("--W must be >= 1");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "remnant-c2p-bench: %s\n%s", e.what(), kUsage);
    return false;
  }
  ok = true;
  return true;
}

}  // namespace c2p_bench
