#pragma once
// Rotation laws of a stationary axisymmetric star and their Bernoulli integrals:
//   uniform:    Omega = const, ln h + ln alpha - ln W = const;
//   j-constant: u^t u_phi = A^2 (Omega_c - Omega) (Komatsu, Eriguchi & Hachisu 1989),
//               ln h + ln alpha - ln W - A^2 (Omega_c - Omega)^2 / 2 = const.
// With the physical distance from the axis R = psi^2 r sin(theta), the Eulerian velocity is
// v = R (Omega + beta^phi) / alpha and W = 1 / sqrt(1 - v^2).
#include <cmath>
#include <optional>

namespace remnant::rotstar {

enum class RotationLaw { uniform, j_constant };

struct LocalRotation {
  double omega = 0, v = 0, W = 1;
  double bernoulli = 0;  // ln W + the law's term: H = const - ln alpha + bernoulli
};

// A^2 = 0 is uniform rotation. Returns nothing where no subluminal rotation exists (v >= 1).
inline std::optional<LocalRotation> local_rotation(RotationLaw law, double omega_c, double A2, double R, double alpha,
                                                   double beta_phi) {
  LocalRotation out;
  auto velocity = [&](double om) { return R * (om + beta_phi) / alpha; };
  if (law == RotationLaw::uniform || R == 0) {
    out.omega = omega_c;
  } else {
    // F(Omega) = R^2 (Omega + beta) / (alpha^2 - R^2 (Omega + beta)^2) - A^2 (Omega_c - Omega) = 0:
    // F rises monotonically from -inf to +inf between the light surfaces v = -1 and v = 1, so the
    // root is unique (it lies below -beta, counter-rotating with respect to the ZAMOs, where frame
    // dragging exceeds Omega_c's law).
    auto F = [&](double om) {
      const double v = velocity(om);
      return R * R * (om + beta_phi) / (alpha * alpha * (1 - v * v)) - A2 * (omega_c - om);
    };
    double lo = -beta_phi - alpha / R * (1 - 1e-15), hi = -beta_phi + alpha / R * (1 - 1e-15);
    for (int it = 0; it < 200 && hi - lo > 1e-15 * std::abs(hi); ++it) {
      const double mid = 0.5 * (lo + hi);
      (F(mid) > 0 ? hi : lo) = mid;
    }
    out.omega = 0.5 * (lo + hi);
  }
  out.v = velocity(out.omega);
  if (!(std::abs(out.v) < 1)) return std::nullopt;
  out.W = 1 / std::sqrt(1 - out.v * out.v);
  out.bernoulli = std::log(out.W);
  if (law == RotationLaw::j_constant) out.bernoulli += 0.5 * A2 * (omega_c - out.omega) * (omega_c - out.omega);
  return out;
}

}  // namespace remnant::rotstar
