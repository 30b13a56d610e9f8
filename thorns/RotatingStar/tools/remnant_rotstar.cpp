// remnant-rotstar: one rotating-star model, or a sequence of them, from the RotatingStar solver.
//   remnant-rotstar --K=100 --gamma=2 --rho-c=1.28e-3 --omega=0.02              uniform rotation
//   remnant-rotstar --rho-c=1.28e-3 --axis-ratio=0.7                            Omega found
//   remnant-rotstar --rho-c=1.28e-3 --A2=70 --omega-c=0.02575                   j-constant law
//   remnant-rotstar --K=100 --gammas=2,3 --rho-bounds=5e-4 --rho-c=...          piecewise polytrope
//   remnant-rotstar --eos-table=FILE --rho-c=... [--T=MeV] [--ye=YE]             table: beta equilibrium
//                                                                               (or fixed Ye) at T_min (or T)
//   remnant-rotstar --K=110 --rho-c=1.366e-3 --Km=3.746 --m=1                    toroidal field (Kiuchi & Yoshida)
//   remnant-rotstar ... --sequence=axis-ratio:1:0.6:9 --out=seq.tsv             a sequence (TSV)
// One model prints `name = value` lines; a sequence writes one TSV row per model. Options:
// --nr, --ntheta, --lmax, --r-out-factor, --tolerance (solver), --ye (polytrope), --code-rho (with a
// table, --rho-c is in code units; the default too). Exit 0 on success, 1 for a model without
// solution, 2 for bad command-line input.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "RotatingStar/eos_slice.hpp"
#include "RotatingStar/report.hpp"
#include "RotatingStar/rns_solver.hpp"

namespace {

using namespace remnant::rotstar;

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* kUsage =
    "usage: remnant-rotstar [--K=100] [--gamma=2 | --gammas=G0,G1,.. --rho-bounds=R1,..] [--ye=0.5] | [--eos-table=FILE [--T=MeV] [--ye=YE]]\n"
    "                       --rho-c=RHO  (--omega=OMEGA | --axis-ratio=Q | --A2=A2 --omega-c=OMEGA_C | --A2=A2 --axis-ratio=Q)\n"
    "                       [--Km=K_M [--m=1]]  (toroidal magnetic field B = K_m (alpha^2 varpi^2 rho h)^m / (alpha varpi))\n"
    "                       [--sequence=rho-c|axis-ratio|omega:FROM:TO:N --out=FILE.tsv]\n"
    "                       [--nr=800] [--ntheta=24] [--lmax=20] [--r-out-factor=2] [--tolerance=1e-11]\n";

double number(const std::string& key, const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end || !std::isfinite(v)) throw UsageError("--" + key + "=" + s + ": not a number");
  return v;
}

