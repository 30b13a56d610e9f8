#include "checkpoint_header.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <set>

#include "checksum.hpp"
#include "h5.hpp"
#include "remnant/error.hpp"
#include "xdmf.hpp"

namespace remnant::io {

namespace {

// A byte sequence with explicit lengths: "ab"+"c" and "a"+"bc" serialise differently.
class Serial {
 public:
  void raw(const void* p, std::size_t n) { s_.append(static_cast<const char*>(p), n); }
  template <class T>
  void value(T v) { raw(&v, sizeof v); }
  void text(const std::string& t) {
    value<std::uint64_t>(t.size());
    s_ += t;
  }
  template <class T>
  void values(const std::vector<T>& v) {
    value<std::uint64_t>(v.size());
    if (!v.empty()) raw(v.data(), v.size() * sizeof(T));
  }
  const std::string& str() const { return s_; }

 private:
  std::string s_;
};

std::string join_lines(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : "\n") + s;
  return out;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  if (s.empty()) return out;
  std::size_t start = 0;
  for (;;) {
    const auto nl = s.find('\n', start);
    out.push_back(s.substr(start, nl - start));
    if (nl == std::string::npos) return out;
    start = nl + 1;
  }
}

std::string fmt(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

std::uint64_t metadata_checksum(const CheckpointHeader& h) {
  Serial s;
  s.text(h.format);
  s.value(h.iteration);
  s.value(h.time);
  s.value(h.dt);
  s.value(h.dt_min);
  s.value(h.dt_max);
  s.value(h.nranks);
  s.value(h.dimension);
  s.value(h.nan_count);
  s.text(h.coordinates);
  s.text(h.parameters);
  s.text(h.thorns);
  s.text(h.git);
  s.value<std::uint64_t>(h.states.size());
  for (const auto& [thorn, text] : h.states) {
    s.text(thorn);
    s.text(text);
  }
  s.values(h.blocks);
  s.values(h.cells);
  s.value<std::uint64_t>(h.groups.size());
  for (const auto& g : h.groups) {
    s.text(g.name);
    s.text(g.components);
    s.text(g.centering);
    s.value(g.width);
    s.values(g.sums);
  }
  return checksum(s.str());
}

void write_header_attributes(hid_t file, const CheckpointHeader& h, std::uint64_t digest) {
  h5::write_attr(file, "iteration", h.iteration);
  h5::write_attr(file, "time", h.time);
  h5::write_attr(file, "dt", h.dt);
  h5::write_attr(file, "dt_min", h.dt_min);
  h5::write_attr(file, "dt_max", h.dt_max);
  h5::write_attr(file, "nranks", h.nranks);
  h5::write_attr(file, "coordinates", h.coordinates);
  h5::write_attr(file, "dimension", h.dimension);
  h5::write_attr(file, "nan_count", h.nan_count);
  std::vector<std::string> thorns, groups;
  for (const auto& st : h.states) thorns.push_back(st.first);
  for (const auto& g : h.groups) groups.push_back(g.name);
  h5::write_attr(file, "persistent_thorns", join_lines(thorns));
  h5::write_attr(file, "groups", join_lines(groups));
  h5::write_attr(file, "metadata_checksum", static_cast<std::int64_t>(digest));
}

CheckpointHeader read_checkpoint_header(hid_t file) {
  CheckpointHeader h;
  if (!h5::has_attr(file, "format")) throw RunError("it is not a Remnant checkpoint (no 'format' attribute)");
  h.format = h5::read_attr_string(file, "format");
  if (h.format != checkpoint_format) {
    if (h.format.rfind("remnant-checkpoint-", 0) == 0)
      throw RunError("its format is '" + h.format + "'; this executable reads '" + checkpoint_format + "'");
    throw RunError("it is not a Remnant checkpoint (format '" + h.format + "')");
  }
  if (!h5::has_attr(file, "complete")) throw RunError("it is incomplete (no 'complete' mark: the writer died)");
  if (const auto mark = h5::read_attr_int(file, "complete"); mark != 1)
    throw RunError("its 'complete' mark is " + std::to_string(mark) + ", not 1 (corrupt file)");
  h.iteration = h5::read_attr_int(file, "iteration");
  h.time = h5::read_attr_double(file, "time");
  h.dt = h5::read_attr_double(file, "dt");
  h.dt_min = h5::read_attr_double(file, "dt_min");
  h.dt_max = h5::read_attr_double(file, "dt_max");
  h.nranks = h5::read_attr_int(file, "nranks");
  h.coordinates = h5::read_attr_string(file, "coordinates");
  h.dimension = h5::read_attr_int(file, "dimension");
  h.nan_count = h5::read_attr_int(file, "nan_count");
  h.parameters = h5::read_string(file, "parameters");
  h.thorns = h5::read_string(file, "provenance/thorns");
  h.git = h5::read_attr_string(file, "git_revision");
  for (const auto& thorn : split_lines(h5::read_attr_string(file, "persistent_thorns")))
    h.states.emplace_back(thorn, h5::read_string(file, "persistent/" + thorn));
  h.blocks = h5::read_int64s(file, "mesh/blocks");
  h.cells = h5::read_int64s(file, "mesh/cells");
  for (const auto& name : split_lines(h5::read_attr_string(file, "groups"))) {
    CheckpointGroup g;
    g.name = name;
    const std::string path = "groups/" + name;
    h5::Handle d(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
    if (d.id() < 0) throw RunError("it lacks the dataset " + path + " (corrupt file)");
    g.components = h5::read_attr_string(d, "components");
    g.centering = h5::read_attr_string(d, "centering");
    const auto shape = h5::shape_of(file, path);
    if (shape.size() != 2) throw RunError("its dataset " + path + " is not two-dimensional (corrupt file)");
    g.width = shape[1];
    g.sums = h5::read_uint64s(file, "checksums/" + name);
    if (shape[0] != g.sums.size()) throw RunError("its dataset " + path + " has another row count than its checksums (corrupt file)");
    h.groups.push_back(std::move(g));
  }
  const auto stored = static_cast<std::uint64_t>(h5::read_attr_int(file, "metadata_checksum"));
  if (stored != metadata_checksum(h))
    throw RunError("its metadata (iteration, time, parameters, thorn state, mesh, checksum tables) do not match "
                   "their checksum (corrupt file)");
  return h;
}

CheckpointExpectations expectations_of(const Context& ctx) {
  CheckpointExpectations e;
  e.dimension = ctx.grid().dimension();
  e.coordinates = to_string(ctx.grid().coordinates());
  for (const auto& p : ctx.persistent_states()) e.persistent_thorns.push_back(p.thorn);
  for (const auto& spec : ctx.vars().groups()) {
    if (!spec.checkpoint) continue;
    CheckpointGroup g;
    g.name = spec.full_name();
    for (const auto& c : spec.components) g.components += (g.components.empty() ? "" : ",") + c.name;
    g.centering = to_string(spec.centering);
    e.groups.push_back(std::move(g));
  }
  return e;
}

void validate_checkpoint_header(const CheckpointHeader& h, const std::string& path, const CheckpointExpectations& e) {
  // The iteration: not negative, and the one its name promises (a renamed copy is not that checkpoint).
  if (h.iteration < 0) throw RunError("its stored iteration " + std::to_string(h.iteration) + " is negative");
  const std::int64_t named = iteration_of(std::filesystem::path(path).filename().string(), "checkpoint", "h5");
  if (named >= 0 && named != h.iteration)
    throw RunError("its stored iteration " + std::to_string(h.iteration) + " is not the " + std::to_string(named) +
                   " of its file name (a renamed or copied file?)");
  // The clock: finite, and the time the run's steps can have reached.
  if (!std::isfinite(h.time) || !std::isfinite(h.dt) || !std::isfinite(h.dt_min) || !std::isfinite(h.dt_max))
    throw RunError("its time, dt or step history is not finite (time " + fmt(h.time) + ", dt " + fmt(h.dt) + ")");
  if (h.iteration == 0) {
    if (h.time != 0 || h.dt < 0)
      throw RunError("at iteration 0 its time is " + fmt(h.time) + " and its dt " + fmt(h.dt) + " (expected 0 and >= 0)");
  } else {
    if (!(h.dt_min > 0 && h.dt_min <= h.dt && h.dt <= h.dt_max))
      throw RunError("its dt " + fmt(h.dt) + " lies outside the run's steps [" + fmt(h.dt_min) + ", " + fmt(h.dt_max) + "]");
    const double n = static_cast<double>(h.iteration), slack = 1e-10;
    if (!(h.time >= n * h.dt_min * (1 - slack) && h.time <= n * h.dt_max * (1 + slack)))
      throw RunError("its time " + fmt(h.time) + " cannot follow from " + std::to_string(h.iteration) +
                     " steps of dt between " + fmt(h.dt_min) + " and " + fmt(h.dt_max));
  }
  if (h.nranks < 1) throw RunError("its writer rank count " + std::to_string(h.nranks) + " is not positive");
  // The grid the parfile describes.
  if (h.dimension != e.dimension || h.coordinates != e.coordinates)
    throw RunError("it holds a " + std::to_string(h.dimension) + "D " + h.coordinates + " grid; this run's is " +
                   std::to_string(e.dimension) + "D " + e.coordinates);
  const std::size_t nb = h.block_count();
  if (h.blocks.size() != 4 * nb || h.cells.size() != 3 * nb || nb == 0)
    throw RunError("its mesh tables disagree (" + std::to_string(h.blocks.size()) + " block entries, " +
                   std::to_string(h.cells.size()) + " cell entries)");
  for (std::size_t b = 0; b < nb; ++b) {
    bool ok = h.blocks[4 * b] >= 0;
    for (int d = 0; d < 3; ++d) ok = ok && h.blocks[4 * b + 1 + d] >= 0 && h.cells[3 * b + d] >= 1;
    if (!ok) throw RunError("its mesh entry " + std::to_string(b) + " has a negative level, index or cell count");
  }
  // The thorns' state and the variable groups this run checkpoints.
  std::set<std::string> have;
  for (const auto& s : h.states) have.insert(s.first);
  for (const auto& t : e.persistent_thorns)
    if (!have.count(t)) throw RunError("it holds no persistent state of thorn " + t);
  for (const auto& want : e.groups) {
    const CheckpointGroup* g = nullptr;
    for (const auto& c : h.groups)
      if (c.name == want.name) g = &c;
    if (!g) throw RunError("it holds no variable group " + want.name);
    if (g->components != want.components || g->centering != want.centering)
      throw RunError("its group " + want.name + " has components [" + g->components + "] (" + g->centering +
                     "); this run's are [" + want.components + "] (" + want.centering + ")");
    if (g->sums.size() != nb) throw RunError("its group " + want.name + " has another number of blocks than its mesh");
  }
}

CheckpointHeader inspect_checkpoint(const std::string& path, const CheckpointExpectations& e) {
  h5::QuietErrors quiet;
  h5::Handle file = h5::open_file_serial(path);
  CheckpointHeader h = read_checkpoint_header(file);
  validate_checkpoint_header(h, path, e);
  return h;
}

std::vector<double> read_verified_rows(hid_t file, const CheckpointGroup& g, const std::vector<std::size_t>& rows) {
  std::vector<hsize_t> hrows(rows.begin(), rows.end());
  for (auto r : rows)
    if (r >= g.sums.size()) throw RunError("block " + std::to_string(r) + " of " + g.name + " is not in the checkpoint");
  std::vector<double> data = rows.empty() ? std::vector<double>{} : h5::read_rows(file, "groups/" + g.name, hrows);
  if (data.size() != rows.size() * g.width) throw RunError("the rows of " + g.name + " have another size than recorded");
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (checksum(data.data() + r * g.width, g.width) != g.sums[rows[r]])
      throw RunError("block " + std::to_string(rows[r]) + " of " + g.name + " does not match its checksum (corrupt file)");
  return data;
}

}  // namespace remnant::io
