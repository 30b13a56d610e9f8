#include "grid_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "curvilinear.hpp"
#include "h5.hpp"
#include "remnant/error.hpp"

namespace remnant::io {

const char* axis_name(CoordinateSystem c, int direction) {
  static const char* names[3][3] = {{"x", "y", "z"}, {"R", "z", "phi"}, {"r", "theta", "phi"}};
  return names[static_cast<int>(c)][direction];
}

namespace {

std::vector<PatchMeta> gather_meta(const std::vector<Patch>& local, MPI_Comm comm) {
  int nranks = 1;
  MPI_Comm_size(comm, &nranks);
  std::vector<PatchMeta> mine;
  for (const auto& p : local) mine.push_back(p.meta);
  const int bytes = static_cast<int>(mine.size() * sizeof(PatchMeta));
  std::vector<int> counts(static_cast<std::size_t>(nranks)), displs(static_cast<std::size_t>(nranks), 0);
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < nranks; ++r) displs[static_cast<std::size_t>(r)] = displs[static_cast<std::size_t>(r - 1)] + counts[static_cast<std::size_t>(r - 1)];
  std::vector<PatchMeta> all(static_cast<std::size_t>((displs.back() + counts.back()) / static_cast<int>(sizeof(PatchMeta))));
  MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, comm);
  std::sort(all.begin(), all.end(), [](const PatchMeta& a, const PatchMeta& b) { return a.gid < b.gid; });
  return all;
}

}  // namespace

