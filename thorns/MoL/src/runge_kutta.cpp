#include "runge_kutta.hpp"

#include <stdexcept>

namespace remnant::mol {

const std::vector<RungeKuttaStage>& runge_kutta_stages(const std::string& method) {
  static const std::vector<RungeKuttaStage> rk3 = {{0.0, 1.0, 0.0}, {0.75, 0.25, 1.0}, {1.0 / 3.0, 2.0 / 3.0, 0.5}};
  static const std::vector<RungeKuttaStage> rk2 = {{0.0, 1.0, 0.0}, {0.5, 0.5, 1.0}};
  static const std::vector<RungeKuttaStage> euler = {{0.0, 1.0, 0.0}};
  if (method == "rk3") return rk3;
  if (method == "rk2") return rk2;
  if (method == "euler") return euler;
  throw std::invalid_argument("unknown Runge-Kutta method '" + method + "'");
}

double time_after_stage(const std::vector<RungeKuttaStage>& stages, std::size_t s) {
  // The new state a u0 + b (u + dt L) sits at a*0 + b*(c_s + 1).
  return stages[s].b * (stages[s].c + 1.0);
}

}  // namespace remnant::mol
