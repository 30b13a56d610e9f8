#pragma once
// Exact solutions of u_tt = c^2 laplacian(u) used for initial data and errors.
#include <array>
#include <string>

namespace remnant::wavetoy {

enum class WaveKind { plane_wave, standing_wave, gaussian };
// Throws std::invalid_argument for a name WaveToy::initial_data does not allow.
WaveKind wave_kind(const std::string& name);

struct WaveSetup {
  WaveKind kind = WaveKind::plane_wave;
  double amplitude = 1;
  std::array<double, 3> k{};       // wave vector (already times 2 pi)
  double speed = 1;
  double width = 0.1;
  std::array<double, 3> center{};
  double omega() const;
};

struct WaveState {
  double u, rho;
};

// The exact solution (plane and standing waves) or the initial pulse (gaussian, t = 0 only).
WaveState exact_solution(const WaveSetup& s, double t, double x, double y, double z);

}  // namespace remnant::wavetoy
