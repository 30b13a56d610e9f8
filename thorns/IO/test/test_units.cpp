// Unit tests of the IO thorn's pieces: checksums, TSV trimming, parameter comparison,
// curvilinear positions, the centre cell choice, cuts, file names, block packing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

#include "block_packing.hpp"
#include "centre_value.hpp"
#include "checkpoint_files.hpp"
#include "checkpoint_header.hpp"
#include "checksum.hpp"
#include "curvilinear.hpp"
#include "fake_grid.hpp"
#include "remnant/tsv_file.hpp"
#include "parameter_record.hpp"
#include "patches.hpp"
#include "tsv_output.hpp"
#include "xdmf.hpp"

namespace remnant::io {
namespace {

std::filesystem::path temp_dir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("remnant_io_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

TEST(Checksum, DetectsOneFlippedBit) {
  std::vector<double> v(1000);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = std::sin(0.1 * static_cast<double>(i));
  const auto h = checksum(v.data(), v.size());
  v[500] = std::nextafter(v[500], 2.0);
  EXPECT_NE(h, checksum(v.data(), v.size()));
  EXPECT_NE(checksum(v.data(), 10), checksum(v.data(), 11));
}

TEST(Tsv, TrimKeepsHeaderAndRowsUpToTheIteration) {
  const auto d = temp_dir("trim");
  const auto p = (d / "a.tsv").string();
  std::ofstream(p) << "# x\n# 1:iteration\t2:time\t3:value\n0\t0\t1\n1\t0.1\t2\n2\t0.2\t3\n3\t0.3";  // last row cut short
  EXPECT_EQ(trim_tsv_file(p, 1), 2);
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), "# x\n# 1:iteration\t2:time\t3:value\n0\t0\t1\n1\t0.1\t2\n");
}

TEST(Tsv, TrimDropsARowWithoutNewline) {
  const auto d = temp_dir("trim2");
  const auto p = (d / "a.tsv").string();
  std::ofstream(p) << "# x\n0\t0\t1\n1\t0.1";
  EXPECT_EQ(trim_tsv_file(p, 5), 1);
}

TEST(Parameters, NeverIsAnErrorFleshAWarningRecoverANote) {
  const std::string old = "Grid::ncells\tnever\t[16, 16, 16]\nFlesh::out_dir\tnever\t\"a\"\nMoL::cfl\trecover\t0.4\n";
  const std::string now = "Grid::ncells\tnever\t[32, 16, 16]\nFlesh::out_dir\tnever\t\"b\"\nMoL::cfl\trecover\t0.3\n";
  const auto c = compare_parameters(old, now);
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_NE(c.errors[0].find("Grid::ncells: checkpoint [16, 16, 16], now [32, 16, 16]"), std::string::npos);
  EXPECT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(c.notes.size(), 1u);
  EXPECT_TRUE(compare_parameters(old, old).errors.empty());
}

TEST(Curvilinear, CartesianPositions) {
  const double pi = 3.14159265358979323846;
  auto x = to_cartesian(CoordinateSystem::cylindrical, 2, {1.5, -0.5, 0.3});
  EXPECT_DOUBLE_EQ(x[0], 1.5);
  EXPECT_DOUBLE_EQ(x[1], -0.5);
  x = to_cartesian(CoordinateSystem::cylindrical, 3, {2, 1, pi / 2});
  EXPECT_NEAR(x[0], 0, 1e-15);
  EXPECT_DOUBLE_EQ(x[1], 2);
  EXPECT_DOUBLE_EQ(x[2], 1);
  x = to_cartesian(CoordinateSystem::spherical, 2, {2, pi / 2, 0});
  EXPECT_DOUBLE_EQ(x[0], 2);
  EXPECT_NEAR(x[1], 0, 1e-15);
  x = to_cartesian(CoordinateSystem::spherical, 3, {1, pi / 2, pi});
  EXPECT_NEAR(x[0], -1, 1e-15);
}

TEST(Centre, PrefersContainingBlockThenNearestThenLowestGid) {
  auto vars = test::one_scalar_registry();
  test::FakeGrid grid(vars, CoordinateSystem::cartesian, 2, {2, 2, 1}, {4, 4, 1}, {-1, -1, 0}, {1, 1, 1}, MPI_COMM_SELF);
  // The origin is a corner shared by four blocks: half-open blocks give it to the upper-right one.
  CellChoice best;
  bool have = false;
  for (Block* b : grid.local_blocks()) {
    const auto c = nearest_cell(*b, {0, 0, 0}, 2);
    if (!have || better(c, best)) best = c, have = true;
  }
  EXPECT_EQ(best.gid, 3);
  EXPECT_EQ(best.cell[0], 0);
  EXPECT_EQ(best.cell[1], 0);
  for (Block* b : grid.local_blocks()) b->field(0, 0)(0, 0, 0) = static_cast<double>(b->gid) + 10;
  EXPECT_EQ(value_at_point(grid, 0, 0, {0, 0, 0}), 13);
  // Outside the domain: the nearest cell anywhere.
  EXPECT_EQ(value_at_point(grid, 0, 0, {-5, -5, 0}), 10);
}

TEST(Cuts, SlicesNeedThreeDimensions) {
  EXPECT_THROW(make_cut("slice_xy", 2, {0, 0, 0}), RunError);
  EXPECT_THROW(make_cut("line_z", 2, {0, 0, 0}), RunError);
  EXPECT_EQ(make_cut("slice_xz", 3, {0, 0, 0}).axes, (std::vector<int>{0, 2}));
  EXPECT_EQ(make_cut("volume", 2, {0, 0, 0}).axes, (std::vector<int>{0, 1}));
}

TEST(Cuts, LinePatchesHoldOneRow) {
  auto vars = test::one_scalar_registry();
  test::FakeGrid grid(vars, CoordinateSystem::cartesian, 2, {2, 2, 1}, {4, 4, 1}, {-1, -1, 0}, {1, 1, 1}, MPI_COMM_SELF);
  for (Block* b : grid.local_blocks()) {
    const Field f = b->field(0, 0);
    for_interior(*b, [&](int i, int j, int k) { f(i, j, k) = b->x(0, i) + 100 * b->x(1, j); });
  }
  const auto p = extract_patches(grid.local_blocks(), 2, make_cut("line_x", 2, {0, 0.3, 0}), {VariableRef{0, 0, "", ""}});
  ASSERT_EQ(p.size(), 2u);  // the two upper blocks
  EXPECT_EQ(p[0].values[0].size(), 4u);
  EXPECT_DOUBLE_EQ(p[0].meta.centre3[1], 0.375);  // centre of the cell holding y = 0.3
  EXPECT_DOUBLE_EQ(p[0].values[0][0], -0.875 + 37.5);
}

TEST(Files, IterationNamesAndOrder) {
  EXPECT_EQ(iteration_of("checkpoint.it0000000012.h5", "checkpoint", "h5"), 12);
  EXPECT_EQ(iteration_of("checkpoint.it0000000012.h5.tmp", "checkpoint", "h5"), -1);
  EXPECT_EQ(iteration_of("grid-volume.it00000004.xmf", "grid-volume", "xmf"), 4);
  const auto d = temp_dir("list");
  for (int it : {4, 12, 8}) std::ofstream(checkpoint_path(d.string(), it)) << "x";
  std::ofstream(checkpoint_path(d.string(), 16) + ".tmp") << "x";
  const auto l = list_checkpoints(d.string());
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[0], checkpoint_path(d.string(), 12));
  EXPECT_EQ(l[2], checkpoint_path(d.string(), 4));
  prune_checkpoints(d.string(), 2, 12);
  EXPECT_EQ(list_checkpoints(d.string()).size(), 2u);
  EXPECT_FALSE(std::filesystem::exists(checkpoint_path(d.string(), 16) + ".tmp"));
}

