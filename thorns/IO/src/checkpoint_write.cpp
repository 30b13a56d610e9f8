// Writing a checkpoint: <name>.tmp through MPI-IO, `complete` last, close, fsync, rename.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
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

using Key = std::tuple<int, std::int64_t, std::int64_t, std::int64_t>;
Key key_of(const BlockKey& k) { return {k.level, k.index[0], k.index[1], k.index[2]}; }

// Gathers (row, values...) records of every rank on rank 0 into a [rows][width] table.
std::vector<std::int64_t> gather_table(const std::vector<std::int64_t>& mine, int width, std::size_t rows, MPI_Comm comm) {
  int rank = 0, nranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &nranks);
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(nranks)), displs(static_cast<std::size_t>(nranks), 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  for (int r = 1; r < nranks; ++r) displs[static_cast<std::size_t>(r)] = displs[static_cast<std::size_t>(r - 1)] + counts[static_cast<std::size_t>(r - 1)];
  std::vector<std::int64_t> all(rank == 0 ? static_cast<std::size_t>(displs.back() + counts.back()) : 0);
  MPI_Gatherv(mine.data(), count, MPI_INT64_T, all.data(), counts.data(), displs.data(), MPI_INT64_T, 0, comm);
  std::vector<std::int64_t> table(rank == 0 ? rows * static_cast<std::size_t>(width) : 0);
  const auto w = static_cast<std::size_t>(width);
  for (std::size_t i = 0; i + w < all.size(); i += w + 1)  // records: row, then `width` values
    for (std::size_t c = 0; c < w; ++c) table[static_cast<std::size_t>(all[i]) * w + c] = all[i + 1 + c];
  return table;
}

}  // namespace

