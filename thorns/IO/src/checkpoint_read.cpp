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
#include "checksum.hpp"
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

struct Header {
  std::int64_t iteration = 0;
  double time = 0, dt = 0;
  std::string parameters, thorns, git;
  std::vector<std::pair<std::string, std::string>> states;
  std::vector<BlockKey> blocks;
  std::vector<std::int64_t> cells;
};

Header read_header(hid_t file, const Context& ctx) {
  Header h;
  if (!h5::has_attr(file, "complete") || h5::read_attr_int(file, "complete") != 1)
    throw RunError("it is incomplete (no 'complete' mark: the writer died)");
  if (h5::read_attr_string(file, "format") != "remnant-checkpoint-1")
    throw RunError("unknown format '" + h5::read_attr_string(file, "format") + "'");
  h.iteration = h5::read_attr_int(file, "iteration");
  h.time = h5::read_attr_double(file, "time");
  h.dt = h5::read_attr_double(file, "dt");
  h.parameters = h5::read_string(file, "parameters");
  h.thorns = h5::read_string(file, "provenance/thorns");
  h.git = h5::read_attr_string(file, "git_revision");
  std::string all_text = h.parameters;
  for (const auto& s : ctx.persistent_states()) {
    if (!h5::exists(file, "persistent/" + s.thorn))
      throw RunError("it holds no persistent state of thorn " + s.thorn);
    h.states.emplace_back(s.thorn, h5::read_string(file, "persistent/" + s.thorn));
    all_text += s.thorn + "\n" + h.states.back().second;
  }
  if (static_cast<std::uint64_t>(h5::read_attr_int(file, "text_checksum")) != checksum(all_text))
    throw RunError("the checksum of its parameters and thorn state does not match (corrupt file)");
  const auto blocks = h5::read_int64s(file, "mesh/blocks");
  for (std::size_t i = 0; i + 3 < blocks.size(); i += 4)
    h.blocks.push_back(BlockKey{static_cast<int>(blocks[i]), {blocks[i + 1], blocks[i + 2], blocks[i + 3]}});
  h.cells = h5::read_int64s(file, "mesh/cells");
  if (h.cells.size() != 3 * h.blocks.size()) throw RunError("its mesh tables disagree (corrupt file)");
  return h;
}

// Fatal (not "try the previous one"): the run itself differs from the one that wrote the file.
void check_compatible(const Context& ctx, const Header& h, const std::string& path) {
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
std::vector<std::vector<double>> read_blocks(hid_t file, Context& ctx, const Header& h, std::vector<std::size_t>& rows) {
  std::map<Key, std::size_t> row_of;
  for (std::size_t i = 0; i < h.blocks.size(); ++i)
    row_of[{h.blocks[i].level, h.blocks[i].index[0], h.blocks[i].index[1], h.blocks[i].index[2]}] = i;
  rows.clear();
  for (Block* b : ctx.grid().local_blocks()) {
    const auto it = row_of.find({b->level, b->index[0], b->index[1], b->index[2]});
    if (it == row_of.end()) throw RunError("a block of the rebuilt mesh is not in the checkpoint");
    for (int d = 0; d < 3; ++d)
      if (h.cells[3 * it->second + static_cast<std::size_t>(d)] != b->n[static_cast<std::size_t>(d)])
        throw RunError("its blocks have other sizes than this grid's (Grid::block_size changed?)");
    rows.push_back(it->second);
  }
  std::vector<hsize_t> hrows(rows.begin(), rows.end());
  std::vector<std::vector<double>> data;
  for (const auto& spec : ctx.vars().groups()) {
    if (!spec.checkpoint) continue;
    const std::string name = "groups/" + spec.full_name();
    if (!h5::exists(file, name)) throw RunError("it holds no variable group " + spec.full_name());
    const auto shape = h5::shape_of(file, name);
    std::size_t width = 0;
    for (Block* b : ctx.grid().local_blocks()) width = packed_size(*b, spec, ctx.grid().dimension());
    if (!rows.empty() && (shape.size() != 2 || shape[1] != width))
      throw RunError("its group " + spec.full_name() + " has another shape than this grid's");
    data.push_back(rows.empty() ? std::vector<double>{} : h5::read_rows(file, name, hrows));
    const auto sums = h5::read_uint64s(file, "checksums/" + spec.full_name());
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (sums.size() != h.blocks.size() || checksum(data.back().data() + r * width, width) != sums[rows[r]])
        throw RunError("block " + std::to_string(rows[r]) + " of " + spec.full_name() +
                       " does not match its checksum (corrupt file)");
  }
  return data;
}

// One candidate: returns "" when restored, else why it is unusable (the same on every rank).
std::string try_checkpoint(Context& ctx, const std::string& path) {
  h5::QuietErrors quiet;
  Header h;
  std::unique_ptr<h5::Handle> file;
  std::string msg;
  bool ok = true;
  try {
    file = std::make_unique<h5::Handle>(h5::open_file_serial(path));
    h = read_header(*file, ctx);
  } catch (const std::exception& e) {
    ok = false;
    msg = e.what();
  }
  if (!agree(ok, msg, ctx.comm())) return msg;
  check_compatible(ctx, h, path);
  ctx.grid().restore_blocks(h.blocks);
  std::vector<std::size_t> rows;
  std::vector<std::vector<double>> data;
  try {
    data = read_blocks(*file, ctx, h, rows);
  } catch (const std::exception& e) {
    ok = false;
    msg = e.what();
  }
  if (!agree(ok, msg, ctx.comm())) return msg;
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
  std::size_t s = 0;
  for (const auto& p : ctx.persistent_states()) p.restore(ctx, h.states[s++].second);
  return "";
}

}  // namespace

bool recover_checkpoint(Context& ctx, const std::string& mode, const CheckpointSettings& settings, std::string* used_path) {
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
    const std::string why = try_checkpoint(ctx, candidates[i]);
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
  throw RunError("IO::recover: no usable checkpoint" + std::string(mode == "auto" ? " in " + settings.dir : "") + ":" +
                 failures + "\n  remove them (or set IO::recover = no) to start from initial data");
}

}  // namespace remnant::io
