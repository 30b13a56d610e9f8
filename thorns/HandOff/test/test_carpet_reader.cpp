// The Carpet reader on files written by a small Carpet-layout writer (synthetic_carpet.hpp): two
// refinement levels, two components per level with ghost zones (NaN) and refined-level buffer
// zones (wrong values), an octant (ReflectionSymmetry in x, y, z, read from the files' parameter
// dump), several files. The unfolded data must reproduce the analytic fields exactly at every
// point, take the finest level wherever it has data, never read a ghost or buffer point, and
// interpolate cubic polynomials exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>
#include <unistd.h>

#include "HandOff/carpet_reader.hpp"
#include "HandOff/sampler.hpp"
#include "remnant/error.hpp"
#include "synthetic_carpet.hpp"

namespace {

using namespace remnant;
using namespace remnant::handoff;

constexpr double kCoarseOffset = 1e-3;  // level 0 holds f + this: shows which level was used

// Even in x, y, z (a scalar of an octant); monotone in |x|, |y|, |z|; cubic in each direction.
double scalar(double x, double y, double z) { return 2 + x * x + 0.5 * y * y + 0.3 * z * z + 0.05 * x * x * y * y; }
// Odd in z, even in x and y: the z component of a vector.
double vz(double x, double y, double z) { return z * (1 + 0.1 * x * x + 0.05 * y * y); }
// Odd in x and z: g_xz.
double gxz(double x, double y, double z) { return 0.01 * x * z * (1 + 0.1 * y * y); }

// Level 0 holds f + kCoarseOffset * (1, z, x z) for (rho, vel[2], gxz): smooth, of the same parity,
// and visible, so that a test sees which level a value came from.
double analytic(const std::string& v, int level, double x, double y, double z) {
  const double off = level == 0 ? kCoarseOffset : 0.0;
  if (v == "HYDROBASE::rho" || v == "rho") return scalar(x, y, z) + off;
  if (v == "HYDROBASE::vel[2]" || v == "vel[2]") return vz(x, y, z) + off * z;
  if (v == "ADMBASE::gxz" || v == "gxz") return gxz(x, y, z) + off * x * z;
  return 0;
}

struct Files {
  std::filesystem::path dir;
  std::vector<std::string> paths;
  synthetic::SyntheticCarpet spec;
  explicit Files(const std::function<void(synthetic::SyntheticCarpet&)>& adjust = {}) {
    dir = std::filesystem::temp_directory_path() / ("handoff_carpet_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    spec.variables = {"HYDROBASE::rho", "HYDROBASE::vel[2]", "ADMBASE::gxz"};
    // Level 0: avoid-origin nodes 0.25 + 0.5 m (16 per direction); level 1 (vertex-centred
    // refinement): 0.25 m, a node on each plane (15 per direction).
    spec.levels = {{0.5, {0.25, 0.25, 0.25}, {16, 16, 16}, 0}, {0.25, {0, 0, 0}, {15, 15, 15}, 1}};
    spec.iterations = {0, 256};
    spec.iterations_of["ADMBASE::gxz"] = {0, 256, 512};
    spec.extra_iterations_of_level[1] = {384};  // the finer level alone (Carpet's intermediate steps)
    if (adjust) adjust(spec);
    paths = synthetic::write_synthetic_carpet(dir.string(), spec, analytic);
  }
  ~Files() { std::filesystem::remove_all(dir); }
  CarpetOptions options() const {
    CarpetOptions o;
    o.files = paths;
    o.variables = {"rho", "vel[2]", "gxz"};
    o.required = {"rho"};
    o.buffer_zones = spec.buffer;
    return o;
  }
};

TEST(CarpetReader, CanonicalNames) {
  EXPECT_EQ(canonical_carpet_name("HYDROBASE::rho"), "rho");
  EXPECT_EQ(canonical_carpet_name("HydroBase::vel[1]"), "vel[1]");
  EXPECT_EQ(canonical_carpet_name("HYDROBASE::Y_e"), "Ye");
  EXPECT_EQ(canonical_carpet_name("HYDROBASE::Bvec[2]"), "Bvec[2]");
  EXPECT_EQ(canonical_carpet_name("ADMBASE::gxy"), "gxy");
  EXPECT_EQ(canonical_carpet_name("ADMBASE::kxx"), "");
  EXPECT_EQ(reflection_parity("gxz", 0), -1.0);
  EXPECT_EQ(reflection_parity("gxz", 1), 1.0);
  EXPECT_EQ(reflection_parity("betay", 1), -1.0);
  EXPECT_EQ(reflection_parity("vel[2]", 2), -1.0);
  EXPECT_EQ(reflection_parity("rho", 2), 1.0);
  EXPECT_EQ(reflection_parity("Bvec[2]", 2), -1.0);  // HandOff::magnetic_parity = vector: as vel
  EXPECT_EQ(reflection_parity("Bvec[0]", 2), 1.0);
  EXPECT_EQ(reflection_parity("Bvec[2]", 2, true), 1.0);  // the Einstein Toolkit's Bvec (pseudo-vector): normal even
  EXPECT_EQ(reflection_parity("Bvec[0]", 2, true), -1.0);
  EXPECT_EQ(reflection_parity("vel[2]", 2, true), -1.0);
}

void expect_exact_octant(const Files& files, int buffer_zones = -1) {
  CarpetOptions o = files.options();
  if (buffer_zones >= 0) o.buffer_zones = buffer_zones;
  const SourceData src = read_carpet(o);
  ASSERT_EQ(src.levels.size(), 2u);
  EXPECT_EQ(src.iteration, 256);  // the latest that rho, vel[2] and gxz all have on every level (not 384)
  EXPECT_TRUE(src.reflection[0] && src.reflection[1] && src.reflection[2]);
  std::size_t checked = 0, negative = 0;
  for (const auto& L : src.levels) {
    // The unfolded level spans -last .. last in each direction, every point valid.
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(L.x(d, 0), -L.x(d, L.n[d] - 1), 1e-12);
    for (int k = 0; k < L.n[2]; ++k)
      for (int j = 0; j < L.n[1]; ++j)
        for (int i = 0; i < L.n[0]; ++i) {
          ASSERT_TRUE(L.is_valid(i, j, k)) << "level " << L.level << " point " << i << "," << j << "," << k;
          const double x = L.x(0, i), y = L.x(1, j), z = L.x(2, k);
          const std::size_t q = L.index(i, j, k);
          // Exactly the written values (mirror images carry the parity's sign exactly).
          for (const char* v : {"rho", "vel[2]", "gxz"}) EXPECT_EQ(L.fields.at(v)[q], analytic(v, L.level, x, y, z)) << v << " level " << L.level << " at " << x << ", " << y << ", " << z;
          ++checked;
          negative += (x < 0 || y < 0 || z < 0);
        }
  }
  EXPECT_EQ(checked, 8u * 16 * 16 * 16 + 29u * 29 * 29);
  EXPECT_GT(negative, 0u);
}

TEST(CarpetReader, OctantTwoLevelsExactAtEveryPoint) { expect_exact_octant(Files()); }

// CarpetIOHDF5::output_ghost_points = "no" (in a byte-array parameter dump): no ghost points in the
// files, nothing but the refined levels' buffer zones to remove.
TEST(CarpetReader, WithoutGhostPointsInTheFiles) {
  expect_exact_octant(Files([](synthetic::SyntheticCarpet& s) {
    s.ghosts_written = false;
    s.parameters_as_bytes = true;
  }));
}

// One run often writes both CarpetIOHDF5 outputs: the 3D slices (out3D_vars, "<var>.xyz.file_N.h5")
// without ghosts (out3D_ghosts = "no", as in the Einstein Toolkit's TOV test run read for the
// README) and the volume output (out_vars, "<var>.file_N.h5") with them (output_ghost_points at
// its default). The volume files keep their ghost points (read as data before: NaN).
TEST(CarpetReader, VolumeOutputKeepsGhostsWhenOnly3DSlicesDropThem) {
  expect_exact_octant(Files([](synthetic::SyntheticCarpet& s) { s.extra_parameters = "CarpetIOHDF5::out3D_ghosts = \"no\"\n"; }));
}

// The 3D slice output follows out3D_ghosts (and not output_ghost_points).
TEST(CarpetReader, SliceOutputWithoutGhostPoints) {
  expect_exact_octant(Files([](synthetic::SyntheticCarpet& s) {
    s.stem = "data.xyz";
    s.ghosts_written = false;
    s.ghosts_parameter = "out3D_ghosts";
    s.extra_parameters = "CarpetIOHDF5::output_ghost_points = \"yes\"\n";
  }));
}

// Carpet's `active` attribute (CarpetIOHDF5 writes it since 2010; the kuibit TOV run and the aurel
// fixtures have it) marks each component's own points: without ghosts, outer and symmetry boundary
// points and Carpet's buffer zones (use_buffer_zones: 9 points per refined face in the kuibit run,
// read as data with HandOff::buffer_zones = 0). Read with HandOff::buffer_zones = 0 the data must be
// exact: the buffer points (value + 0.5) never read, with and without ghost points in the files.
TEST(CarpetReader, ActiveRegionsDropBufferZones) {
  expect_exact_octant(Files([](synthetic::SyntheticCarpet& s) { s.write_active = true; }), 0);
  expect_exact_octant(Files([](synthetic::SyntheticCarpet& s) {
    s.write_active = true;
    s.ghosts_written = false;
    s.stem = "data.xyz";
    s.ghosts_parameter = "out3D_ghosts";
  }), 0);
}

// Files without cctk_bbox: the outer boundary is the coarsest level's edge.
TEST(CarpetReader, WithoutBoundingBoxAttribute) {
  expect_exact_octant(Files([](synthetic::SyntheticCarpet& s) { s.write_bbox = false; }));
}

TEST(CarpetReader, SamplerFinestLevelExactAtPointsCubicBetween) {
  const Files files;
  const SourceData src = read_carpet(files.options());
  const Sampler s(src, {"rho", "vel[2]"});
  double out[2];
  int level = -1;
  // At points of level 1 (inside it): level 1's value, exactly.
  ASSERT_TRUE(s.sample({0.25 + 5 * 0.25, -(0.25 + 3 * 0.25), 0.25 + 0 * 0.25}, out, &level));
  EXPECT_EQ(level, 1);
  EXPECT_EQ(out[0], analytic("rho", 1, 1.5, -1.0, 0.25));
  // Beyond level 1: level 0's value exactly at its points.
  ASSERT_TRUE(s.sample({0.25 + 12 * 0.5, 0.25, -0.75}, out, &level));
  EXPECT_EQ(level, 0);
  EXPECT_EQ(out[0], analytic("rho", 0, 6.25, 0.25, -0.75));
  EXPECT_EQ(out[1], analytic("vel[2]", 0, 6.25, 0.25, -0.75));
  // Random points: cubic polynomials are reproduced to round-off (the limiter stays off where the
  // field is monotone); inside level 1 its data are used, the coarse offset never appears there.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-6.7, 6.7);  // level 0's cubic stencils reach 6.75
  int fine = 0, coarse = 0;
  for (int n = 0; n < 2000; ++n) {
    const double x = u(gen), y = u(gen), z = u(gen);
    if (std::abs(x) < 0.5 || std::abs(y) < 0.5) continue;  // the limiter acts at the even fields' minimum
    ASSERT_TRUE(s.sample({x, y, z}, out, &level)) << x << " " << y << " " << z;
    const double reach = std::max({std::abs(x), std::abs(y), std::abs(z)});
    if (level == 1 && reach > 3.0) continue;  // level 1's last cell: its trilinear value (finest data first)
    if (std::abs(z) >= 0.5) EXPECT_NEAR(out[0], analytic("rho", level, x, y, z), 1e-12) << x << " " << y << " " << z << " level " << level;
    EXPECT_NEAR(out[1], analytic("vel[2]", level, x, y, z), 1e-12) << x << " " << y << " " << z << " level " << level;
    const bool inside_fine = std::abs(x) < 3.5 - 2 * 0.25 && std::abs(y) < 3.5 - 2 * 0.25 && std::abs(z) < 3.5 - 2 * 0.25;
    if (inside_fine) EXPECT_EQ(level, 1) << x << " " << y << " " << z;
    (level == 1 ? fine : coarse)++;
  }
  EXPECT_GT(fine, 50);
  EXPECT_GT(coarse, 50);
  // Outside the data: no value.
  EXPECT_FALSE(s.sample({9.0, 0, 0}, out));
}

TEST(CarpetReader, LimiterAtAJump) {
  // A step in rho across x = 3 (a star's surface): the interpolant stays within the neighbours.
  synthetic::SyntheticCarpet spec;
  spec.variables = {"HYDROBASE::rho"};
  spec.levels = {{0.5, {0.25, 0.25, 0.25}, {16, 16, 16}, 0}};
  const auto dir = std::filesystem::temp_directory_path() / ("handoff_jump_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  CarpetOptions o;
  o.files = synthetic::write_synthetic_carpet(dir.string(), spec, [](const std::string&, int, double x, double, double) {
    return x < 3 ? 1.0 : 1e-6;
  });
  o.variables = {"rho"};
  const SourceData src = read_carpet(o);
  std::filesystem::remove_all(dir);
  const Sampler s(src, {"rho"});
  for (double x = 1.0; x < 5.0; x += 0.01) {
    double v = 0;
    ASSERT_TRUE(s.sample({x, 1.1, 2.2}, &v));
    EXPECT_GE(v, 1e-6 - 1e-15) << x;
    EXPECT_LE(v, 1.0 + 1e-15) << x;
  }
}

TEST(CarpetReader, LimiterKeepsASmoothMaximumBetweenThePoints) {
  // A smooth maximum (a star's centre) between the points of a cell-centred grid: the cubic value
  // exceeds the 8 nearest points and is kept (clipped to their range it fell short by 3 a h^2 / 4);
  // a positive field stays positive at a kink to zero (a star's surface).
  synthetic::SyntheticCarpet spec;
  spec.variables = {"HYDROBASE::rho"};
  spec.reflection = {false, false, false};
  spec.levels = {{0.5, {-3.75, -3.75, -3.75}, {16, 16, 16}, 0}};
  const auto dir = std::filesystem::temp_directory_path() / ("handoff_max_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  CarpetOptions o;
  auto rho = [](double x, double y, double z) { return std::max(1.0 - 0.05 * (x * x + y * y + z * z), 0.0); };
  o.files = synthetic::write_synthetic_carpet(dir.string(), spec, [&](const std::string&, int, double x, double y, double z) {
    return rho(x, y, z);
  });
  o.variables = {"rho"};
  o.reflection_from_file = false;
  const SourceData src = read_carpet(o);
  std::filesystem::remove_all(dir);
  const Sampler s(src, {"rho"});
  double v = 0;
  ASSERT_TRUE(s.sample({0.0, 0.0, 0.0}, &v));
  EXPECT_NEAR(v, 1.0, 1e-12);  // the quadratic is reproduced by the cubic
  ASSERT_TRUE(s.sample({0.1, -0.05, 0.02}, &v));
  EXPECT_NEAR(v, rho(0.1, -0.05, 0.02), 1e-12);
  for (double x = 3.0; x < 3.75; x += 0.01) {  // across the surface at r = sqrt(20) = 4.47 on the diagonal-ish line
    ASSERT_TRUE(s.sample({x, 1.3, 1.7}, &v));
    EXPECT_GE(v, 0.0) << x;
  }
}

TEST(CarpetReader, Errors) {
  const Files files;
  CarpetOptions o = files.options();
  // A variable that is in no file.
  o.variables.push_back("press");
  o.required.push_back("press");
  try {
    read_carpet(o);
    FAIL() << "no error for a missing variable";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("'press'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(files.paths.front()), std::string::npos) << e.what();
  }
  // An iteration one variable lacks.
  o = files.options();
  o.iteration = 512;
  try {
    read_carpet(o);
    FAIL() << "no error for a variable at another iteration";
  } catch (const RunError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(m.find("'rho'") != std::string::npos || m.find("'vel[2]'") != std::string::npos) << m;
    EXPECT_NE(m.find("iteration 512"), std::string::npos) << m;
    EXPECT_NE(m.find("0, 256"), std::string::npos) << m;
    EXPECT_NE(m.find(".h5"), std::string::npos) << m;
  }
  // An iteration at which only the finer level was written.
  o = files.options();
  o.iteration = 384;
  try {
    read_carpet(o);
    FAIL() << "no error for an iteration without the coarse level";
  } catch (const RunError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("refinement levels 1 at iteration 384 but levels 0, 1"), std::string::npos) << m;
    EXPECT_NE(m.find("HandOff::iteration"), std::string::npos) << m;
  }
  // Missing files.
  EXPECT_THROW(expand_file_patterns({files.dir.string() + "/nothing*.h5"}), RunError);
  EXPECT_EQ(expand_file_patterns({files.dir.string() + "/data.file_*.h5"}).size(), 2u);
  o = files.options();
  o.files = {files.dir.string() + "/absent.h5"};
  EXPECT_THROW(read_carpet(o), RunError);
}

}  // namespace
