#include "HandOff/carpet_reader.hpp"

#include <glob.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "h5_read.hpp"
#include "level_builder.hpp"
#include "remnant/error.hpp"

namespace remnant::handoff {
namespace {

struct DatasetRef {
  std::string file, name;
  int rl = 0, c = 0;
};

// "HYDROBASE::rho it=12 tl=0 rl=1 c=3" -> fields; false when the name is not of that form.
bool parse_dataset_name(const std::string& s, std::string& var, std::int64_t& it, int& tl, int& map, int& rl, int& c) {
  std::istringstream in(s);
  if (!(in >> var) || var.find("::") == std::string::npos) return false;
  std::string tok;
  bool have_it = false, have_rl = false;
  tl = 0, map = 0, c = 0;
  while (in >> tok) {
    const auto eq = tok.find('=');
    if (eq == std::string::npos) return false;
    const std::string key = tok.substr(0, eq);
    long long value = 0;
    try {
      value = std::stoll(tok.substr(eq + 1));
    } catch (...) {
      return false;
    }
    if (key == "it") it = value, have_it = true;
    else if (key == "tl") tl = static_cast<int>(value);
    else if (key == "m") map = static_cast<int>(value);
    else if (key == "rl") rl = static_cast<int>(value), have_rl = true;
    else if (key == "c") c = static_cast<int>(value);
    else return false;
  }
  return have_it && have_rl;
}

// Carpet's parameter dump ("Parameters and Global Attributes/All Parameters", text or bytes),
// lower case; empty when the file has none.
std::string parameter_dump(hid_t file, const std::string& path) {
  const std::string group = "Parameters and Global Attributes";
  if (!h5::exists(file, group) || !h5::exists(file, group + "/All Parameters")) return "";
  std::string text;
  try {
    h5::Handle g(H5Gopen2(file, group.c_str(), H5P_DEFAULT), H5Gclose);
    text = h5::read_text_dataset(g, "All Parameters", path);
  } catch (const RunError&) {
    return "";
  }
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return text;
}

// A boolean Cactus parameter ("thorn::name = yes") of the dump; -1 when absent.
int dump_flag(const std::string& dump, const std::string& key) {
  const auto pos = dump.find(key);
  if (pos == std::string::npos) return -1;
  const auto eol = dump.find('\n', pos);
  const std::string line = dump.substr(pos, eol == std::string::npos ? std::string::npos : eol - pos);
  const auto eq = line.find('=');
  if (eq == std::string::npos) return -1;
  const std::string v = line.substr(eq + 1);
  if (v.find("yes") != std::string::npos || v.find("true") != std::string::npos || v.find('1') != std::string::npos) return 1;
  return 0;
}

// A file's output: its path less ".file_N.h5" (CarpetIOHDF5 writes one file per process group).
std::string output_stem(const std::string& path) {
  const auto p = path.rfind(".file_");
  return p == std::string::npos ? path : path.substr(0, p);
}

// Whether a file holds ghost points (Cactus dumps only parameters set away from their default,
// yes): CarpetIOHDF5's 3D slice output (out3D_vars, files "<var>.xyz[.file_N].h5") follows
// out3D_ghosts, its volume output (out_vars, "<var>[.file_N].h5") output_ghost_points; one run
// often writes both with different settings.
bool ghost_points_written(const std::string& dump, const std::string& path) {
  const std::string name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  const bool slice_3d = name.find(".xyz.") != std::string::npos;
  return dump_flag(dump, slice_3d ? "carpetiohdf5::out3d_ghosts" : "carpetiohdf5::output_ghost_points") != 0;
}

// Carpet's `active` attribute, a bboxset written as text ("bboxset<CCTK_INT4,3>(set<bbox>:{([lo]:
// [hi]:[stride]/...),...},...)", indices in units of the finest level's spacing), as inclusive
// boxes of component-local indices (the level index less iorigin); none when not of that form.
std::optional<std::vector<std::array<int, 6>>> parse_active(const std::string& text, const std::vector<long long>& iorigin) {
  std::vector<std::array<int, 6>> boxes;
  if (text.find("set<bbox>:{}") != std::string::npos) return boxes;  // the component owns no point
  std::size_t pos = 0;
  while ((pos = text.find("([", pos)) != std::string::npos) {
    long long v[9];
    char sep[9];
    std::istringstream in(text.substr(pos + 2));
    bool ok = true;
    for (int q = 0; q < 9 && ok; ++q) {
      ok = static_cast<bool>(in >> v[q] >> sep[q]);
      if (ok && q % 3 == 2 && q < 8) ok = in.get() == ':' && in.get() == '[';  // "]:[" between vectors
    }
    if (!ok) return std::nullopt;
    std::array<int, 6> b{};
    for (std::size_t a = 0; a < 3; ++a) {
      const long long stride = v[6 + a];
      if (stride <= 0 || v[a] % stride != 0 || v[3 + a] % stride != 0) return std::nullopt;
      b[a] = static_cast<int>(v[a] / stride - iorigin[a]);
      b[3 + a] = static_cast<int>(v[3 + a] / stride - iorigin[a]);
    }
    boxes.push_back(b);
    pos += 2;
  }
  if (boxes.empty()) return std::nullopt;
  return boxes;
}

std::string join_levels(const std::set<int>& s) {
  std::string out;
  for (auto x : s) out += (out.empty() ? "" : ", ") + std::to_string(x);
  return out;
}

std::string join(const std::set<std::int64_t>& s) {
  std::string out;
  for (auto x : s) out += (out.empty() ? "" : ", ") + std::to_string(x);
  return out;
}

}  // namespace

std::string canonical_carpet_name(const std::string& full) {
  const auto p = full.find("::");
  if (p == std::string::npos) return "";
  std::string thorn = full.substr(0, p), v = full.substr(p + 2);
  std::transform(thorn.begin(), thorn.end(), thorn.begin(), [](unsigned char ch) { return std::toupper(ch); });
  std::string lv = v;
  std::transform(lv.begin(), lv.end(), lv.begin(), [](unsigned char ch) { return std::tolower(ch); });
  if (thorn == "HYDROBASE") {
    if (lv == "rho" || lv == "press" || lv == "eps" || lv == "temperature") return lv;
    if (lv == "y_e") return "Ye";
    for (const char* vec : {"vel", "bvec"})
      for (int c = 0; c < 3; ++c)
        if (lv == std::string(vec) + "[" + std::to_string(c) + "]")
          return (std::string(vec) == "vel" ? "vel[" : "Bvec[") + std::to_string(c) + "]";
    return "";
  }
  if (thorn == "ADMBASE") {
    static const std::set<std::string> known{"alp", "betax", "betay", "betaz", "gxx", "gxy", "gxz", "gyy", "gyz", "gzz"};
    return known.count(lv) ? lv : "";
  }
  return "";
}

std::vector<std::string> expand_file_patterns(const std::vector<std::string>& patterns) {
  std::vector<std::string> out;
  for (const auto& p : patterns) {
    glob_t g{};
    const int rc = ::glob(p.c_str(), 0, nullptr, &g);
    if (rc != 0 || g.gl_pathc == 0) {
      ::globfree(&g);
      throw RunError("HandOff::files: '" + p + "' matches no file");
    }
    for (std::size_t i = 0; i < g.gl_pathc; ++i) out.emplace_back(g.gl_pathv[i]);
    ::globfree(&g);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

SourceData read_carpet(const CarpetOptions& opt) {
  if (opt.files.empty()) throw RunError("HandOff::files is empty: name the CarpetIOHDF5 files to read");
  // Index every dataset: variable -> iteration -> datasets.
  std::map<std::string, std::map<std::int64_t, std::vector<DatasetRef>>> index;
  std::array<bool, 3> refl = opt.reflection;
  bool ghosts_in_files = true;
  std::map<std::string, bool> ghosts_of_file;
  const std::set<std::string> wanted(opt.variables.begin(), opt.variables.end());
  // Parameter dumps: a file without one takes that of a file of the same output (the name less
  // ".file_N.h5"), else the first one found.
  std::map<std::string, std::string> dump_of, dump_of_output;
  std::string any_dump;
  for (const auto& file : opt.files) {
    h5::Handle f = h5::open_file(file);
    dump_of[file] = parameter_dump(f, file);
    if (dump_of[file].empty()) continue;
    dump_of_output.emplace(output_stem(file), dump_of[file]);
    if (any_dump.empty()) any_dump = dump_of[file];
  }
  for (auto& [file, dump] : dump_of)
    if (dump.empty()) dump = dump_of_output.count(output_stem(file)) ? dump_of_output.at(output_stem(file)) : any_dump;
  for (const auto& file : opt.files) {
    h5::Handle f = h5::open_file(file);
    const std::string& dump = dump_of.at(file);
    if (opt.reflection_from_file)
      for (int d = 0; d < 3; ++d)
        if (dump_flag(dump, std::string("reflectionsymmetry::reflection_") + static_cast<char>('x' + d)) == 1)
          refl[static_cast<std::size_t>(d)] = true;
    const bool ghosts = ghost_points_written(dump, file);
    ghosts_of_file[file] = ghosts;
    ghosts_in_files = ghosts_in_files && ghosts;
    for (const auto& name : h5::dataset_names(f)) {
      std::string var;
      std::int64_t it = 0;
      int tl = 0, map = 0, rl = 0, c = 0;
      if (!parse_dataset_name(name, var, it, tl, map, rl, c) || tl != 0) continue;
      const std::string canon = canonical_carpet_name(var);
      if (canon.empty() || !wanted.count(canon)) continue;
      if (map != 0)
        throw RunError("HandOff: " + file + ": dataset '" + name +
                       "' belongs to map " + std::to_string(map) + "; multi-patch (Llama) data is not supported");
      index[canon][it].push_back({file, name, rl, c});
    }
  }
  for (const auto& r : opt.required)
    if (!index.count(r))
      throw RunError("HandOff: the variable '" + r + "' is in none of the files of HandOff::files (" +
                     std::to_string(opt.files.size()) + " file(s), first " + opt.files.front() + ")");
  if (index.empty()) throw RunError("HandOff: no HydroBase or ADMBase variable in the files of HandOff::files");

  // The iteration: the latest that every variable has, or the one asked for (each must have it).
  std::int64_t it = opt.iteration;
  if (it < 0) {
    std::set<std::int64_t> common;
    bool first = true;
    // Iterations at which a variable has every refinement level it has anywhere: Carpet writes
    // finer levels alone at their intermediate steps, which would leave the coarse levels out.
    for (const auto& [v, its] : index) {
      std::set<int> all_levels;
      for (const auto& [i, refs] : its)
        for (const auto& r : refs) all_levels.insert(r.rl);
      std::set<std::int64_t> mine;
      for (const auto& [i, refs] : its) {
        std::set<int> levels;
        for (const auto& r : refs) levels.insert(r.rl);
        if (levels == all_levels) mine.insert(i);
      }
      if (first) common = mine, first = false;
      else {
        std::set<std::int64_t> both;
        std::set_intersection(common.begin(), common.end(), mine.begin(), mine.end(), std::inserter(both, both.end()));
        common = both;
      }
    }
    if (common.empty()) {
      std::string detail;
      for (const auto& [v, its] : index) {
        std::set<std::int64_t> mine;
        for (const auto& [i, refs] : its) mine.insert(i);
        detail += "\n  " + v + " (" + its.begin()->second.front().file + "): iterations " + join(mine);
      }
      throw RunError("HandOff: the variables share no iteration with all their refinement levels; set HandOff::iteration "
                     "to one they all have:" + detail);
    }
    it = *common.rbegin();
  }
  for (const auto& [v, its] : index)
    if (!its.count(it)) {
      std::set<std::int64_t> mine;
      for (const auto& [i, refs] : its) mine.insert(i);
      throw RunError("HandOff: " + its.begin()->second.front().file + ": variable '" + v + "' has no data at iteration " +
                     std::to_string(it) + " (it has iterations " + join(mine) + "); see HandOff::iteration");
    }

  for (const auto& [v, its] : index) {
    std::set<int> all_levels, here;
    for (const auto& [i, refs] : its)
      for (const auto& r : refs) (i == it ? here : all_levels).insert(r.rl), all_levels.insert(r.rl);
    if (here != all_levels)
      throw RunError("HandOff: " + its.at(it).front().file + ": variable '" + v + "' has refinement levels " + join_levels(here) +
                     " at iteration " + std::to_string(it) + " but levels " + join_levels(all_levels) +
                     " elsewhere (Carpet writes finer levels alone between coarse steps); choose another HandOff::iteration");
  }

  // Read the components and build the levels.
  LevelBuilder builder(refl, opt.buffer_zones, opt.axial_magnetic_field);
  SourceData out;
  out.format = "carpet";
  out.iteration = it;
  out.reflection = refl;
  bool have_time = false;
  for (const auto& [v, its] : index) {
    const auto& refs = its.at(it);
    out.file_of[v] = refs.front().file;
    for (const auto& r : refs) {
      h5::Handle f = h5::open_file(r.file);
      std::vector<hsize_t> shape;
      std::vector<double> data = h5::read_dataset(f, r.name, r.file, &shape);
      h5::Handle d(H5Dopen2(f, r.name.c_str(), H5P_DEFAULT), H5Dclose);
      const auto origin = h5::attr_doubles(d, "origin", r.file, r.name);
      const auto delta = h5::attr_doubles(d, "delta", r.file, r.name);
      std::vector<long long> ghosts{0, 0, 0};
      if (h5::has_attr(d, "cctk_nghostzones") && ghosts_of_file.at(r.file))
        ghosts = h5::attr_ints(d, "cctk_nghostzones", r.file, r.name);
      if (!have_time && h5::has_attr(d, "time")) out.time = h5::attr_doubles(d, "time", r.file, r.name).at(0), have_time = true;
      if (shape.size() != 3 || origin.size() != 3 || delta.size() != 3 || ghosts.size() != 3)
        throw RunError("HandOff: " + r.file + ": dataset '" + r.name + "' is not 3D data (HandOff reads 3D Carpet output)");
      Component comp;
      comp.level = r.rl;
      for (int a = 0; a < 3; ++a) {
        comp.origin[static_cast<std::size_t>(a)] = origin[static_cast<std::size_t>(a)];
        comp.delta[static_cast<std::size_t>(a)] = delta[static_cast<std::size_t>(a)];
        comp.ghosts[static_cast<std::size_t>(a)] = static_cast<int>(ghosts[static_cast<std::size_t>(a)]);
        comp.n[static_cast<std::size_t>(a)] = static_cast<int>(shape[static_cast<std::size_t>(2 - a)]);
      }
      if (h5::has_attr(d, "cctk_bbox")) {  // 1 on faces of the grid's outer (or symmetry) boundary
        const auto bbox = h5::attr_ints(d, "cctk_bbox", r.file, r.name);
        if (bbox.size() == 6)
          for (std::size_t q = 0; q < 6; ++q) comp.outer[q] = static_cast<int>(bbox[q]);
      }
      if (h5::has_attr(d, "active") && h5::has_attr(d, "iorigin")) {
        const auto io = h5::attr_ints(d, "iorigin", r.file, r.name);
        if (io.size() == 3) comp.active = parse_active(h5::attr_string(d, "active", r.file, r.name), io);
        out.active_regions = out.active_regions || comp.active.has_value();
      }
      comp.where = r.file + ": " + r.name;
      builder.add(v, std::move(comp), std::move(data));
    }
  }
  out.levels = builder.build();
  out.ghosts_in_files = ghosts_in_files;
  return out;
}

}  // namespace remnant::handoff
