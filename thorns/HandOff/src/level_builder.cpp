#include "level_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "remnant/error.hpp"

namespace remnant::handoff {
namespace {

constexpr double kLatticeTolerance = 1e-6;  // in units of the spacing

long long lattice_index(double x, double lo, double dx, const std::string& where) {
  const double s = (x - lo) / dx;
  const long long i = std::llround(s);
  if (std::abs(s - static_cast<double>(i)) > kLatticeTolerance)
    throw RunError("HandOff: " + where + ": the component's points are not on its refinement level's lattice");
  return i;
}

// Mirrors a level across x^d = 0: nodes at x^d < 0 take the data of their images times the parity.
void unfold(SourceLevel& L, int d, bool axial_magnetic_field) {
  const auto ud = static_cast<std::size_t>(d);
  const double s2 = 2 * L.origin[ud] / L.delta[ud];
  const long long two_s = std::llround(s2);
  if (std::abs(s2 - static_cast<double>(two_s)) > kLatticeTolerance)
    throw RunError("HandOff: the reflection plane " + std::string(1, static_cast<char>('x' + d)) +
                   " = 0 lies neither on nor half-way between the points of refinement level " + std::to_string(L.level));
  const long long N = L.n[ud];
  const long long lo = std::min<long long>(0, -(N - 1) - two_s), hi = std::max<long long>(N - 1, -two_s);
  SourceLevel U;
  U.level = L.level;
  U.delta = L.delta;
  U.origin = L.origin;
  U.origin[ud] = L.origin[ud] + static_cast<double>(lo) * L.delta[ud];
  U.n = L.n;
  U.n[ud] = static_cast<int>(hi - lo + 1);
  U.valid.assign(U.size(), 0);
  for (const auto& [name, v] : L.fields) U.fields[name].assign(U.size(), std::numeric_limits<double>::quiet_NaN());
  std::map<std::string, double> parity;
  for (const auto& [name, v] : L.fields) parity[name] = reflection_parity(name, d, axial_magnetic_field);
  for (int k = 0; k < U.n[2]; ++k)
    for (int j = 0; j < U.n[1]; ++j)
      for (int i = 0; i < U.n[0]; ++i) {
        std::array<long long, 3> m{i, j, k};
        m[ud] += lo;  // index in L's lattice
        const double x = L.origin[ud] + static_cast<double>(m[ud]) * L.delta[ud];
        double sign = 1;
        if (x < -kLatticeTolerance * L.delta[ud]) m[ud] = -m[ud] - two_s, sign = -1;
        if (m[ud] < 0 || m[ud] >= N) continue;
        const int mi = static_cast<int>(m[0]), mj = static_cast<int>(m[1]), mk = static_cast<int>(m[2]);
        if (!L.is_valid(mi, mj, mk)) continue;
        const std::size_t to = U.index(i, j, k), from = L.index(mi, mj, mk);
        U.valid[to] = 1;
        for (auto& [name, v] : U.fields) v[to] = L.fields.at(name)[from] * (sign < 0 ? parity[name] : 1.0);
      }
  L = std::move(U);
}

// Crops a level to the bounding box of its valid points (ghost and buffer extents go).
void crop(SourceLevel& L) {
  std::array<int, 3> lo{L.n[0], L.n[1], L.n[2]}, hi{-1, -1, -1};
  for (int k = 0; k < L.n[2]; ++k)
    for (int j = 0; j < L.n[1]; ++j)
      for (int i = 0; i < L.n[0]; ++i)
        if (L.valid[L.index(i, j, k)]) {
          const std::array<int, 3> m{i, j, k};
          for (std::size_t a = 0; a < 3; ++a) lo[a] = std::min(lo[a], m[a]), hi[a] = std::max(hi[a], m[a]);
        }
  if (hi[0] < 0) throw RunError("HandOff: refinement level " + std::to_string(L.level) + " has no point outside ghost zones");
  SourceLevel C;
  C.level = L.level;
  C.delta = L.delta;
  for (std::size_t a = 0; a < 3; ++a) C.origin[a] = L.origin[a] + lo[a] * L.delta[a], C.n[a] = hi[a] - lo[a] + 1;
  C.valid.assign(C.size(), 0);
  for (const auto& [name, v] : L.fields) C.fields[name].resize(C.size());
  for (int k = 0; k < C.n[2]; ++k)
    for (int j = 0; j < C.n[1]; ++j)
      for (int i = 0; i < C.n[0]; ++i) {
        const std::size_t to = C.index(i, j, k), from = L.index(i + lo[0], j + lo[1], k + lo[2]);
        C.valid[to] = L.valid[from];
        for (auto& [name, v] : C.fields) v[to] = L.fields.at(name)[from];
      }
  L = std::move(C);
}

}  // namespace

void LevelBuilder::add(const std::string& variable, Component c, std::vector<double> data) {
  const std::size_t expect = static_cast<std::size_t>(c.n[0]) * static_cast<std::size_t>(c.n[1]) * static_cast<std::size_t>(c.n[2]);
  if (data.size() != expect) throw RunError("HandOff: " + c.where + ": the data's size does not match its shape");
  for (int a = 0; a < 3; ++a)
    if (!(c.delta[static_cast<std::size_t>(a)] > 0)) throw RunError("HandOff: " + c.where + ": the spacing 'delta' is not positive");
  pieces_[c.level][variable].push_back({std::move(c), std::move(data)});
}

std::vector<SourceLevel> LevelBuilder::build() const {
  std::vector<SourceLevel> levels;
  if (pieces_.empty()) return levels;
  const int coarsest = pieces_.begin()->first;
  for (const auto& [lev, vars] : pieces_) {
    // The level's lattice: the union of every variable's components.
    const Component& ref = vars.begin()->second.front().c;
    std::array<double, 3> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (const auto& [v, ps] : vars)
      for (const auto& p : ps)
        for (std::size_t a = 0; a < 3; ++a) {
          if (std::abs(p.c.delta[a] / ref.delta[a] - 1) > 1e-10)
            throw RunError("HandOff: " + p.c.where + ": the spacing differs from other components of refinement level " +
                           std::to_string(lev) + " (" + ref.where + ")");
          lo[a] = std::min(lo[a], p.c.origin[a]);
          hi[a] = std::max(hi[a], p.c.origin[a] + (p.c.n[a] - 1) * p.c.delta[a]);
        }
    SourceLevel L;
    L.level = lev;
    L.origin = lo;
    L.delta = ref.delta;
    for (std::size_t a = 0; a < 3; ++a) L.n[a] = static_cast<int>(lattice_index(hi[a], lo[a], ref.delta[a], ref.where) + 1);
    L.valid.assign(L.size(), 1);
    for (const auto& [v, ps] : vars) {
      auto& f = L.fields[v];
      f.assign(L.size(), std::numeric_limits<double>::quiet_NaN());
      std::vector<std::uint8_t> mine(L.size(), 0);
      for (const auto& p : ps) {
        std::array<long long, 3> off;
        std::array<int, 3> first, last;  // kept component-local points
        for (std::size_t a = 0; a < 3; ++a) {
          off[a] = lattice_index(p.c.origin[a], lo[a], L.delta[a], p.c.where);
          const bool at_lower = off[a] == 0, at_upper = off[a] + p.c.n[a] == L.n[a];
          const bool outer_level = lev == coarsest;
          // Points a face loses: none on the grid's outer boundary (cctk_bbox, else the coarsest
          // level's edge); the ghosts elsewhere, and the buffer zones on a refined level's edge.
          auto strip = [&](int side, bool at_edge) {
            const int known = p.c.outer[2 * a + static_cast<std::size_t>(side)];
            const bool outer = known >= 0 ? known == 1 : outer_level && at_edge;
            if (outer) return 0;
            return p.c.ghosts[a] + (at_edge && !outer_level ? buffer_ : 0);
          };
          // A lower face reaching below a reflection plane: its symmetry ghosts go by position.
          const bool symmetry_face = reflection_[a] && p.c.origin[a] < -kLatticeTolerance * L.delta[a];
          const bool active_region = p.c.active.has_value();  // Carpet's `active` boxes decide
          first[a] = symmetry_face || active_region ? 0 : strip(0, at_lower);
          last[a] = p.c.n[a] - 1 - (active_region ? 0 : strip(1, at_upper));
        }
        auto owned = [&p](const std::array<int, 3>& m) {
          if (!p.c.active) return true;
          for (const auto& b : *p.c.active)
            if (m[0] >= b[0] && m[1] >= b[1] && m[2] >= b[2] && m[0] <= b[3] && m[1] <= b[4] && m[2] <= b[5]) return true;
          return false;
        };
        for (int k = first[2]; k <= last[2]; ++k)
          for (int j = first[1]; j <= last[1]; ++j)
            for (int i = first[0]; i <= last[0]; ++i) {
              const std::array<int, 3> ijk{i, j, k};
              bool keep = owned(ijk);
              for (std::size_t a = 0; a < 3; ++a)
                if (reflection_[a] && p.c.origin[a] + ijk[a] * L.delta[a] < -kLatticeTolerance * L.delta[a]) keep = false;
              if (!keep) continue;
              const std::size_t to = L.index(static_cast<int>(off[0] + i), static_cast<int>(off[1] + j), static_cast<int>(off[2] + k));
              const std::size_t from = static_cast<std::size_t>(i) + static_cast<std::size_t>(p.c.n[0]) *
                                                                     (static_cast<std::size_t>(j) + static_cast<std::size_t>(p.c.n[1]) * static_cast<std::size_t>(k));
              f[to] = p.data[from];
              mine[to] = 1;
            }
      }
      for (std::size_t q = 0; q < L.size(); ++q) L.valid[q] &= mine[q];
    }
    crop(L);
    for (int d = 0; d < 3; ++d)
      if (reflection_[static_cast<std::size_t>(d)]) unfold(L, d, axial_magnetic_field_);
    levels.push_back(std::move(L));
  }
  return levels;
}

}  // namespace remnant::handoff
