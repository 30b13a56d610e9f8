// remnant-eos: inspect and evaluate tabulated equations of state.
//   remnant-eos info  TABLE [options]                 ranges, bounds and load-time checks
//   remnant-eos eval  TABLE [options] RHO T YE ...    state at (rho [g/cm^3], T [MeV], Ye) triples
//   remnant-eos eval  TABLE [options] --eps RHO EPS YE  T from eps (eps in units of c^2)
//   remnant-eos slice TABLE [options] [--T=MeV] [--n=N] cold beta-equilibrium slice
// Options: --format=auto|stellarcollapse|compose_ascii|compose_hdf5
//          --cs2=from_file|relativistic|newtonian   --mu-e=mu_l_minus_mu_q|mu_l
//          --eps-shift=X (code units)   --code (rho in code units)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "EOS/beta_equilibrium.hpp"
#include "EOS/errors.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "EOS/units.hpp"

namespace {

using namespace remnant::eos;
namespace u = remnant::units;

int usage() {
  std::fprintf(stderr,
               "usage: remnant-eos info|eval|slice TABLE [options] ...\n"
               "  info  TABLE                     ranges, bounds and table checks\n"
               "  eval  TABLE RHO T YE [...]      state at rho [g/cm^3], T [MeV], Ye (triples)\n"
               "  eval  TABLE --eps RHO EPS YE    T and state from eps [c^2]\n"
               "  slice TABLE [--T=MeV] [--n=N]   cold neutrinoless beta-equilibrium slice\n"
               "options: --format=auto|stellarcollapse|compose_ascii|compose_hdf5\n"
               "         --cs2=from_file|relativistic|newtonian  --mu-e=mu_l_minus_mu_q|mu_l\n"
               "         --eps-shift=X (code units)  --code (densities in code units)\n");
  return 2;
}

struct Cli {
  std::string cmd, table;
  ReadOptions read;
  bool code = false, from_eps = false;
  double T_slice = -1;
  int n_slice = 0;
  std::vector<double> numbers;
};

bool starts(const std::string& a, const char* p, std::string& rest) {
  const std::string s(p);
  if (a.rfind(s, 0) != 0) return false;
  rest = a.substr(s.size());
  return true;
}

// A finite number: NaN and inf are refused (they would be evaluated at the table's edge).
double number(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end) throw EosError("not a number: '" + s + "'");
  if (!std::isfinite(v)) throw EosError("'" + s + "' is not a finite number");
  return v;
}

Cli parse(int argc, char** argv) {
  Cli c;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    std::string v;
    if (starts(a, "--format=", v)) {
      c.read.format = v == "stellarcollapse" ? TableFormat::stellarcollapse
                      : v == "compose_ascii" ? TableFormat::compose_ascii
                      : v == "compose_hdf5"  ? TableFormat::compose_hdf5
                      : v == "auto"          ? TableFormat::automatic
                                             : throw EosError("unknown --format " + v);
    } else if (starts(a, "--cs2=", v)) {
      c.read.sc_cs2 = v == "relativistic" ? Cs2Convention::relativistic
                      : v == "newtonian"  ? Cs2Convention::newtonian
                      : v == "from_file"  ? Cs2Convention::from_file
                                          : throw EosError("unknown --cs2 " + v);
    } else if (starts(a, "--mu-e=", v)) {
      c.read.compose_mu_e = v == "mu_l" ? ComposeElectronMu::mu_l
                            : v == "mu_l_minus_mu_q" ? ComposeElectronMu::mu_l_minus_mu_q
                                                     : throw EosError("unknown --mu-e " + v);
    } else if (starts(a, "--eps-shift=", v)) {
      c.read.eps_shift = number(v);
    } else if (starts(a, "--T=", v)) {
      c.T_slice = number(v);
      if (!(c.T_slice > 0)) throw EosError("--T=" + v + ": allowed T > 0 MeV");
    } else if (starts(a, "--n=", v)) {
      const double n = number(v);
      if (n != std::floor(n) || n < 2 || n > 1e7) throw EosError("--n=" + v + ": allowed integers 2 .. 1e7");
      c.n_slice = int(n);
    } else if (a == "--code") {
      c.code = true;
    } else if (a == "--eps") {
      c.from_eps = true;
    } else if (a.size() > 1 && a[0] == '-' && !(std::isdigit(a[1]) || a[1] == '.')) {
      throw EosError("unknown option " + a);
    } else if (c.cmd.empty()) {
      c.cmd = a;
    } else if (c.table.empty()) {
      c.table = a;
    } else {
      c.numbers.push_back(number(a));
    }
  }
  return c;
}

void info(const Tabulated<>& eos) {
  const TableData& t = eos.table();
  const Bounds& b = t.bounds;
  std::printf("file        %s\nformat      %s\n", t.file.c_str(), t.format.c_str());
  std::printf("grid        %d rho x %d T x %d Ye (%zu points, %zu bytes thermo)\n", t.lrho.n, t.lT.n, t.ye.n,
              t.points(), t.thermo.size() * sizeof(double));
  std::printf("rho         %.6e .. %.6e g/cm^3  (%.6e .. %.6e code), dlog10 = %.6g\n",
              b.rho_min / u::rho_cgs_to_code, b.rho_max / u::rho_cgs_to_code, b.rho_min, b.rho_max,
              t.lrho.dx / std::log(10.0));
  std::printf("T           %.6e .. %.6e MeV, dlog10 = %.6g\n", b.T_min, b.T_max, t.lT.dx / std::log(10.0));
  std::printf("Ye          %.6g .. %.6g, dYe = %.6g\n", b.ye_min, b.ye_max, t.ye.dx);
  std::printf("eps         %.6e .. %.6e (c^2), energy shift %.6e\n", b.eps_min, b.eps_max, t.eps_shift);
  std::printf("p           %.6e .. %.6e (code)%s\n", b.press_min, b.press_max,
              t.p_shift > 0 ? " (log interpolation with a shift)" : "");
  std::printf("h           min %.12g (lower bound of the interpolant), max %.6e\n", b.h_min, b.h_max);
  std::printf("chemical potentials %s, composition %s\n", t.has_chem ? "yes" : "no", t.has_compo ? "yes" : "no");
  std::printf("checks      %zu warning(s)\n%s", t.report.warnings(), t.report.str().c_str());
}