std::string write_checkpoint(Context& ctx, const CheckpointSettings& settings, const StepHistory& history) {
  const double t0 = MPI_Wtime();
  GridDriver& grid = ctx.grid();
  MPI_Comm comm = ctx.comm();
  const bool writer = ctx.rank() == 0;
  const int dim = grid.dimension();
  if (writer) {
    std::error_code ec;
    std::filesystem::create_directories(settings.dir, ec);
    if (ec) throw RunError("IO: cannot create checkpoint directory " + settings.dir + ": " + ec.message());
  }
  MPI_Barrier(comm);
  const std::string path = checkpoint_path(settings.dir, ctx.iteration());
  const std::string tmp = path + ".tmp";

  // Rows of this rank's blocks in the gid-ordered block list.
  const auto keys = grid.all_blocks();
  std::map<Key, std::size_t> row_of;
  for (std::size_t i = 0; i < keys.size(); ++i) row_of[key_of(keys[i])] = i;
  std::vector<Block*> local(grid.local_blocks().begin(), grid.local_blocks().end());
  std::vector<hsize_t> rows;
  for (Block* b : local) {
    const auto it = row_of.find({b->level, b->index[0], b->index[1], b->index[2]});
    if (it == row_of.end()) throw RunError("IO: a local block is missing from GridDriver::all_blocks()");
    rows.push_back(it->second);
  }
  std::vector<std::size_t> order(local.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rows[a] < rows[b]; });
  std::vector<hsize_t> sorted_rows;
  for (auto i : order) sorted_rows.push_back(rows[i]);
  const auto nb = static_cast<hsize_t>(keys.size());

  CheckpointHeader header;
  header.iteration = ctx.iteration();
  header.time = ctx.time();
  header.dt = ctx.dt();
  header.dt_min = history.dt_min;
  header.dt_max = history.dt_max;
  header.nranks = ctx.nranks();
  header.dimension = dim;
  header.coordinates = to_string(grid.coordinates());
  header.parameters = parameter_record(ctx);
  const Provenance prov = provenance_of(ctx);
  header.thorns = prov.thorns;
  header.git = prov.git_revision;
  // Persistent thorn state is the same on every rank; rank 0's text is stored.
  for (const auto& s : ctx.persistent_states()) header.states.emplace_back(s.thorn, s.save(ctx));
  for (const auto& k : keys) header.blocks.insert(header.blocks.end(), {k.level, k.index[0], k.index[1], k.index[2]});

  std::int64_t nans = 0;
  {
    h5::Handle file = h5::create_file(tmp, comm, kFileSealBytes);
    h5::write_attr(file, "format", header.format);  // first: a dead writer's file still says what it is
    write_provenance(file, prov, writer);
    h5::write_string(file, "parameters", header.parameters, writer);
    {
      h5::Handle g = h5::create_group(file, "persistent");
      for (const auto& [t, s] : header.states) h5::write_string(g, t, s, writer);
    }
    {
      h5::Handle g = h5::create_group(file, "mesh");
      h5::write_array(g, "blocks", {nb, 4}, header.blocks, writer);
      std::vector<std::int64_t> mine;
      for (std::size_t i = 0; i < local.size(); ++i)
        mine.insert(mine.end(), {static_cast<std::int64_t>(rows[i]), local[i]->n[0], local[i]->n[1], local[i]->n[2]});
      header.cells = gather_table(mine, 3, keys.size(), comm);
      h5::write_array(g, "cells", {nb, 3}, header.cells, writer);
    }
    h5::Handle groups = h5::create_group(file, "groups");
    h5::Handle sums = h5::create_group(file, "checksums");
    std::vector<double> buf;
    int written = 0;
    for (const auto& spec : ctx.vars().groups()) {
      if (!spec.checkpoint) continue;
      buf.clear();
      std::vector<std::int64_t> mine;
      std::size_t per_block = 0;
      for (auto i : order) {
        const std::size_t start = buf.size();
        pack(*local[i], spec, dim, buf);
        per_block = buf.size() - start;
        for (std::size_t p = start; p < buf.size(); ++p) nans += std::isnan(buf[p]) ? 1 : 0;
        mine.insert(mine.end(), {static_cast<std::int64_t>(rows[i]), static_cast<std::int64_t>(checksum(buf.data() + start, per_block))});
      }
      // Ranks without blocks still need the row width: every block of a group has the same size.
      unsigned long long width = per_block, max_width = 0;
      MPI_Allreduce(&width, &max_width, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, comm);
      h5::write_rows_collective(groups, spec.full_name(), nb, {static_cast<hsize_t>(max_width)}, sorted_rows, buf.data());
      CheckpointGroup g;
      g.name = spec.full_name();
      for (const auto& c : spec.components) g.components += (g.components.empty() ? "" : ",") + c.name;
      g.centering = to_string(spec.centering);
      g.width = max_width;
      {
        h5::Handle d(H5Dopen2(groups, spec.full_name().c_str(), H5P_DEFAULT), H5Dclose);
        h5::write_attr(d, "components", g.components);
        h5::write_attr(d, "centering", g.centering);
      }
      const auto table = gather_table(mine, 1, keys.size(), comm);
      g.sums.assign(table.begin(), table.end());
      h5::write_array(sums, spec.full_name(), {nb}, g.sums, writer);
      header.groups.push_back(std::move(g));
      if (++written == 1 && settings.kill_at_iteration == ctx.iteration()) {
        // Test of crash safety: die with a half-written file, as a node failure would.
        H5Fflush(file, H5F_SCOPE_GLOBAL);
        MPI_Barrier(comm);
        std::raise(SIGKILL);
      }
    }
    MPI_Allreduce(&nans, &header.nan_count, 1, MPI_INT64_T, MPI_SUM, comm);
    if (header.nan_count > 0 && writer)
      ctx.warn("checkpoint at iteration " + std::to_string(ctx.iteration()) + " holds " + std::to_string(header.nan_count) +
               " NaN values (attribute nan_count)");
    // Only rank 0 holds the gathered tables: its checksum goes into everyone's attribute.
    std::uint64_t digest = writer ? metadata_checksum(header) : 0;
    MPI_Bcast(&digest, 1, MPI_UINT64_T, 0, comm);
    write_header_attributes(file, header, digest);
    // Last: a reader that sees `complete` knows every dataset before it was written.
    h5::write_attr(file, "complete", std::int64_t{1});
    groups.reset();  // a parallel file closes only when nothing in it is open
    sums.reset();
    file.close_checked(tmp);
  }
  MPI_Barrier(comm);
  std::vector<std::string> pruned;
  if (writer) {
    seal_file(tmp);  // before the rename: a file under its final name is always sealed
    commit_file(tmp, path);
    pruned = prune_checkpoints(settings.dir, settings.keep, ctx.iteration());
  }
  MPI_Barrier(comm);
  if (writer) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    char msg[512];
    std::snprintf(msg, sizeof msg, "checkpoint %s written (%.1f MB in %.2f s)%s", path.c_str(),
                  static_cast<double>(bytes) / 1e6, MPI_Wtime() - t0,
                  pruned.empty() ? "" : (", removed " + std::to_string(pruned.size()) + " older").c_str());
    ctx.info(msg);
  }
  return path;
}

}  // namespace remnant::io
