// Every byte of a checkpoint that recovery uses is checked: a small WaveToy run writes checkpoints
// at iterations 4 and 8; then thousands of single-bit flips of the newest one, each followed by
// IO's recovery (IO::recover = auto) on a fresh grid. Each must end in one of two ways only:
//   - the flipped file is used and the restored state (clock, every checkpointed block, thorn
//     state) is bit-identical to recovering the intact file (the flip hit unused bytes), or
//   - the file is rejected by name ("checkpoint.it0000000008.h5 is unusable") and the state is
//     bit-identical to recovering the previous checkpoint (iteration 4).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <span>
#include <sstream>

#include "block_packing.hpp"
#include "checkpoint.hpp"
#include "checkpoint_files.hpp"
#include "checkpoint_header.hpp"
#include "file_seal.hpp"
#include "remnant/driver.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace remnant::io {
namespace {

namespace fs = std::filesystem;

const ThornCatalog& catalog() {
  static const ThornCatalog c(remnant_compiled_thorns());
  return c;
}

SimulationOptions options(const fs::path& out, std::vector<std::string> extra) {
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/wavetoy_1d.yaml";
  o.quiet = true;
  o.overrides = {"Grid::ncells=[16,1,1]", "Grid::block_size=[8,1,1]", "IO::tsv_every=0", "Flesh::out_dir=" + out.string(),
                 "IO::checkpoint_every=4", "IO::checkpoint_keep=5", "MoL::max_iterations=8"};
  o.overrides.insert(o.overrides.end(), extra.begin(), extra.end());
  return o;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Everything recovery installed: the clock, every checkpointed group of every block, thorn state.
std::string fingerprint(Context& ctx) {
  std::string f;
  auto add = [&](const void* p, std::size_t n) { f.append(static_cast<const char*>(p), n); };
  const auto& c = ctx.clock();
  add(&c.iteration, sizeof c.iteration);
  add(&c.time, sizeof c.time);
  add(&c.dt, sizeof c.dt);
  std::vector<double> buf;
  for (const auto& spec : ctx.vars().groups())
    if (spec.checkpoint)
      for (Block* b : ctx.grid().local_blocks()) pack(*b, spec, ctx.grid().dimension(), buf);
  add(buf.data(), buf.size() * sizeof(double));
  for (const auto& s : ctx.persistent_states()) f += s.thorn + "=" + s.save(ctx) + ";";
  return f;
}

// Recovers from `dir` on a fresh simulation with stdout and stderr (the rejection warnings) captured.
struct Recovery {
  std::string used, fingerprint, log, error;
};
Recovery recover_from(const fs::path& dir, const fs::path& scratch) {
  Recovery r;
  Simulation sim(catalog(), options(scratch / "out", {}), MPI_COMM_SELF);
  sim.setup_output_and_grid();
  CheckpointSettings settings;
  settings.dir = dir.string();
  const fs::path log = scratch / "stderr.txt";
  std::fflush(stdout);
  std::fflush(stderr);
  const int saved_out = ::dup(1), saved_err = ::dup(2);
  std::FILE* f = std::fopen(log.c_str(), "w");
  ::dup2(::fileno(f), 1);
  ::dup2(::fileno(f), 2);
  try {
    if (recover_checkpoint(sim.context(), "auto", settings, &r.used)) r.fingerprint = fingerprint(sim.context());
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  std::cout << std::flush;
  std::cerr << std::flush;
  std::fflush(stdout);
  std::fflush(stderr);
  ::dup2(saved_out, 1);
  ::dup2(saved_err, 2);
  ::close(saved_out);
  ::close(saved_err);
  std::fclose(f);
  r.log = bytes_of(log);
  return r;
}

// A run to 8 with checkpoints at 4 and 8 under `root`; returns their folder.
fs::path write_checkpoints(const fs::path& root) {
  fs::remove_all(root);
  Simulation sim(catalog(), options(root / "run", {}), MPI_COMM_SELF);
  sim.setup_output_and_grid();
  sim.run();
  return root / "run" / "checkpoints";
}

// A mesh entry the Grid cannot hold, under a matching metadata checksum (as a faulty writer would
// leave it): the Grid's refusal must reject the file by name and recovery go on with the previous.
TEST(CheckpointRecovery, MeshTheGridRefusesFallsBackToThePreviousCheckpoint) {
  const fs::path root = fs::temp_directory_path() / ("remnant_forged_mesh_" + std::to_string(::getpid()));
  const fs::path dir = write_checkpoints(root);
  const std::string newest = checkpoint_path(dir.string(), 8);
  {
    hid_t f = H5Fopen(newest.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    CheckpointHeader h = read_checkpoint_header(f);
    h.blocks[4 * 1 + 1] = 99;  // block 1 at index i = 99: outside a 16-cell domain of 8-cell blocks
    hid_t d = H5Dopen2(f, "mesh/blocks", H5P_DEFAULT);
    ASSERT_GE(H5Dwrite(d, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, h.blocks.data()), 0);
    H5Dclose(d);
    hid_t a = H5Aopen(f, "metadata_checksum", H5P_DEFAULT);
    const auto sum = static_cast<std::int64_t>(metadata_checksum(h));
    ASSERT_GE(H5Awrite(a, H5T_NATIVE_INT64, &sum), 0);
    H5Aclose(a);
    H5Fclose(f);
    seal_file(newest);  // the faulty writer seals what it wrote
  }
  const Recovery r = recover_from(dir, root);
  EXPECT_EQ(r.used, checkpoint_path(dir.string(), 4)) << r.error << r.log;
  EXPECT_NE(r.log.find("checkpoint.it0000000008.h5 is unusable: the checkpoint's mesh has a block"), std::string::npos)
      << r.log;
  fs::remove_all(root);
}

// HDF5 can crash (not fail) on a damaged object header, so recovery checks the file's seal (a
// checksum of everything after the user block) before HDF5 parses anything.
TEST(CheckpointRecovery, DamagedBytesAreRejectedByTheFileSealBeforeHdf5ReadsThem) {
  const fs::path root = fs::temp_directory_path() / ("remnant_seal_" + std::to_string(::getpid()));
  const fs::path dir = write_checkpoints(root);
  const std::string newest = checkpoint_path(dir.string(), 8);
  const std::string original = bytes_of(newest);
  ASSERT_EQ(original.rfind("remnant-file-seal fnv64 ", 0), 0u) << "the checkpoint starts with its seal";
  for (std::size_t offset : {std::size_t{kFileSealBytes} + 8, std::size_t{kFileSealBytes} + 700, original.size() - 3}) {
    std::string damaged = original;
    damaged[offset] = static_cast<char>(damaged[offset] ^ 0x10);
    std::ofstream(newest, std::ios::binary | std::ios::trunc) << damaged;
    const Recovery r = recover_from(dir, root);
    EXPECT_EQ(r.used, checkpoint_path(dir.string(), 4)) << "byte " << offset << ": " << r.error << r.log;
    EXPECT_NE(r.log.find("checkpoint.it0000000008.h5 is unusable: its contents do not match the file seal"), std::string::npos)
        << "byte " << offset << ": " << r.log;
  }
  std::ofstream(newest, std::ios::binary | std::ios::trunc) << original.substr(0, original.size() - 100);
  const Recovery r = recover_from(dir, root);
  EXPECT_NE(r.log.find("(truncated or extended)"), std::string::npos) << r.log;
  fs::remove_all(root);
}

TEST(CheckpointBitFlips, EveryFlipIsUsedIdenticallyOrRejectedByName) {
  const fs::path root = fs::temp_directory_path() / ("remnant_bitflips_" + std::to_string(::getpid()));
  const fs::path dir = write_checkpoints(root);
  const fs::path newest = checkpoint_path(dir.string(), 8), previous = checkpoint_path(dir.string(), 4);
  ASSERT_TRUE(fs::exists(newest) && fs::exists(previous));

  // The references: recovery from the intact pair, and from the previous one alone.
  const fs::path work = root / "flipped";
  fs::create_directories(work);
  fs::copy_file(previous, checkpoint_path(work.string(), 4));
  const Recovery from_previous = recover_from(work, root);
  ASSERT_EQ(from_previous.used, checkpoint_path(work.string(), 4)) << from_previous.error;
  const std::string original = bytes_of(newest);
  const std::string target = checkpoint_path(work.string(), 8);
  std::ofstream(target, std::ios::binary) << original;
  const Recovery intact = recover_from(work, root);
  ASSERT_EQ(intact.used, target) << intact.error;
  ASSERT_NE(intact.fingerprint, from_previous.fingerprint);

  std::mt19937_64 rng(20261123);
  const int flips = 2048;
  int used = 0, rejected = 0;
  std::map<std::string, int> reasons;
  for (int n = 0; n < flips; ++n) {
    const std::size_t bit = rng() % (original.size() * 8);
    std::string damaged = original;
    damaged[bit / 8] = static_cast<char>(damaged[bit / 8] ^ (1 << (bit % 8)));
    std::ofstream(target, std::ios::binary | std::ios::trunc) << damaged;
    const Recovery r = recover_from(work, root);
    // A rejected file must not stay open (HDF5 would hold it, and complain at exit).
    ASSERT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0) << "bit " << bit << " (byte " << bit / 8 << ") leaves HDF5 objects open";
    ASSERT_TRUE(r.error.empty()) << "bit " << bit << ": recovery failed: " << r.error;
    if (r.used == target) {
      ++used;
      ASSERT_EQ(r.fingerprint, intact.fingerprint) << "bit " << bit << " (byte " << bit / 8
                                                   << "): the flipped file was used but restored another state";
    } else {
      ++rejected;
      ASSERT_EQ(r.used, checkpoint_path(work.string(), 4)) << "bit " << bit;
      ASSERT_EQ(r.fingerprint, from_previous.fingerprint) << "bit " << bit;
      const std::string named = "checkpoint.it0000000008.h5 is unusable: ";
      const auto at = r.log.find(named);
      ASSERT_NE(at, std::string::npos) << "bit " << bit << ": the rejection does not name the file:\n" << r.log;
      // Count reasons by their first words (HDF5's own messages vary in their details).
      std::string why = r.log.substr(at + named.size(), 40);
      why = why.substr(0, why.find_first_of("(\n:"));
      ++reasons[why];
    }
  }
  std::printf("%d single-bit flips of a %zu-byte checkpoint: %d in unused bytes (state bit-identical), %d rejected by name "
              "(previous checkpoint used, bit-identical)\n", flips, original.size(), used, rejected);
  for (const auto& [why, count] : reasons) std::printf("  %5d  %s\n", count, why.c_str());
  EXPECT_GT(rejected, flips / 10);  // the sample reaches the data and metadata, not just padding
  fs::remove_all(root);
}

}  // namespace
}  // namespace remnant::io
