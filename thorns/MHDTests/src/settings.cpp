#include "settings.hpp"

#include <vector>

#include "remnant/error.hpp"

namespace remnant::mhd_tests {

Settings settings_from(const Context& ctx) {
  auto real = [&](const char* n) { return ctx.param<double>("MHDTests", n); };
  auto pair = [&](const char* n) {
    const auto& v = ctx.param<std::vector<double>>("MHDTests", n);
    return std::array<double, 2>{v[0], v[1]};
  };
  const std::string& name = ctx.param<std::string>("MHDTests", "problem");
  if (name == "none")
    throw InputError(ctx.params().origin("MHDTests", "problem"),
                     "MHDTests is active but MHDTests::problem is none; choose one of balsara1, balsara2, balsara3, "
                     "balsara4, balsara5, field_loop, cylindrical_blast, rotor");
  Settings s;
  s.problem = problem_from_name(name);
  s.discontinuity = real("discontinuity_position");
  s.ye = real("ye");
  s.loop.profile = ctx.param<std::string>("MHDTests", "field_loop_profile") == "smooth"
                       ? FieldLoopParams::Profile::smooth
                       : FieldLoopParams::Profile::beckwith_stone;
  s.loop.amplitude = real("field_loop_amplitude");
  s.loop.radius = real("field_loop_radius");
  s.loop.centre = pair("field_loop_centre");
  s.loop.velocity = pair("field_loop_velocity");
  s.loop.press = real("field_loop_pressure");
  const auto& lo = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto& hi = ctx.param<std::vector<double>>("Grid", "xmax");
  s.loop.period = {hi[0] - lo[0], hi[1] - lo[1]};
  s.blast.B0 = real("blast_B0");
  s.rotor.omega = real("rotor_omega");
  s.rotor.B0 = real("rotor_B0");
  return s;
}

FluidState state_at(const Settings& s, double x, double y) {
  switch (s.problem) {
    case Problem::field_loop: return field_loop_state(s.loop);
    case Problem::cylindrical_blast: return blast_state(s.blast, x, y);
    case Problem::rotor: return rotor_state(s.rotor, x, y);
    default: {
      const RiemannProblem rp = riemann_problem(s.problem);
      return x < s.discontinuity ? rp.left : rp.right;
    }
  }
}

}  // namespace remnant::mhd_tests