// A file named after a later iteration than the one just written (one that recovery rejected, e.g.
// a renamed copy) must not count among the newest: with keep = 1 it would delete every new one.
TEST(Files, PruneIgnoresCheckpointsBeyondTheCurrentIteration) {
  const auto d = temp_dir("prune_future");
  for (int it : {30, 35, 32, 34}) std::ofstream(checkpoint_path(d.string(), it)) << "x";
  const auto deleted = prune_checkpoints(d.string(), 1, 34);
  EXPECT_EQ(deleted.size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(checkpoint_path(d.string(), 34)));
  EXPECT_TRUE(std::filesystem::exists(checkpoint_path(d.string(), 35)));
  EXPECT_FALSE(std::filesystem::exists(checkpoint_path(d.string(), 32)));
}

// A header as a 1D run of two 8-cell blocks writes it at iteration 12 with a constant dt.
CheckpointHeader good_header() {
  CheckpointHeader h;
  h.iteration = 12;
  h.dt = h.dt_min = h.dt_max = 0.01;
  for (int i = 0; i < 12; ++i) h.time += h.dt;
  h.dimension = 1;
  h.coordinates = "cartesian";
  h.parameters = "Grid::ncells\tnever\t[16,1,1]\n";
  h.thorns = "Grid,MoL,IO";
  h.states = {{"IO", "-1"}};
  h.blocks = {0, 0, 0, 0, 0, 1, 0, 0};
  h.cells = {8, 1, 1, 8, 1, 1};
  h.groups = {CheckpointGroup{"Test::f", "f", "cell", 8, {1, 2}}};
  return h;
}