void print_state(const Tabulated<>& eos, double rho, double T, double ye) {
  const Thermo th = eos.thermo(rho, T, ye);
  std::printf("rho = %.9e g/cm^3 (%.9e code)  T = %.9g MeV  Ye = %.6g\n", rho / u::rho_cgs_to_code, rho, T, ye);
  std::printf("  p    = %.12e code = %.9e dyn/cm^2\n", th.press, th.press / u::press_cgs_to_code);
  std::printf("  eps  = %.12e c^2\n  cs2  = %.12e c^2\n  h    = %.15g\n  s    = %.9g kB/baryon\n", th.eps, th.cs2,
              th.h, th.entropy);
  if (eos.has_chemical_potentials()) {
    const ChemPot m = eos.chem(rho, T, ye);
    std::printf("  mu_e = %.9g  mu_p = %.9g  mu_n = %.9g  mu_e+mu_p-mu_n = %.9g MeV\n", m.mu_e, m.mu_p, m.mu_n,
                m.mu_nu());
  }
  if (eos.has_composition()) {
    const Composition c = eos.composition(rho, T, ye);
    std::printf("  Xa = %.6g Xh = %.6g Xn = %.6g Xp = %.6g Abar = %.6g Zbar = %.6g\n", c.Xa, c.Xh, c.Xn, c.Xp,
                c.Abar, c.Zbar);
  }
  const Bounds& b = eos.bounds();
  const double r = 1e-12;  // axis end values carry rounding from the file
  if (rho < b.rho_min * (1 - r) || rho > b.rho_max * (1 + r) || T < b.T_min * (1 - r) || T > b.T_max * (1 + r) ||
      ye < b.ye_min - r || ye > b.ye_max + r)
    std::printf("  note: outside the table; evaluated at the nearest edge\n");
}

int run(const Cli& c) {
  Tabulated<> eos(load_table(c.table, c.read));
  const double to_code = c.code ? 1.0 : u::rho_cgs_to_code;
  if (c.cmd == "info") {
    info(eos);
  } else if (c.cmd == "eval") {
    if (c.numbers.empty() || c.numbers.size() % 3) throw EosError("eval needs RHO T YE triples");
    for (std::size_t i = 0; i < c.numbers.size(); i += 3) {
      const std::string which = "triple " + std::to_string(i / 3 + 1) + ": ";
      if (!(c.numbers[i] > 0)) throw EosError(which + "RHO must be > 0, got " + std::to_string(c.numbers[i]));
      if (!c.from_eps && !(c.numbers[i + 1] > 0))
        throw EosError(which + "T must be > 0 MeV, got " + std::to_string(c.numbers[i + 1]));
      if (!(c.numbers[i + 2] >= 0 && c.numbers[i + 2] <= 1))
        throw EosError(which + "YE must lie in [0, 1], got " + std::to_string(c.numbers[i + 2]));
      const double rho = c.numbers[i] * to_code, ye = c.numbers[i + 2];
      double T = c.numbers[i + 1];
      if (c.from_eps) {
        const Inversion inv = eos.temperature(rho, c.numbers[i + 1], ye);
        std::printf("eps = %.12e -> T = %.12g MeV (flags 0x%x%s%s)\n", c.numbers[i + 1], inv.T, inv.flags,
                    inv.flags & kInvBelowEpsLow ? ", rule 8: eps raised to eps(T_min)" : "",
                    inv.flags & kInvAboveEpsHigh ? ", rule 9: eps lowered to eps(T_max)" : "");
        T = inv.T;
      }
      print_state(eos, rho, T, ye);
    }
  } else if (c.cmd == "slice") {
    const double T = c.T_slice > 0 ? c.T_slice : eos.bounds().T_min;
    std::vector<double> rhos;
    if (c.n_slice > 1) {
      const Bounds& b = eos.bounds();
      for (int i = 0; i < c.n_slice; ++i)
        rhos.push_back(std::min(b.rho_max, b.rho_min * std::pow(b.rho_max / b.rho_min, double(i) / (c.n_slice - 1))));
    } else {
      const Axis& a = eos.table().lrho;
      for (int i = 0; i < a.n; ++i) rhos.push_back(std::exp(a.node(i)));
    }
    const BetaSlice s = beta_equilibrium_slice(eos, T, rhos);
    std::printf("# cold neutrinoless beta-equilibrium slice at T = %g MeV of %s\n", T, c.table.c_str());
    std::printf("# rho[g/cm^3] Ye p[dyn/cm^2] eps[c^2] cs2[c^2] bracketed\n");
    for (std::size_t i = 0; i < s.rho.size(); ++i)
      std::printf("%.9e %.9f %.9e %.9e %.9e %d\n", s.rho[i] / u::rho_cgs_to_code, s.ye[i],
                  s.press[i] / u::press_cgs_to_code, s.eps[i], s.cs2[i], int(s.bracketed[i]));
  } else {
    return usage();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Cli c = parse(argc, argv);
    if (c.cmd.empty() || c.table.empty()) return usage();
    return run(c);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "remnant-eos: error: %s\n", e.what());
    return 1;
  }
}
