// Recovery: find the newest usable checkpoint, check it, rebuild the mesh, read each rank's
// blocks. Every rank opens the file read-only by itself (no collective HDF5 calls), so a rank
// that meets a damaged file cannot leave the others waiting; the ranks agree after each phase.
#include <filesystem>
#include <memory>
#include <map>
#include <tuple>

#include "block_packing.hpp"
#include "checkpoint.hpp"
#include "checkpoint_files.hpp"
#include "checkpoint_header.hpp"
#include "checksum.hpp"
#include "file_seal.hpp"
#include "h5.hpp"
#include "parameter_record.hpp"
#include "provenance.hpp"

namespace remnant::io {

namespace {

// True on every rank iff ok on every rank; otherwise `msg` becomes the lowest failing rank's.
bool agree(bool ok, std::string& msg, MPI_Comm comm) {
  int rank = 0, nranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &nranks);
  int first_bad = ok ? nranks : rank, lowest = nranks;
  MPI_Allreduce(&first_bad, &lowest, 1, MPI_INT, MPI_MIN, comm);
  if (lowest == nranks) return true;
  int len = static_cast<int>(msg.size());
  MPI_Bcast(&len, 1, MPI_INT, lowest, comm);
  msg.resize(static_cast<std::size_t>(len));
  MPI_Bcast(msg.data(), len, MPI_CHAR, lowest, comm);
  return false;
}

// Fatal (not "try the previous one"): the run itself differs from the one that wrote the file.
void check_compatible(const Context& ctx, const CheckpointHeader& h, const std::string& path) {
  const Provenance now = provenance_of(ctx);
  if (h.thorns != now.thorns)
    throw RunError("IO::recover: " + path + " was written with active thorns [" + h.thorns + "], this run has [" +
                   now.thorns + "]; a continuation needs the same thorns");
  const ParameterChanges c = compare_parameters(h.parameters, parameter_record(ctx));
  if (!c.errors.empty()) {
    std::string msg = "IO::recover: parameters with 'steerable: never' changed since " + path + ":";
    for (const auto& e : c.errors) msg += "\n    " + e;
    throw RunError(msg + "\n  restore them, or start a new run without IO::recover");
  }
  for (const auto& w : c.warnings) ctx.info("WARNING: changed since the checkpoint (allowed for Flesh): " + w);
  for (const auto& n : c.notes) ctx.info("changed since the checkpoint: " + n);
  if (h.git != now.git_revision)
    ctx.info("WARNING: the checkpoint comes from git revision " + h.git + ", this executable is " + now.git_revision +
             ": the continuation may not be bit-identical");
}

using Key = std::tuple<int, std::int64_t, std::int64_t, std::int64_t>;

// Reads and verifies this rank's blocks of every checkpointed group into `data` (per group).
std::vector<std::vector<double>> read_blocks(hid_t file, Context& ctx, const CheckpointHeader& h) {
  std::map<Key, std::size_t> row_of;
  for (std::size_t i = 0; i < h.block_count(); ++i)
    row_of[{static_cast<int>(h.blocks[4 * i]), h.blocks[4 * i + 1], h.blocks[4 * i + 2], h.blocks[4 * i + 3]}] = i;
  std::vector<std::size_t> rows;
  for (Block* b : ctx.grid().local_blocks()) {
    const auto it = row_of.find({b->level, b->index[0], b->index[1], b->index[2]});
    if (it == row_of.end()) throw RunError("a block of the rebuilt mesh is not in the checkpoint");
    for (int d = 0; d < 3; ++d)
      if (h.cells[3 * it->second + static_cast<std::size_t>(d)] != b->n[static_cast<std::size_t>(d)])
        throw RunError("its blocks have other sizes than this grid's (Grid::block_size changed?)");
    rows.push_back(it->second);
  }
  std::vector<std::vector<double>> data;
  for (const auto& spec : ctx.vars().groups()) {
    if (!spec.checkpoint) continue;
    const CheckpointGroup* g = nullptr;
    for (const auto& c : h.groups)
      if (c.name == spec.full_name()) g = &c;
    if (!g) throw RunError("it holds no variable group " + spec.full_name());
    for (Block* b : ctx.grid().local_blocks())
      if (packed_size(*b, spec, ctx.grid().dimension()) != g->width)
        throw RunError("its group " + spec.full_name() + " has another shape than this grid's");
    data.push_back(read_verified_rows(file, *g, rows));
  }
  return data;
}

// Runs `step` on every rank; true when it succeeded everywhere, else `msg` is the first failure's.
template <class F>
bool on_every_rank(F&& step, std::string& msg, MPI_Comm comm) {
  bool ok = true;
  try {
    step();
  } catch (const std::exception& e) {
    ok = false;
    msg = e.what();
  }
  return agree(ok, msg, comm);
}

// One candidate: returns "" when restored, else why it is unusable (the same on every rank).
// The data, clock and thorn state change only once the whole file has passed every check (the
// mesh is rebuilt before the blocks are read; the next candidate, if any, rebuilds it again).
std::string try_checkpoint(Context& ctx, const std::string& path, StepHistory* history) {
  h5::QuietErrors quiet;
  CheckpointHeader h;
  std::unique_ptr<h5::Handle> file;
  std::string msg;
  const CheckpointExpectations expect = expectations_of(ctx);
  // The seal first (rank 0 reads the file once), so that HDF5 never parses a damaged file.
  if (!on_every_rank(
          [&] {
            const std::string bad = ctx.rank() == 0 ? check_file_seal(path) : std::string();
            if (!bad.empty()) throw RunError(bad);
          },
          msg, ctx.comm()))
    return msg;
  if (!on_every_rank(
          [&] {
            try {
              file = std::make_unique<h5::Handle>(h5::open_file_serial(path));
            } catch (const std::exception& e) {
              throw RunError(std::string("it cannot be opened as HDF5 (truncated, damaged or not an HDF5 file): ") + e.what());
            }
            h = read_checkpoint_header(*file);
            validate_checkpoint_header(h, path, expect);
          },
          msg, ctx.comm()))
    return msg;
  check_compatible(ctx, h, path);
  std::vector<BlockKey> keys;
  for (std::size_t i = 0; i < h.block_count(); ++i)
    keys.push_back(BlockKey{static_cast<int>(h.blocks[4 * i]), {h.blocks[4 * i + 1], h.blocks[4 * i + 2], h.blocks[4 * i + 3]}});
  // The Grid rejects a mesh it cannot hold before changing anything: then try the previous file.
  if (!on_every_rank([&] { ctx.grid().restore_blocks(keys); }, msg, ctx.comm())) return msg;
  std::vector<std::vector<double>> data;
  if (!on_every_rank([&] { data = read_blocks(*file, ctx, h); }, msg, ctx.comm())) return msg;
  // Everything verified: install it.
  std::size_t g = 0;
  const int dim = ctx.grid().dimension();
  for (const auto& spec : ctx.vars().groups()) {
    if (!spec.checkpoint) continue;
    std::size_t r = 0;
    for (Block* b : ctx.grid().local_blocks()) {
      const std::size_t width = packed_size(*b, spec, dim);
      unpack(*b, spec, dim, data[g].data() + r * width);
      ++r;
    }
    ++g;
  }
  auto& clock = ctx.clock();
  clock.iteration = h.iteration;
  clock.time = h.time;
  clock.dt = h.dt;
  clock.substep = 0;
  for (const auto& p : ctx.persistent_states())
    for (const auto& [thorn, text] : h.states)
      if (thorn == p.thorn) p.restore(ctx, text);
  if (history) *history = StepHistory{h.dt_min, h.dt_max};
  return "";
}

}  // namespace