CheckpointExpectations expectations() {
  return CheckpointExpectations{1, "cartesian", {"IO"}, {CheckpointGroup{"Test::f", "f", "cell", 0, {}}}};
}

std::string rejection(const CheckpointHeader& h, const std::string& name = "checkpoint.it0000000012.h5") {
  try {
    validate_checkpoint_header(h, "/some/dir/" + name, expectations());
  } catch (const RunError& e) {
    return e.what();
  }
  return "";
}

// The metadata checksum changes with any field: the damage of issue 16 (sign bit of the iteration,
// one bit of the time) and every other kind of field.
TEST(CheckpointHeader, ChecksumCoversEveryField) {
  const auto base = metadata_checksum(good_header());
  std::vector<std::function<void(CheckpointHeader&)>> damage = {
      [](auto& h) { h.iteration ^= std::int64_t{1} << 63; },
      [](auto& h) { h.iteration = -5; },
      [](auto& h) { h.time = std::ldexp(h.time, -1); },
      [](auto& h) { h.time = 1e10; },
      [](auto& h) { h.dt_max *= 2; },
      [](auto& h) { h.nan_count = 1; },
      [](auto& h) { h.coordinates = "spherical"; },
      [](auto& h) { h.parameters[3] ^= 1; },
      [](auto& h) { h.thorns += "x"; },
      [](auto& h) { h.git = "x"; },
      [](auto& h) { h.states[0].second = "0"; },
      [](auto& h) { h.blocks[5] = 99; },
      [](auto& h) { h.cells[0] = 4; },
      [](auto& h) { h.groups[0].width = 9; },
      [](auto& h) { h.groups[0].sums[1] ^= 4; },
      [](auto& h) { h.groups[0].components = "g"; },
  };
  for (std::size_t i = 0; i < damage.size(); ++i) {
    CheckpointHeader h = good_header();
    damage[i](h);
    EXPECT_NE(metadata_checksum(h), base) << "damage " << i;
  }
}

// A header whose checksum matches (written so by a faulty writer, or forged) must still make sense.
TEST(CheckpointHeader, ValidationRejectsWhatCannotBeThisRunsCheckpoint) {
  EXPECT_EQ(rejection(good_header()), "");
  EXPECT_EQ(rejection(good_header(), "my_copy.h5"), "");  // IO::recover = <a file of another name>
  auto with = [](std::function<void(CheckpointHeader&)> f) {
    CheckpointHeader h = good_header();
    f(h);
    return h;
  };
  EXPECT_NE(rejection(with([](auto& h) { h.iteration = -5; }), "copy.h5").find("is negative"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.iteration ^= std::int64_t{1} << 63; })).find("is negative"), std::string::npos);
  EXPECT_NE(rejection(good_header(), "checkpoint.it0000000035.h5").find("stored iteration 12 is not the 35 of its file name"),
            std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.time = std::ldexp(h.time, -1); })).find("cannot follow from 12 steps"),
            std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.time = 1e10; })).find("cannot follow from 12 steps"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.time = NAN; })).find("not finite"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.dt = 0.02; })).find("outside the run's steps"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.dt_min = h.dt_max = 0; })).find("outside the run's steps"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.iteration = 0; }), "x.h5").find("at iteration 0"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.dimension = 2; })).find("this run's is 1D cartesian"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.blocks[5] = -1; })).find("mesh entry 1"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.cells.pop_back(); })).find("mesh tables disagree"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.states.clear(); })).find("persistent state of thorn IO"), std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.groups[0].name = "Test::g"; })).find("no variable group Test::f"),
            std::string::npos);
  EXPECT_NE(rejection(with([](auto& h) { h.groups[0].sums.pop_back(); })).find("another number of blocks"), std::string::npos);
}

TEST(Packing, RoundTripOfInteriorPoints) {
  auto vars = test::one_scalar_registry();
  test::FakeGrid grid(vars, CoordinateSystem::cartesian, 3, {1, 1, 1}, {3, 4, 5}, {0, 0, 0}, {1, 1, 1}, MPI_COMM_SELF);
  Block& b = *grid.local_blocks()[0];
  const Field f = b.field(0, 0);
  for_interior(b, [&](int i, int j, int k) { f(i, j, k) = i + 10 * j + 100 * k; });
  std::vector<double> buf;
  pack(b, vars.group(0), 3, buf);
  EXPECT_EQ(buf.size(), packed_size(b, vars.group(0), 3));
  EXPECT_EQ(buf.size(), 60u);
  std::fill(b.data(0), b.data(0) + b.size(0), 0.0);
  unpack(b, vars.group(0), 3, buf.data());
  EXPECT_EQ(f(2, 3, 4), 432);
}

}  // namespace
}  // namespace remnant::io
