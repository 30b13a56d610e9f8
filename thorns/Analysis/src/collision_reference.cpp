#include "Analysis/collision_reference.hpp"

#include <mpi.h>

#include <array>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace remnant::analysis {
namespace {

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream s(line);
  std::string field;
  while (std::getline(s, field, '\t')) out.push_back(field);
  return out;
}

}  // namespace

std::optional<CollisionReference> collision_reference_from_tsv(std::istream& in) {
  std::map<std::string, std::size_t> column;
  std::vector<std::string> first, last;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      const std::size_t start = line.find_first_not_of("# ");
      if (start == std::string::npos) continue;
      const std::vector<std::string> names = split_tabs(line.substr(start));
      if (names.empty() || names[0] != "iteration") continue;
      column.clear();
      for (std::size_t c = 0; c < names.size(); ++c) column[names[c]] = c;
      continue;
    }
    std::vector<std::string> row = split_tabs(line);
    if (row.size() != column.size()) continue;  // a row of another header, or cut short by a crash
    if (first.empty()) first = row;
    last = std::move(row);
  }
  for (const char* name : {"time", "rho_max", "rho_max_point", "quad_dI"})
    if (!column.count(name)) return std::nullopt;
  if (first.empty()) return std::nullopt;
  const auto value = [&](const std::vector<std::string>& row, const char* name) {
    return std::strtod(row[column.at(name)].c_str(), nullptr);
  };
  CollisionReference r;
  r.rho_max = value(first, "rho_max");
  r.rho_max_point = value(first, "rho_max_point");
  r.has_previous = true;
  r.previous_time = value(last, "time");
  r.previous_quad_dI = value(last, "quad_dI");
  return r;
}

std::optional<CollisionReference> resumed_collision_reference(const Context& ctx, const std::string& path) {
  std::array<double, 6> packed{};  // found, rho_max, rho_max_point, has_previous, time, quad_dI
  if (ctx.rank() == 0) {
    std::ifstream in(path);
    if (const auto r = in ? collision_reference_from_tsv(in) : std::nullopt)
      packed = {1.0, r->rho_max, r->rho_max_point, r->has_previous ? 1.0 : 0.0, r->previous_time, r->previous_quad_dI};
  }
  MPI_Bcast(packed.data(), static_cast<int>(packed.size()), MPI_DOUBLE, 0, ctx.comm());
  if (packed[0] == 0.0) {
    ctx.info("Analysis: recovered without earlier collision rows in " + path +
             ": rho_max_norm and rho_max_point_norm are relative to this run's first row, h_plus starts at 0");
    return std::nullopt;
  }
  return CollisionReference{packed[1], packed[2], packed[3] != 0.0, packed[4], packed[5]};
}

}  // namespace remnant::analysis
