#include "exact_solution.hpp"

#include <cmath>
#include <stdexcept>

namespace remnant::wavetoy {

WaveKind wave_kind(const std::string& name) {
  if (name == "plane_wave") return WaveKind::plane_wave;
  if (name == "standing_wave") return WaveKind::standing_wave;
  if (name == "gaussian") return WaveKind::gaussian;
  throw std::invalid_argument("unknown WaveToy initial data '" + name + "'");
}

double WaveSetup::omega() const { return speed * std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]); }

WaveState exact_solution(const WaveSetup& s, double t, double x, double y, double z) {
  const double w = s.omega();
  if (s.kind == WaveKind::plane_wave) {
    const double phase = s.k[0] * x + s.k[1] * y + s.k[2] * z - w * t;
    return {s.amplitude * std::sin(phase), -s.amplitude * w * std::cos(phase)};
  }
  if (s.kind == WaveKind::standing_wave) {
    // Directions with k = 0 contribute a factor 1 (the wave is constant along them).
    auto factor = [](double k, double x) { return k == 0 ? 1.0 : std::sin(k * x); };
    const double space = factor(s.k[0], x) * factor(s.k[1], y) * factor(s.k[2], z);
    return {s.amplitude * space * std::cos(w * t), -s.amplitude * w * space * std::sin(w * t)};
  }
  const double dx = x - s.center[0], dy = y - s.center[1], dz = z - s.center[2];
  const double r2 = dx * dx + dy * dy + dz * dz;
  return {s.amplitude * std::exp(-r2 / (s.width * s.width)), 0.0};
}

}  // namespace remnant::wavetoy