bool recover_checkpoint(Context& ctx, const std::string& mode, const CheckpointSettings& settings, std::string* used_path,
                        StepHistory* history) {
  if (mode == "no") return false;
  std::vector<std::string> candidates;
  if (mode == "auto") {
    candidates = list_checkpoints(settings.dir);
    if (candidates.empty()) {
      ctx.info("IO::recover = auto: no checkpoint in " + settings.dir + ", starting from initial data");
      return false;
    }
  } else {
    if (!std::filesystem::exists(mode)) throw RunError("IO::recover: no checkpoint file '" + mode + "'");
    candidates.push_back(mode);
  }
  std::string failures;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const std::string why = try_checkpoint(ctx, candidates[i], history);
    if (why.empty()) {
      ctx.info("recovered from " + candidates[i] + " at iteration " + std::to_string(ctx.iteration()) + ", t = " +
               std::to_string(ctx.time()));
      if (used_path) *used_path = candidates[i];
      return true;
    }
    const bool more = i + 1 < candidates.size();
    if (ctx.rank() == 0)
      ctx.warn("checkpoint " + candidates[i] + " is unusable: " + why + (more ? "; trying the previous one" : ""));
    failures += "\n    " + candidates[i] + ": " + why;
  }
  if (mode != "auto")
    throw RunError("IO::recover: " + mode + " cannot be used:" + failures +
                   "\n  give IO::recover the path of a checkpoint (<dir>/checkpoint.it<iteration>.h5), auto or no");
  throw RunError("IO::recover: no usable checkpoint in " + settings.dir + ":" + failures +
                 "\n  move them aside (or set IO::recover = no) to start from initial data");
}

}  // namespace remnant::io
