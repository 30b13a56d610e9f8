#pragma once
// A bare 3D block with the groups of HydroBase, Spacetime and GRMHD as their thorn.yaml declare
// them, for the bit-for-bit kernel tests and the benchmark's star block (no grid, no exchange).
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "groups.hpp"
#include "mhd_groups.hpp"
#include "remnant/grid.hpp"
#include "remnant/thorn_spec.hpp"

namespace remnant::grmhd::test {

inline VariableRegistry kernel_registry() {
  VariableRegistry vars;
  for (const char* thorn : {"HydroBase", "Spacetime", "GRMHD"}) {
    const std::string path = std::string(REMNANT_SOURCE_DIR) + "/thorns/" + thorn + "/thorn.yaml";
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    for (VariableGroupSpec spec : parse_thorn_spec(text.str(), path).variables) {
      spec.thorn = thorn;
      vars.add(spec);
    }
  }
  return vars;
}

inline Groups hydro_groups(const VariableRegistry& vars) {
  Groups g;
  g.cons = vars.find("HydroBase::cons");
  g.cons_rhs = vars.find("HydroBase::cons_rhs");
  g.prim = vars.find("HydroBase::prim");
  g.metric = vars.find("Spacetime::metric");
  g.flux = {vars.find("GRMHD::flux_x"), vars.find("GRMHD::flux_y"), vars.find("GRMHD::flux_z")};
  return g;
}

inline MhdGroups mhd_groups(const VariableRegistry& vars) {
  MhdGroups g;
  for (int d = 0; d < 3; ++d) {
    const std::string k = std::to_string(d + 1), xyz(1, static_cast<char>('x' + d));
    g.bface[d] = vars.find("HydroBase::Bface" + k);
    g.bface_rhs[d] = vars.find("HydroBase::Bface" + k + "_rhs");
    g.emf[d] = vars.find("GRMHD::emf_" + xyz);
  }
  g.bvec = vars.find("HydroBase::Bvec");
  return g;
}

// An n^3 Cartesian block from the origin with 3 ghosts and cell widths dx (by default different
// along x, y, z).
inline std::unique_ptr<Block> kernel_block(const VariableRegistry& vars, int n,
                                           const std::array<double, 3>& dx = {0.3, 0.25, 0.2}) {
  return std::make_unique<Block>(0, 0, std::array<std::int64_t, 3>{0, 0, 0}, std::array<int, 3>{n, n, n},
                                 std::array<int, 3>{3, 3, 3}, std::array<double, 3>{0.0, 0.0, 0.0}, dx, vars);
}

// Every point (ghosts included) of component c of `group` from value(), in storage order: the
// kernel tests fill blocks with random states this way.
template <class Value>
void fill_component(Block& b, int group, int c, Value value) {
  const std::size_t np = b.points_per_component(group);
  double* p = b.data(group) + static_cast<std::size_t>(c) * np;
  for (std::size_t i = 0; i < np; ++i) p[i] = value();
}

}  // namespace remnant::grmhd::test