GridFileSummary write_grid_file(const GridFileSpec& spec, const std::vector<Patch>& local, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const bool writer = rank == 0;
  GridFileSummary out;
  out.blocks = gather_meta(local, comm);
  if (out.blocks.empty()) return out;
  const auto& all = out.blocks;
  const int dim = static_cast<int>(spec.cut.axes.size());
  const auto nb = static_cast<hsize_t>(all.size());
  for (const auto& m : all)
    if (m.n != all.front().n)
      throw RunError("IO: " + spec.path + ": blocks of different sizes cannot share one dataset");
  const auto& n = all.front().n;

  // Rows this rank writes: positions of its patches in the gid-ordered list.
  std::vector<hsize_t> rows;
  for (const auto& p : local)
    rows.push_back(static_cast<hsize_t>(
        std::lower_bound(all.begin(), all.end(), p.meta.gid, [](const PatchMeta& m, std::int64_t g) { return m.gid < g; }) -
        all.begin()));
  std::vector<hsize_t> cell_shape, node_shape;
  for (int a = dim - 1; a >= 0; --a) {
    cell_shape.push_back(static_cast<hsize_t>(n[static_cast<std::size_t>(a)]));
    node_shape.push_back(static_cast<hsize_t>(n[static_cast<std::size_t>(a)] + 1));
  }

  const std::string tmp = spec.path + ".tmp";
  {
    h5::Handle file = h5::create_file(tmp, comm);
    h5::write_attr(file, "format", std::string("remnant-grid-1"));
    h5::write_attr(file, "iteration", spec.iteration);
    h5::write_attr(file, "time", spec.time);
    h5::write_attr(file, "coordinates", std::string(to_string(spec.coordinates)));
    h5::write_attr(file, "grid_dimension", static_cast<std::int64_t>(spec.grid_dimension));
    h5::write_attr(file, "dimension", static_cast<std::int64_t>(dim));
    h5::write_attr(file, "cut", spec.cut.name);
    h5::write_attr(file, "axes", std::vector<std::int64_t>(spec.cut.axes.begin(), spec.cut.axes.end()));
    h5::write_attr(file, "point", std::vector<double>(spec.cut.point.begin(), spec.cut.point.end()));
    h5::write_attr(file, "block_cells", std::vector<std::int64_t>(n.begin(), n.begin() + dim));
    std::string names;
    for (const auto& v : spec.variables) names += (names.empty() ? "" : ",") + v.file;
    h5::write_attr(file, "variables", names);
    write_provenance(file, spec.provenance, writer);

    {  // Block list and 1D coordinates: small, rank 0 writes them.
      h5::Handle g = h5::create_group(file, "blocks");
      std::vector<std::int64_t> gid, level, index;
      std::vector<double> lo, dx, fixed;
      for (const auto& m : all) {
        gid.push_back(m.gid);
        level.push_back(m.level);
        index.insert(index.end(), m.index.begin(), m.index.end());
        lo.insert(lo.end(), m.lo.begin(), m.lo.begin() + dim);
        dx.insert(dx.end(), m.dx.begin(), m.dx.begin() + dim);
        fixed.insert(fixed.end(), m.centre3.begin(), m.centre3.end());
      }
      const auto d = static_cast<hsize_t>(dim);
      h5::write_array(g, "gid", {nb}, gid, writer);
      h5::write_array(g, "level", {nb}, level, writer);
      h5::write_array(g, "index", {nb, 3}, index, writer);
      h5::write_array(g, "lo", {nb, d}, lo, writer);
      h5::write_array(g, "dx", {nb, d}, dx, writer);
      h5::write_array(g, "fixed", {nb, 3}, fixed, writer);
      h5::Handle c = h5::create_group(file, "coords");
      for (int a = 0; a < dim; ++a) {
        const auto ua = static_cast<std::size_t>(a);
        std::vector<double> centres, nodes;
        for (const auto& m : all)
          for (std::int64_t i = 0; i <= m.n[ua]; ++i) {
            nodes.push_back(m.lo[ua] + static_cast<double>(i) * m.dx[ua]);
            if (i < m.n[ua]) centres.push_back(m.lo[ua] + (static_cast<double>(i) + 0.5) * m.dx[ua]);
          }
        const std::string name = axis_name(spec.coordinates, spec.cut.axes[ua]);
        h5::write_array(c, name, {nb, static_cast<hsize_t>(n[ua])}, centres, writer);
        h5::write_array(c, name + "_nodes", {nb, static_cast<hsize_t>(n[ua] + 1)}, nodes, writer);
      }
    }

    if (spec.coordinates != CoordinateSystem::cartesian && dim >= 2) {
      // Node positions in Cartesian space, each rank for its own blocks.
      const int ncart = cartesian_components(spec.coordinates, spec.grid_dimension);
      std::vector<double> buf;
      for (const auto& p : local) {
        const auto& m = p.meta;
        std::array<std::int64_t, 3> nn{1, 1, 1};
        for (int a = 0; a < dim; ++a) nn[static_cast<std::size_t>(a)] = m.n[static_cast<std::size_t>(a)] + 1;
        for (std::int64_t k = 0; k < nn[2]; ++k)
          for (std::int64_t j = 0; j < nn[1]; ++j)
            for (std::int64_t i = 0; i < nn[0]; ++i) {
              std::array<double, 3> q = m.centre3;
              const std::array<std::int64_t, 3> ijk{i, j, k};
              for (int a = 0; a < dim; ++a)
                q[static_cast<std::size_t>(spec.cut.axes[static_cast<std::size_t>(a)])] =
                    m.lo[static_cast<std::size_t>(a)] + static_cast<double>(ijk[static_cast<std::size_t>(a)]) * m.dx[static_cast<std::size_t>(a)];
              const auto x = to_cartesian(spec.coordinates, spec.grid_dimension, q);
              buf.insert(buf.end(), x.begin(), x.begin() + ncart);
            }
      }
      auto shape = node_shape;
      shape.push_back(static_cast<hsize_t>(ncart));
      h5::write_rows_collective(file, "cartesian_nodes", nb, shape, rows, buf.data());
    }

    h5::Handle data = h5::create_group(file, "data");
    std::vector<double> buf;
    for (std::size_t v = 0; v < spec.variables.size(); ++v) {
      buf.clear();
      std::int64_t nans = 0;
      for (const auto& p : local) {
        for (double x : p.values[v]) nans += std::isnan(x) ? 1 : 0;
        buf.insert(buf.end(), p.values[v].begin(), p.values[v].end());
      }
      const std::string& name = spec.variables[v].file;
      h5::write_rows_collective(data, name, nb, cell_shape, rows, buf.data());
      std::int64_t total = 0;
      MPI_Allreduce(&nans, &total, 1, MPI_INT64_T, MPI_SUM, comm);
      out.nan_counts.push_back(total);
      h5::Handle d(H5Dopen2(data, name.c_str(), H5P_DEFAULT), H5Dclose);
      h5::write_attr(d, "name", spec.variables[v].full);
      h5::write_attr(d, "nan_count", total);
      if (!spec.variables[v].centering_note.empty()) h5::write_attr(d, "centering", spec.variables[v].centering_note);
    }
    data.reset();  // a parallel file closes only when nothing in it is open
    file.close_checked(tmp);
  }
  std::uint64_t cells = nb;
  for (auto s : cell_shape) cells *= s;
  out.bytes = cells * 8 * spec.variables.size();
  MPI_Barrier(comm);
  if (writer) {
    std::error_code ec;
    std::filesystem::rename(tmp, spec.path, ec);
    if (ec) throw RunError("IO: cannot rename " + tmp + " to " + spec.path + ": " + ec.message());
  }
  MPI_Barrier(comm);
  out.written = true;
  return out;
}

}  // namespace remnant::io