int run(int argc, char** argv) {
  std::map<std::string, std::string> opt;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--help" || arg == "-h") {
      std::printf("%s", kUsage);
      return 0;
    }
    const auto eq = arg.find('=');
    if (arg.rfind("--", 0) != 0 || eq == std::string::npos) throw UsageError("argument '" + arg + "': expected --name=value");
    opt[arg.substr(2, eq - 2)] = arg.substr(eq + 1);
  }
  static const char* known[] = {"K", "gamma", "gammas", "rho-bounds", "ye", "T", "eos-table", "rho-c", "omega", "omega-c", "A2", "axis-ratio",
                                "Km", "m", "sequence", "out", "nr", "ntheta", "lmax", "r-out-factor", "tolerance"};
  for (const auto& [k, v] : opt) {
    bool ok = false;
    for (const char* n : known) ok = ok || k == n;
    if (!ok) throw UsageError("unknown option --" + k);
  }
  auto get = [&](const char* k, double def) { return opt.count(k) ? number(k, opt[k]) : def; };
  RnsParameters p;
  if (!opt.count("rho-c")) throw UsageError("--rho-c is required");
  p.rho_central = get("rho-c", 0);
  if (opt.count("omega") && opt.count("omega-c")) throw UsageError("give --omega (uniform) or --omega-c with --A2 (j-constant), not both");
  if (opt.count("A2")) {
    p.law = RotationLaw::j_constant;
    p.A2 = get("A2", 0);
    if (opt.count("omega")) throw UsageError("--A2 (j-constant law) takes --omega-c, not --omega");
    p.omega = get("omega-c", 0);
  } else {
    if (opt.count("omega-c")) throw UsageError("--omega-c needs --A2 (the j-constant law)");
    p.omega = get("omega", 0);
  }
  p.axis_ratio = get("axis-ratio", 0);
  if (opt.count("m") && !opt.count("Km")) throw UsageError("--m is the exponent of the toroidal field: it needs --Km");
  p.field.K_m = get("Km", 0);
  p.field.m = get("m", 1);
  if (p.axis_ratio != 0 && p.omega != 0) throw UsageError("give the rotation rate or --axis-ratio, not both");
  p.nr = int(get("nr", p.nr));
  p.n_theta = int(get("ntheta", p.n_theta));
  p.lmax = int(get("lmax", p.lmax));
  p.r_out_factor = get("r-out-factor", p.r_out_factor);
  p.tolerance = get("tolerance", p.tolerance);

  std::unique_ptr<remnant::tov::ColdSlice> slice;
  std::unique_ptr<remnant::eos::Tabulated<>> table;
  if (opt.count("eos-table")) {
    if (opt.count("K") || opt.count("gamma")) throw UsageError("--eos-table excludes --K and --gamma");
    table = std::make_unique<remnant::eos::Tabulated<>>(remnant::eos::load_table(opt["eos-table"]));
    const double T = get("T", -1);
    slice = opt.count("ye") ? fixed_ye_slice(*table, get("ye", 0), T) : beta_slice(*table, T);
  } else if (opt.count("gammas")) {
    if (opt.count("gamma")) throw UsageError("give --gamma (polytrope) or --gammas (piecewise polytrope), not both");
    auto list = [&](const char* key) {
      std::vector<double> v;
      const std::string t = opt.count(key) ? opt[key] : "";
      for (std::size_t a = 0, b; a < t.size(); a = b + 1) {
        b = t.find(',', a);
        if (b == std::string::npos) b = t.size();
        v.push_back(number(key, t.substr(a, b - a)));
      }
      return v;
    };
    slice = piecewise_polytrope_slice(get("K", 100), list("gammas"), list("rho-bounds"), get("ye", 0.5));
  } else {
    if (opt.count("T")) throw UsageError("--T is for --eos-table");
    if (opt.count("rho-bounds")) throw UsageError("--rho-bounds needs --gammas");
    slice = remnant::tov::polytrope_slice(get("K", 100), get("gamma", 2), get("ye", 0.5));
  }
  auto check_rho = [&](double rho) {
    if (table) {
      const std::string bad = check_density_in_table(*table, rho);
      if (!bad.empty()) throw RnsError(opt["eos-table"] + ": " + bad);
    }
  };

  if (!opt.count("sequence")) {
    if (opt.count("out")) throw UsageError("--out is for --sequence");
    check_rho(p.rho_central);
    const RotatingStarModel m(*slice, p);
    for (const auto& [name, v] : global_rows(m.globals())) std::printf("%s = %.10g\n", name.c_str(), v);
    return 0;
  }
  // --sequence=WHAT:FROM:TO:N
  const std::string seq = opt["sequence"];
  std::vector<std::string> f;
  for (std::size_t a = 0, b; a <= seq.size(); a = b + 1) {
    b = seq.find(':', a);
    if (b == std::string::npos) b = seq.size();
    f.push_back(seq.substr(a, b - a));
  }
  if (f.size() != 4 || (f[0] != "rho-c" && f[0] != "axis-ratio" && f[0] != "omega"))
    throw UsageError("--sequence=" + seq + ": expected rho-c|axis-ratio|omega:FROM:TO:N");
  const double from = number("sequence", f[1]), to = number("sequence", f[2]);
  const int n = int(number("sequence", f[3]));
  if (n < 1) throw UsageError("--sequence: N must be >= 1");
  if (!opt.count("out")) throw UsageError("--sequence needs --out=FILE.tsv");
  std::ofstream out(opt["out"]);
  if (!out) throw UsageError("--out=" + opt["out"] + ": cannot write");
  bool header = false;
  int failed = 0;
  for (int k = 0; k < n; ++k) {
    const double x = n == 1 ? from : from + (to - from) * k / (n - 1);
    RnsParameters q = p;
    (f[0] == "rho-c" ? q.rho_central : f[0] == "axis-ratio" ? q.axis_ratio : q.omega) = x;
    try {
      check_rho(q.rho_central);
      const RotatingStarModel m(*slice, q);
      const auto rows = global_rows(m.globals());
      if (!header) {
        for (std::size_t c = 0; c < rows.size(); ++c) out << rows[c].first << (c + 1 < rows.size() ? '\t' : '\n');
        header = true;
      }
      out.precision(10);
      for (std::size_t c = 0; c < rows.size(); ++c) out << rows[c].second << (c + 1 < rows.size() ? '\t' : '\n');
      std::printf("%s = %.6g: M_komar = %.6f, axis_ratio = %.4f, Omega_c = %.6f\n", f[0].c_str(), x, m.globals().M_komar,
                  m.globals().axis_ratio, m.globals().omega_c);
    } catch (const RnsError& e) {
      // The sequence ends where the models do (e.g. at mass shedding): report and stop.
      std::fprintf(stderr, "remnant-rotstar: %s = %g: %s; the sequence stops here\n", f[0].c_str(), x, e.what());
      failed = 1;
      break;
    }
  }
  std::printf("wrote %s\n", opt["out"].c_str());
  return failed;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "remnant-rotstar: error: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "remnant-rotstar: error: %s\n", e.what());
    return 1;
  }
}
