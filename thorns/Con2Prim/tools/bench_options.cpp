// remnant-c2p-bench command line.
#include "bench_options.hpp"

#include "EOS/units.hpp"

#include <cmath>
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
    "  --accuracy=X                   acceptance: largest conserved residual of an ok recovery (default 1e-6)\n"
    "  --eps-to-T=exact|brent         eps -> T inversion (default exact)\n"
    "  --no-polish                    Brent's best point instead of the secant polish (paper-literal)\n"
    "  --w-max=X                      error-policy W_max (default: none)\n"
    "  --rho-thr=X                    atmosphere threshold, code units (default: none)\n"
    "  --seed=N                       directions of v and B (default 1)\n"
"  --hint=F                       pass recover() the T hint T_true exp(F u), u uniform in [-1, 1] (seeded by\n"
    "                                 --seed): 0.05 = within 5 %, as from the previous step; 10 = far off\n"
    "  --min-time=S                   seconds per timing run (default 0.5); --no-timing skips it\n"
    "  --fuzz=N                       instead of the planes: N random states over the whole table (rho, T, Ye),\n"
    "                                 W in [1, 1e4], b^2/2p in [1e-10, 1e10]; counts failures, NaN, silently wrong\n"
    "  Out-of-range values are errors (exit code 2): W >= 1, b^2/2p >= 0, Ye, rho, T inside the table,\n"
    "  0 < tol <= 1e-2, max-iter >= 1, sample counts >= 1.\n";

// A finite number (NaN and inf are rejected: every option is a finite quantity).
double number(const std::string& key, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end || !std::isfinite(x))
    throw std::runtime_error("option " + key + "=" + v + ": not a finite number");
  return x;
}

// An integer in [lo, hi].
long long integer(const std::string& key, const std::string& v, long long lo, long long hi) {
  const double x = number(key, v);
  if (x != std::floor(x) || x < double(lo) || x > double(hi))
    throw std::runtime_error("option " + key + "=" + v + ": allowed integers " + std::to_string(lo) + " .. " +
                             std::to_string(hi));
  return static_cast<long long>(x);
}

// Throws "option KEY=VALUE: allowed ..." unless ok.
void allow(bool ok, const std::string& key, double v, const std::string& allowed) {
  if (ok) return;
  char b[64];
  std::snprintf(b, sizeof b, "%g", v);
  throw std::runtime_error("option " + key + "=" + b + ": allowed " + allowed);
}

constexpr long long kMaxSamples = 100000;  // per axis of a plane

