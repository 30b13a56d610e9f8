#pragma once
// Plain value types shared by every EOS: state outputs, bounds, inversion status.
#include <cstdint>
#include <limits>

namespace remnant::eos {

// Thermodynamic state in code units (T in MeV). h = 1 + eps + p/rho. entropy (kB per baryon) is
// filled by tabulated EOSs; analytic ones leave it 0 (it costs a log and a pow per call, and the
// evolution never reads it; IdealGas::entropy_index gives the ideal gas's).
struct Thermo {
  double press = 0, eps = 0, cs2 = 0, h = 1, entropy = 0;
};
struct PressCs2 {
  double press = 0, cs2 = 0;
  bool acausal = false;  // Tabulated::acausal(rho, ye) of the same point, from the same indices
};

// Chemical potentials in MeV, each including its particle's rest mass relative to m_n
// (StellarCollapse convention): neutrinoless beta equilibrium is mu_e + mu_p - mu_n = 0.
struct ChemPot {
  double mu_e = 0, mu_p = 0, mu_n = 0;
  double mu_nu() const { return mu_e + mu_p - mu_n; }
};

// Mass fractions of alphas, heavy nuclei, free neutrons and protons; heavy-nucleus A and Z.
struct Composition {
  double Xa = 0, Xh = 0, Xn = 0, Xp = 0, Abar = 0, Zbar = 0;
};

// The bounds that the atmosphere and the primitive recovery need (paper: rho, eps, T, Ye, h
// min/max). For tables they come from the grid; h_min is a strict lower bound of the interpolant.
struct Bounds {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  double rho_min = 0, rho_max = inf;
  double T_min = 0, T_max = inf;
  double ye_min = 0, ye_max = 1;
  double eps_min = -inf, eps_max = inf;
  double h_min = 1, h_max = inf;
  double press_min = 0, press_max = inf;
};

// Outcome flags of an eps -> T inversion (bit set). Rules 8 and 9 of the paper's error policy.
enum InversionFlag : std::uint32_t {
  kInvOk = 0,
  kInvBelowEpsLow = 1u << 0,   // rule 8: eps <= eps(rho, T_min, Ye): set T = T_min, eps = eps_low
  kInvAboveEpsHigh = 1u << 1,  // rule 9: eps >= eps(rho, T_max, Ye): set T = T_max, eps = eps_high
  kInvMaxIter = 1u << 2,       // the 50-iteration fallback was taken
  kInvRhoClamped = 1u << 3,    // rho outside the table: evaluated at the nearest edge
  kInvYeClamped = 1u << 4,     // Ye outside the table: evaluated at the nearest edge
};

struct Inversion {
  double T = 0;          // recovered temperature (MeV)
  double eps = 0;        // eps actually used (differs from the input under rules 8/9)
  std::uint32_t flags = kInvOk;
  int iterations = 0;
};

enum class InversionMethod { brent, exact };

}  // namespace remnant::eos
