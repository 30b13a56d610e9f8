#include "HandOff/remnant_reader.hpp"

#include "h5_read.hpp"
#include "level_builder.hpp"
#include "remnant/error.hpp"

namespace remnant::handoff {
namespace {

// A block's data on the next coarser level (x fastest): the 2^3-cell means (conserved variables and
// the metric, as the run's restriction), or the lowest child's value (primitives: the mean of p
// is not p_EOS of the means, and HandOff checks the data's p against the EOS).
std::vector<double> restrict_block(const std::vector<double>& v, const std::array<int, 3>& n, bool mean) {
  const std::array<int, 3> m{n[0] / 2, n[1] / 2, n[2] / 2};
  std::vector<double> out(static_cast<std::size_t>(m[0]) * static_cast<std::size_t>(m[1]) * static_cast<std::size_t>(m[2]), 0.0);
  for (int k = 0; k < 2 * m[2]; ++k)
    for (int j = 0; j < 2 * m[1]; ++j)
      for (int i = 0; i < 2 * m[0]; ++i)
        if (mean || (i % 2 == 0 && j % 2 == 0 && k % 2 == 0))
          out[static_cast<std::size_t>(i / 2 + m[0] * (j / 2 + m[1] * (k / 2)))] +=
              (mean ? 0.125 : 1.0) * v[static_cast<std::size_t>(i + n[0] * (j + n[1] * k))];
  return out;
}

}  // namespace

SourceData read_remnant_volume(const std::vector<std::string>& files, std::array<bool, 3> reflection, bool axial_magnetic_field) {
  if (files.size() != 1)
    throw RunError("HandOff::format = remnant reads one volume file (grid-volume.it*.h5); HandOff::files names " +
                   std::to_string(files.size()));
  const std::string& path = files.front();
  h5::Handle f = h5::open_file(path);
  const std::string format = h5::has_attr(f, "format") ? h5::attr_string(f, "format", path, "/") : "";
  if (format != "remnant-grid-1")
    throw RunError("HandOff: " + path + " is not Remnant grid output (attribute format = '" + format +
                   "', expected 'remnant-grid-1'); see HandOff::format");
  const std::string coords = h5::attr_string(f, "coordinates", path, "/");
  const long long dim = h5::attr_ints(f, "dimension", path, "/").at(0);
  const long long gdim = h5::attr_ints(f, "grid_dimension", path, "/").at(0);
  if (coords != "cartesian" || dim != 3 || gdim != 3)
    throw RunError("HandOff: " + path + " holds " + std::to_string(dim) + "D output of a " + std::to_string(gdim) + "D " + coords +
                   " grid; HandOff reads the volume output of 3D Cartesian runs");
  SourceData out;
  out.format = "remnant";
  out.iteration = h5::attr_ints(f, "iteration", path, "/").at(0);
  out.time = h5::attr_doubles(f, "time", path, "/").at(0);
  out.reflection = reflection;
  const auto cells = h5::attr_ints(f, "block_cells", path, "/");
  h5::Handle blocks(H5Gopen2(f, "blocks", H5P_DEFAULT), H5Gclose);
  h5::Handle data(H5Gopen2(f, "data", H5P_DEFAULT), H5Gclose);
  if (!blocks.ok() || !data.ok()) throw RunError("HandOff: " + path + ": no /blocks or /data group");
  const auto level = h5::read_dataset(blocks, "level", path);
  const auto lo = h5::read_dataset(blocks, "lo", path);
  const auto dx = h5::read_dataset(blocks, "dx", path);
  // Remnant dataset -> HandOff field; required ones must be in the file.
  struct Map {
    const char* dataset;
    const char* field;
    bool required;
    bool mean = false;  // restricted to coarser levels as 2^3 means (else a child's value)
  };
  static const Map maps[] = {
      {"HydroBase-prim.rho", "rho", true},     {"HydroBase-prim.eps", "eps", true},       {"HydroBase-prim.press", "press", false},
      {"HydroBase-prim.Ye", "Ye", false},      {"HydroBase-prim.temperature", "temperature", false},
      {"HydroBase-prim.vel1", "vel[0]", true}, {"HydroBase-prim.vel2", "vel[1]", true},   {"HydroBase-prim.vel3", "vel[2]", true},
      {"HydroBase-cons.D", "Dt", true, true},        {"HydroBase-cons.S1", "St[0]", true, true},      {"HydroBase-cons.S2", "St[1]", true, true},
      {"HydroBase-cons.S3", "St[2]", true, true},    {"HydroBase-cons.tau", "taut", true, true},      {"HydroBase-cons.DYe", "DYet", true, true},
      {"Spacetime-metric.psi", "psi", true, true},   {"Spacetime-metric.alpha", "alp", false, true},
      {"HydroBase-Bvec.B1", "Bvec[0]", false, true}, {"HydroBase-Bvec.B2", "Bvec[1]", false, true},
      {"HydroBase-Bvec.B3", "Bvec[2]", false, true}};
  LevelBuilder builder(reflection, 0, axial_magnetic_field);
  const std::size_t nb = level.size(), per = static_cast<std::size_t>(cells[0] * cells[1] * cells[2]);
  for (const auto& m : maps) {
    if (!h5::exists(data, m.dataset)) {
      if (m.required)
        throw RunError("HandOff: " + path + ": no dataset /data/" + m.dataset +
                       "; write HydroBase::prim, HydroBase::cons and Spacetime::metric (IO::hdf5_variables) in the 3D run");
      continue;
    }
    const auto values = h5::read_dataset(data, m.dataset, path);
    if (values.size() != nb * per) throw RunError("HandOff: " + path + ": /data/" + m.dataset + " does not match /blocks");
    out.file_of[m.field] = path;
    for (std::size_t b = 0; b < nb; ++b) {
      Component c;
      c.level = static_cast<int>(level[b]);
      for (std::size_t a = 0; a < 3; ++a) {
        c.delta[a] = dx[3 * b + a];
        c.origin[a] = lo[3 * b + a] + 0.5 * c.delta[a];
        c.n[a] = static_cast<int>(cells[a]);
      }
      c.where = path + ": block " + std::to_string(b);
      std::vector<double> v(values.begin() + static_cast<std::ptrdiff_t>(b * per), values.begin() + static_cast<std::ptrdiff_t>((b + 1) * per));
      // The file holds the mesh's leaves only: a coarser level has no points under a finer block,
      // so between a fine block's outermost centres and the coarse ones (half a spacing of each)
      // neither level could interpolate (the cells there got no data). The block's restriction
      // (2^3 means, as the run's own restriction) fills the coarser levels beneath it; the
      // integrals count each point on its finest level only (owned_by_finer).
      Component coarse = c;
      std::vector<double> cv = v;
      builder.add(m.field, std::move(c), std::move(v));
      while (coarse.level > 0 && coarse.n[0] % 2 == 0 && coarse.n[1] % 2 == 0 && coarse.n[2] % 2 == 0) {
        cv = restrict_block(cv, coarse.n, m.mean);
        coarse.level -= 1;
        for (std::size_t a = 0; a < 3; ++a) {
          coarse.origin[a] += 0.5 * coarse.delta[a];  // the first coarse centre: the corner of two fine cells
          coarse.delta[a] *= 2, coarse.n[a] /= 2;
        }
        coarse.where = path + ": block " + std::to_string(b) + " restricted to level " + std::to_string(coarse.level);
        builder.add(m.field, coarse, cv);
      }
    }
  }
  out.levels = builder.build();
  // The conformally flat 3-metric of the run.
  for (auto& L : out.levels) {
    auto& psi = L.fields.at("psi");
    std::vector<double> g(L.size());
    for (std::size_t q = 0; q < L.size(); ++q) g[q] = psi[q] * psi[q] * psi[q] * psi[q];
    L.fields["gxx"] = g, L.fields["gyy"] = g, L.fields["gzz"] = g;
    L.fields["gxy"].assign(L.size(), 0.0), L.fields["gxz"].assign(L.size(), 0.0), L.fields["gyz"].assign(L.size(), 0.0);
    L.fields.erase("psi");
  }
  return out;
}

}  // namespace remnant::handoff
