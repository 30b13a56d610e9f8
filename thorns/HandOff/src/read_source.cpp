#include "read_source.hpp"

#include <array>
#include <cmath>

#include "EOS/eos.hpp"
#include "HandOff/carpet_reader.hpp"
#include "HandOff/remnant_reader.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "magnetic_source.hpp"
#include "remnant/error.hpp"
#include "remnant/parameters.hpp"
#include "source_quantities.hpp"

namespace remnant::handoff {
namespace {

// A magnetic field in the data: an error unless the user lets HandOff drop it.
void check_magnetic_field(const Context& ctx, SourceData& src, std::vector<std::string>& notes) {
  double bmax = 0;
  for (const auto& L : src.levels)
    for (int c = 0; c < 3; ++c) {
      auto it = L.fields.find("Bvec[" + std::to_string(c) + "]");
      if (it == L.fields.end()) continue;
      for (std::size_t q = 0; q < L.size(); ++q)
        if (L.valid[q]) bmax = std::max(bmax, std::abs(it->second[q]));
    }
  const bool evolved = hydrobase::magnetic_field_evolved(ctx);
  if (evolved && !ctx.param<bool>("HandOff", "ignore_magnetic_field")) {
    if (!has_magnetic_field(src) && bmax > 0)
      throw RunError("HandOff: the data hold only some components of HydroBase::Bvec; all three are needed");
    if (!has_magnetic_field(src))
      notes.push_back("no HydroBase::Bvec[0..2] in the data: the run's magnetic field starts from zero");
    return;  // imported (magnetic_import.hpp)
  }
  if (bmax > 0 && !ctx.param<bool>("HandOff", "ignore_magnetic_field")) {
    std::string file = "the data";
    for (int c = 2; c >= 0; --c)
      if (src.file_of.count("Bvec[" + std::to_string(c) + "]")) file = src.file_of.at("Bvec[" + std::to_string(c) + "]");
    throw RunError("HandOff: " + file + ": the data hold a magnetic field (HydroBase::Bvec, max |B| = " + std::to_string(bmax) +
                   "), but this run evolves none (HydroBase::magnetic_field = none): set HydroBase::magnetic_field = "
                   "evolved to import it, or HandOff::ignore_magnetic_field = true to hand off the fluid alone");
  }
  if (bmax > 0) notes.push_back("the data's magnetic field (max |B| = " + std::to_string(bmax) + ") is dropped (HandOff::ignore_magnetic_field)");
  for (auto& L : src.levels)
    for (int c = 0; c < 3; ++c) L.fields.erase("Bvec[" + std::to_string(c) + "]");
}

}  // namespace

std::array<bool, 3> reflection_parameter(const Parameters& p) {
  std::array<bool, 3> mirrors{false, false, false};
  for (const auto& r : p.get<std::vector<std::string>>("HandOff", "reflection")) mirrors[static_cast<std::size_t>(r[0] - 'x')] = true;
  return mirrors;
}

void check_centre_on_mirrors(const Parameters& p, const std::array<bool, 3>& mirrors, const std::array<bool, 3>& from_files) {
  const auto& centre = p.get<std::vector<double>>("HandOff", "centre");
  for (std::size_t d = 0; d < 3; ++d) {
    if (!mirrors[d] || centre[d] == 0) continue;
    const std::string axis(1, static_cast<char>('x' + d));
    const std::string mirror_from = from_files[d] ? "ReflectionSymmetry::reflection_" + axis + " in the files' parameter dump"
                                                  : "HandOff::reflection";
    throw InputError(p.origin("HandOff", "centre"),
                     "HandOff::centre = [" + format_number(centre[0]) + ", " + format_number(centre[1]) + ", " +
                         format_number(centre[2]) + "] has " + axis + " = " + format_number(centre[d]) +
                         ", but the data are mirrored across " + axis + " = 0 (" + mirror_from +
                         "): unfolded they are symmetric about that plane, so their centre lies on it; allowed: HandOff::centre[" +
                         std::to_string(d) + "] = 0 along the mirrored axis " + axis + " (any value along an axis without a mirror)");
  }
}

std::shared_ptr<SourceData> read_source(const Context& ctx, std::vector<std::string>& notes) {
  const auto files = expand_file_patterns(ctx.param<std::vector<std::string>>("HandOff", "files"));
  const auto& format = ctx.param<std::string>("HandOff", "format");
  const auto& parity = ctx.param<std::string>("HandOff", "magnetic_parity");
  auto src = std::make_shared<SourceData>();
  const std::array<bool, 3> mirrors = reflection_parameter(ctx.params());
  if (format == "carpet") {
    CarpetOptions o;
    o.files = files;
    o.iteration = ctx.param<std::int64_t>("HandOff", "iteration");
    o.variables = {"rho", "press", "eps", "temperature", "Ye", "vel[0]", "vel[1]", "vel[2]", "Bvec[0]", "Bvec[1]", "Bvec[2]",
                   "alp", "gxx", "gxy", "gxz", "gyy", "gyz", "gzz"};
    o.required = {"rho"};
    o.reflection = mirrors;
    o.buffer_zones = static_cast<int>(ctx.param<std::int64_t>("HandOff", "buffer_zones"));
    o.axial_magnetic_field = parity != "vector";  // auto: the Einstein Toolkit's Bvec is a pseudo-vector
    *src = read_carpet(o);
    if (src->active_regions)
      notes.push_back("each component's own points are its `active` region (Carpet's attribute): ghost, buffer and symmetry "
                      "points are dropped, HandOff::buffer_zones is not used for such components");
  } else {
    *src = read_remnant_volume(files, mirrors, parity != "vector");
  }
  // The remnant's centre onto the grid's origin (after unfolding: mirrors are the data's x^d = 0).
  std::array<bool, 3> mirrors_from_files{};
  for (std::size_t d = 0; d < 3; ++d) mirrors_from_files[d] = src->reflection[d] && !mirrors[d];
  check_centre_on_mirrors(ctx.params(), src->reflection, mirrors_from_files);
  const auto& centre = ctx.param<std::vector<double>>("HandOff", "centre");
  if (centre[0] != 0 || centre[1] != 0 || centre[2] != 0) {
    for (auto& L : src->levels)
      for (std::size_t d = 0; d < 3; ++d) L.origin[d] -= centre[d];
    notes.push_back("the data's point (" + format_number(centre[0], 6) + ", " + format_number(centre[1], 6) + ", " +
                    format_number(centre[2], 6) + ") is placed at the grid's origin (HandOff::centre)");
  }
  check_magnetic_field(ctx, *src, notes);
  MissingPolicy policy;
  policy.from_eos = ctx.param<std::string>("HandOff", "missing_variables") == "from_eos";
  policy.ye = ctx.param<double>("HandOff", "ye");
  policy.eos_tolerance = ctx.param<double>("HandOff", "eos_tolerance");
  src->has_metric = src->has("gxx");
  src->has_lapse = src->has("alp");
  for (auto& n : complete_source(*src, ctx.service<eos::EOS>("eos"), policy)) notes.push_back(std::move(n));
  const bool magnetic = has_magnetic_field(*src);
  if (magnetic) add_magnetic_source(*src);
  for (auto& n : add_conserved(*src)) notes.push_back(std::move(n));
  // Only what the hand-off samples stays in memory (every rank holds all the data).
  for (auto& L : src->levels)
    for (const char* f : {"press", "temperature", "gxx", "gxy", "gxz", "gyy", "gyz", "gzz", "Bvec[0]", "Bvec[1]", "Bvec[2]"})
      L.fields.erase(f);
  return src;
}

}  // namespace remnant::handoff