Range range(const std::string& key, const std::string& v) {
  const auto a = v.find(':'), b = v.rfind(':');
  if (a == std::string::npos || a == b) throw std::runtime_error("option " + key + "=" + v + ": expected LO:HI:N");
  Range r{number(key, v.substr(0, a)), number(key, v.substr(a + 1, b - a - 1)),
          int(integer(key, v.substr(b + 1), 1, kMaxSamples))};
  if (r.lo > r.hi) throw std::runtime_error("option " + key + "=" + v + ": LO must not exceed HI");
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
      else if (key == "--n-rho") o.n_rho = int(integer(key, val, 1, kMaxSamples));
      else if (key == "--n-T") o.n_T = int(integer(key, val, 1, kMaxSamples));
      else if (key == "--rho-max") {
        o.rho_T_max_cgs = number(key, val);
        allow(o.rho_T_max_cgs > 0, key, o.rho_T_max_cgs, "rho > 0 g/cm^3");
      }
      else if (key == "--W") o.W = number(key, val);
      else if (key == "--b2p") o.b2p = number(key, val);
      else if (key == "--ye") o.ye = number(key, val);
      else if (key == "--rho") o.rho_cgs = number(key, val);
      else if (key == "--T") o.T = number(key, val);
      else if (key == "--log-Wm1") o.log_Wm1 = range(key, val);
      else if (key == "--log-b2p") o.log_b2p = range(key, val);
      else if (key == "--random-B") o.random_B = true;
      else if (key == "--tol") o.settings.tolerance = number(key, val);
      else if (key == "--accuracy") o.settings.accuracy = number(key, val);
      else if (key == "--max-iter") o.settings.max_iterations = int(integer(key, val, 1, 100000));
      else if (key == "--eps-to-T") {
        if (val == "exact") o.settings.eps_to_T = remnant::eos::InversionMethod::exact;
        else if (val == "brent") o.settings.eps_to_T = remnant::eos::InversionMethod::brent;
        else throw std::runtime_error("--eps-to-T: exact or brent");
      } else if (key == "--no-polish") o.settings.secant_polish = false;
      else if (key == "--w-max") o.settings.policy.W_max = number(key, val);
      else if (key == "--rho-thr") o.rho_thr = number(key, val);
      else if (key == "--seed") o.seed = unsigned(integer(key, val, 0, 4294967295LL));
      else if (key == "--fuzz") o.fuzz = std::size_t(integer(key, val, 1, 1000000000LL));
      else if (key == "--min-time") o.min_time = number(key, val);
      else if (key == "--hint") {
        o.hint = number(key, val);
        allow(o.hint >= 0 && o.hint <= 50, "--hint", o.hint, "0 <= F <= 50");
      }
      else if (key == "--no-timing") o.time_it = false;
      else throw std::runtime_error("unknown option " + key);
    }
    if (o.table.empty()) throw std::runtime_error("no table given");
    // Ranges that do not depend on the table (those that do are checked once it is loaded).
    allow(o.W >= 1 && o.W <= 1e10, "--W", o.W, "1 <= W <= 1e10");
    allow(o.b2p >= 0 && o.b2p <= 1e30, "--b2p", o.b2p, "0 <= b^2/2p <= 1e30");
    allow(o.ye >= 0 && o.ye <= 1, "--ye", o.ye, "0 <= Ye <= 1 (and inside the table's Ye range)");
    allow(o.rho_cgs > 0, "--rho", o.rho_cgs, "rho > 0 g/cm^3 (inside the table)");
    allow(o.T > 0, "--T", o.T, "T > 0 MeV (inside the table)");
    allow(o.settings.tolerance > 0 && o.settings.tolerance <= 1e-2, "--tol", o.settings.tolerance,
          "0 < tol <= 1e-2");
    allow(o.settings.accuracy > 0 && o.settings.accuracy < 1, "--accuracy", o.settings.accuracy, "0 < accuracy < 1");
    allow(o.settings.policy.W_max > 1, "--w-max", o.settings.policy.W_max, "W_max > 1");
    allow(o.rho_thr >= 0, "--rho-thr", o.rho_thr, "rho_thr >= 0 (code units)");
    allow(o.min_time >= 0 && o.min_time <= 600, "--min-time", o.min_time, "0 <= seconds <= 600");
    allow(o.log_Wm1.hi <= 8, "--log-Wm1", o.log_Wm1.hi, "HI <= 8 (W <= 1e8)");
    allow(std::abs(o.log_b2p.lo) <= 30 && std::abs(o.log_b2p.hi) <= 30, "--log-b2p", o.log_b2p.hi,
          "-30 <= LO <= HI <= 30");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "remnant-c2p-bench: %s\n%s", e.what(), kUsage);
    return false;
  }
  ok = true;
  return true;
}

void check_against_table(const Options& o, const remnant::eos::Bounds& b) {
  const double to_cgs = 1 / remnant::units::rho_cgs_to_code, r = 1e-12;  // axis ends carry rounding
  auto inside = [&](const char* key, double v, double lo, double hi, const char* unit) {
    if (v >= lo * (1 - r) - r && v <= hi * (1 + r) + r) return;
    char m[256];
    std::snprintf(m, sizeof m, "option %s=%g: outside the table %s (allowed %g .. %g%s)", key, v, o.table.c_str(),
                  lo, hi, unit);
    throw std::runtime_error(m);
  };
  if (o.fuzz == 0) inside("--ye", o.ye, b.ye_min, b.ye_max, "");
  if (o.fuzz == 0 && o.plane_W_b) {
    inside("--rho", o.rho_cgs, b.rho_min * to_cgs, b.rho_max * to_cgs, " g/cm^3");
    inside("--T", o.T, b.T_min, b.T_max, " MeV");
  }
  if (o.rho_T_max_cgs > 0 && !(o.rho_T_max_cgs > b.rho_min * to_cgs)) {
    char m[256];
    std::snprintf(m, sizeof m, "option --rho-max=%g: below the table's rho_min %g g/cm^3 (%s)", o.rho_T_max_cgs,
                  b.rho_min * to_cgs, o.table.c_str());
    throw std::runtime_error(m);
  }
}

}  // namespace c2p_bench
