#include "source_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace remnant::handoff {
namespace {

// True when a finer level than l has a valid point within half its spacing of X.
bool owned_by_finer(const SourceData& src, std::size_t l, const Point3& X) {
  for (std::size_t f = l + 1; f < src.levels.size(); ++f) {
    const SourceLevel& F = src.levels[f];
    int idx[3];
    bool inside = true;
    for (std::size_t a = 0; a < 3 && inside; ++a) {
      const double t = (X[a] - F.origin[a]) / F.delta[a];
      idx[a] = static_cast<int>(std::lround(t));
      inside = std::abs(t - idx[a]) <= 0.5 + 1e-9;
    }
    if (inside && F.is_valid(idx[0], idx[1], idx[2])) return true;
  }
  return false;
}

void add(Integrals& s, double w, double D, double Sx, double Sy, double tau, const Point3& X, double em, double emt, bool matter) {
  if (matter) s.matter_rest_mass += w * D;
  s.magnetic_energy += w * em;
  s.magnetic_energy_toroidal += w * emt;
  s.rest_mass += w * D;
  s.angular_momentum += w * (X[0] * Sy - X[1] * Sx);
  s.energy += w * (tau + D);
}

}  // namespace

double smallest_density(const SourceData& src) {
  double m = std::numeric_limits<double>::infinity();
  for (const SourceLevel& L : src.levels) {
    const auto& rho = L.fields.at("rho");
    for (std::size_t q = 0; q < L.size(); ++q)
      if (L.valid[q]) m = std::min(m, rho[q]);
  }
  return std::isfinite(m) ? m : 0.0;
}

SourceIntegrals integrate_source(const SourceData& src, const TargetDomain& target, double atmosphere_rho) {
  SourceIntegrals out;
  out.atmosphere_rho = atmosphere_rho;
  out.rho_min = smallest_density(src);
  for (std::size_t l = 0; l < src.levels.size(); ++l) {
    const SourceLevel& L = src.levels[l];
    const double h = L.delta[0], dV = L.delta[0] * L.delta[1] * L.delta[2];
    const auto& D = L.fields.at("Dt");
    const auto& Sx = L.fields.at("St[0]");
    const auto& Sy = L.fields.at("St[1]");
    const auto& tau = L.fields.at("taut");
    const auto& rho = L.fields.at("rho");
    const auto em_it = L.fields.find("Emag"), emt_it = L.fields.find("Emagtor");
    const double* em = em_it == L.fields.end() ? nullptr : em_it->second.data();
    const double* emt = emt_it == L.fields.end() ? nullptr : emt_it->second.data();
    for (int k = 0; k < L.n[2]; ++k)
      for (int j = 0; j < L.n[1]; ++j)
        for (int i = 0; i < L.n[0]; ++i) {
          const std::size_t q = L.index(i, j, k);
          if (!L.valid[q]) continue;
          const Point3 X{L.x(0, i), L.x(1, j), L.x(2, k)};
          if (owned_by_finer(src, l, X)) continue;
          const double e = em ? em[q] : 0.0, et = emt ? emt[q] : 0.0;
          const bool matter = rho[q] > atmosphere_rho;
          add(out.all, dV, D[q], Sx[q], Sy[q], tau[q], X, e, et, matter);
          if (target.contains(target.fold(X))) add(out.covered, dV, D[q], Sx[q], Sy[q], tau[q], X, e, et, matter);
          const double f = target.fraction_inside(X, h);
          if (f > 0) add(out.grid, f * dV, D[q], Sx[q], Sy[q], tau[q], X, e, et, matter);
        }
  }
  return out;
}

}  // namespace remnant::handoff
