// remnant-handoff-testdata: writes the BU0 TOV star (K = 100, Gamma = 2, rho_c = 1.28e-3) as 3D
// Einstein Toolkit CarpetIOHDF5 data (octant, two refinement levels of spacing 1 and 0.5, two
// components each with ghost and buffer zones, two files), the input of
// parfiles/handoff_tov_cyl_2d.yaml when no real Carpet run is at hand:
//   build/bin/remnant-handoff-testdata --out=handoff_data [--omega=0.01]   (omega: rigid rotation, bitant)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "../test/synthetic_carpet.hpp"
#include "TOV/tov_solver.hpp"

int main(int argc, char** argv) {
  std::string out = "handoff_data";
  double omega = 0;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--out=", 6) == 0) out = argv[i] + 6;
    else if (std::strncmp(argv[i], "--omega=", 8) == 0) omega = std::atof(argv[i] + 8);
    else {
      std::fprintf(stderr, "remnant-handoff-testdata: unknown option '%s'; usage: --out=DIR [--omega=W]\n", argv[i]);
      return 1;
    }
  }
  using namespace remnant;
  const auto slice = tov::polytrope_slice(100.0, 2.0, 0.5);
  const tov::TovStar star(*slice, 1.28e-3);
  handoff::synthetic::SyntheticCarpet spec;
  spec.variables = {"HYDROBASE::rho", "HYDROBASE::press", "HYDROBASE::eps", "HYDROBASE::vel[0]", "HYDROBASE::vel[1]",
                    "HYDROBASE::vel[2]", "ADMBASE::alp", "ADMBASE::gxx", "ADMBASE::gxy", "ADMBASE::gxz",
                    "ADMBASE::gyy", "ADMBASE::gyz", "ADMBASE::gzz"};
  spec.levels = {{1.0, {0.5, 0.5, 0.5}, {16, 16, 16}, 0}, {0.5, {0, 0, 0}, {21, 21, 21}, 1}};
  if (omega != 0) {
    spec.reflection = {false, false, true};
    spec.levels = {{1.0, {-15.5, -15.5, 0.5}, {32, 32, 16}, 0}, {0.5, {-10, -10, 0}, {41, 41, 21}, 1}};
  }
  spec.iterations = {1024};
  spec.stem = "tov3d";
  std::filesystem::create_directories(out);
  const auto files = handoff::synthetic::write_synthetic_carpet(out, spec, [&](const std::string& v, int, double x, double y, double z) {
    const tov::TovPoint p = star.at(std::sqrt(x * x + y * y + z * z));
    if (v == "HYDROBASE::rho") return p.rho;
    if (v == "HYDROBASE::press") return p.press;
    if (v == "HYDROBASE::eps") return p.eps;
    if (v == "HYDROBASE::vel[0]") return p.rho > 0 ? -omega * y : 0.0;
    if (v == "HYDROBASE::vel[1]") return p.rho > 0 ? omega * x : 0.0;
    if (v == "ADMBASE::alp") return p.alpha;
    if (v == "ADMBASE::gxx" || v == "ADMBASE::gyy" || v == "ADMBASE::gzz") return std::pow(p.psi, 4);
    return 0.0;
  });
  for (const auto& f : files) std::printf("%s\n", f.c_str());
  std::printf("BU0: M = %.6f, M0 = %.6f, isotropic R = %.5f; buffer zones: 2 (HandOff::buffer_zones=2)\n",
              star.gravitational_mass(), star.rest_mass(), star.isotropic_radius());
  return 0;
}
