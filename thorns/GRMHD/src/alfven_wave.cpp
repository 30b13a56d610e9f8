#include "alfven_wave.hpp"

#include <cmath>
#include <numbers>

#include "EOS/eos.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "groups.hpp"
#include "interior_faces.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/error.hpp"

namespace remnant::grmhd {

double AlfvenWave::speed() const {
  const double h = 1 + gamma / (gamma - 1) * press / rho;
  const double w = rho * h + B0 * B0 * (1 + eta * eta);
  const double q = 2 * eta * B0 * B0 / w;
  return std::sqrt(B0 * B0 / w / (0.5 * (1 + std::sqrt(1 - q * q))));
}

std::array<double, 3> AlfvenWave::field(double x, double t) const {
  const double ph = 2 * std::numbers::pi / length * (x - x0 - speed() * t);
  return {B0, eta * B0 * std::cos(ph), eta * B0 * std::sin(ph)};
}

std::array<double, 3> AlfvenWave::velocity(double x, double t) const {
  const auto B = field(x, t);
  const double va = speed();
  return {0.0, -va * B[1] / B0, -va * B[2] / B0};
}

std::array<double, 3> AlfvenWave::field_average(double xl, double xr, double t) const {
  const double k = 2 * std::numbers::pi / length, s = speed() * t;
  const double pl = k * (xl - x0 - s), pr = k * (xr - x0 - s), w = eta * B0 / (pr - pl);
  return {B0, w * (std::sin(pr) - std::sin(pl)), -w * (std::cos(pr) - std::cos(pl))};
}

AlfvenWave alfven_wave_from(const Context& ctx) {
  const auto& eos = ctx.service<eos::EOS>("eos");
  const auto* ideal = std::get_if<eos::IdealGas<>>(&eos.variant());
  if (!ideal) throw RunError("GRMHD::initial_data = alfven_wave needs EOS::type = ideal_gas");
  const auto& p = ctx.param<std::vector<double>>("GRMHD", "alfven_wave");
  AlfvenWave w;
  w.rho = p[0];
  w.press = p[1];
  w.B0 = p[2];
  w.eta = p[3];
  w.gamma = ideal->gamma();
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  w.x0 = lo[0];
  w.length = hi[0] - lo[0];
  return w;
}

void alfven_wave_initial_data(Context& ctx) {
  const AlfvenWave w = alfven_wave_from(ctx);
  const double ye = ctx.param<double>("GRMHD", "initial_ye");
  for (Block* b : ctx.grid().local_blocks()) {
    const Prim prim(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      const auto v = w.velocity(b->x(0, i), 0.0);
      prim.rho(i, j, k) = w.rho;
      for (int c = 0; c < 3; ++c) prim.vel(c, i, j, k) = v[c];
      prim.press(i, j, k) = w.press;
      prim.eps(i, j, k) = w.press / ((w.gamma - 1) * w.rho);
      prim.Ye(i, j, k) = ye;
      prim.temperature(i, j, k) = 0;
      prim.W(i, j, k) = 1.0 / std::sqrt(1.0 - (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
      prim.cs2(i, j, k) = 0;
    });
  }
}

void alfven_wave_field(Context& ctx) {
  if (ctx.grid().coordinates() != CoordinateSystem::cartesian)
    throw InputError(ctx.params().origin("GRMHD", "initial_data"), "GRMHD::initial_data = alfven_wave needs Grid::coordinates = cartesian");
  const AlfvenWave w = alfven_wave_from(ctx);
  const hydrobase::FieldGroups g = hydrobase::FieldGroups::of(ctx);
  for (Block* b : ctx.grid().local_blocks()) {
    // x faces: B^1 = B0; y, z faces: the exact average over the cell's x extent (uniform in y, z).
    for (int a = 0; a < 3; ++a) {
      const Field f = b->field(g.bface[a], 0);
      for_interior_faces(*b, a, [&](int i, int j, int k) {
        f(i, j, k) = a == 0 ? w.B0 : w.field_average(b->face_coordinate(0, i), b->face_coordinate(0, i + 1), 0.0)[a];
      });
    }
  }
}

}  // namespace remnant::grmhd
