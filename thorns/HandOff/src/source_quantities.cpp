#include "source_quantities.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "magnetic_source.hpp"
#include "point_metric.hpp"
#include "remnant/error.hpp"
#include "remnant/parameters.hpp"

namespace remnant::handoff {
namespace {

std::string num(double x) { return format_number(x); }

std::string where(const SourceLevel& L, std::size_t q) {
  const int i = static_cast<int>(q % static_cast<std::size_t>(L.n[0]));
  const int j = static_cast<int>((q / static_cast<std::size_t>(L.n[0])) % static_cast<std::size_t>(L.n[1]));
  const int k = static_cast<int>(q / (static_cast<std::size_t>(L.n[0]) * static_cast<std::size_t>(L.n[1])));
  return "(x, y, z) = (" + num(L.x(0, i)) + ", " + num(L.x(1, j)) + ", " + num(L.x(2, k)) + ") on refinement level " +
         std::to_string(L.level);
}

std::string file_of(const SourceData& s, const std::string& v) {
  auto it = s.file_of.find(v);
  return it == s.file_of.end() ? std::string("the data") : it->second;
}

void require(const SourceData& s, const std::string& v, const MissingPolicy& p, const std::string& instead) {
  if (!s.has(v) && !p.from_eos)
    throw RunError("HandOff: the data (" + file_of(s, "rho") + (s.file_of.size() > 1 ? " and others" : "") +
                   ") have no variable '" + v + "' and HandOff::missing_variables = error (with from_eos: " + instead + ")");
}

}  // namespace

std::vector<std::string> complete_source(SourceData& src, const eos::EOS& eos, const MissingPolicy& policy) {
  std::vector<std::string> notes;
  if (!src.has("rho")) throw RunError("HandOff: the data have no rest-mass density 'rho' (HydroBase::rho)");
  int nvel = 0;
  for (int c = 0; c < 3; ++c) nvel += src.has("vel[" + std::to_string(c) + "]");
  if (nvel != 0 && nvel != 3) throw RunError("HandOff: the data hold only some components of HydroBase::vel; all three are needed");
  require(src, "vel[0]", policy, "the fluid is at rest");
  require(src, "Ye", policy, "Ye = HandOff::ye");
  if (!src.has("eps") && !src.has("temperature") && !src.has("press"))
    require(src, "eps", policy, "eps of the EOS at its lowest temperature");
  if (nvel == 0) notes.push_back("no HydroBase::vel in the data: the fluid is at rest");
  if (!src.has("Ye")) notes.push_back("no HydroBase::Y_e in the data: Ye = " + num(policy.ye) + " (HandOff::ye)");
  const bool had_ye = src.has("Ye");
  const bool had_eps = src.has("eps"), had_T = src.has("temperature"), had_p = src.has("press");
  if (!had_eps)
    notes.push_back(had_T ? "no HydroBase::eps in the data: eps = eps_EOS(rho, T, Ye)"
                    : had_p ? "no HydroBase::eps in the data: eps from the EOS with p_EOS(rho, eps, Ye) = press"
                            : "no HydroBase::eps, temperature or press in the data: eps = eps_EOS(rho, T_min, Ye) (cold)");
  if (!had_p) notes.push_back("no HydroBase::press in the data: press = p_EOS(rho, eps, Ye)");
  const eos::Bounds& bounds = eos.bounds();
  double rho_max = 0;
  for (const auto& L : src.levels)
    for (std::size_t q = 0; q < L.size(); ++q)
      if (L.valid[q]) rho_max = std::max(rho_max, L.fields.at("rho")[q]);
  for (auto& L : src.levels) {
    const std::size_t n = L.size();
    auto& rho = L.fields.at("rho");
    if (nvel == 0)
      for (int c = 0; c < 3; ++c) L.fields["vel[" + std::to_string(c) + "]"].assign(n, 0.0);
    if (!had_ye) L.fields["Ye"].assign(n, policy.ye);
    auto& ye = L.fields.at("Ye");
    std::vector<double>* T = had_T ? &L.fields.at("temperature") : nullptr;
    auto& eps = L.fields["eps"];
    if (!had_eps) eps.assign(n, 0.0);
    auto& press = L.fields["press"];
    if (!had_p) press.assign(n, 0.0);
    eos.visit([&](const auto& e) {
      for (std::size_t q = 0; q < n; ++q) {
        if (!L.valid[q] || !(rho[q] > 0)) continue;
        const double r = std::clamp(rho[q], bounds.rho_min, bounds.rho_max);
        if (!had_eps) {
          if (had_T) {
            eps[q] = e.thermo(r, std::clamp((*T)[q], bounds.T_min, bounds.T_max), ye[q]).eps;
          } else if (had_p) {  // p is monotone in T at fixed rho and Ye: bisection
            double a = bounds.T_min, b = std::isfinite(bounds.T_max) ? bounds.T_max : 1e3;
            for (int it = 0; it < 200 && b - a > 1e-14 * (1 + b); ++it) {
              const double m = 0.5 * (a + b);
              (e.thermo(r, m, ye[q]).press < press[q] ? a : b) = m;
            }
            eps[q] = e.thermo(r, 0.5 * (a + b), ye[q]).eps;
          } else {
            eps[q] = e.thermo(r, bounds.T_min, ye[q]).eps;
          }
        }
        double Tg = T ? (*T)[q] : 0.0;
        const double p_eos = e.thermo_from_eps(r, eps[q], ye[q], Tg).press;
        if (!had_p) {
          press[q] = p_eos;
        } else if (policy.eos_tolerance > 0 && rho[q] > 1e-6 * rho_max) {
          const double dev = std::abs(press[q] / p_eos - 1);
          if (!(dev <= policy.eos_tolerance))
            throw RunError("HandOff: " + file_of(src, "press") + ": the variable 'press' = " + num(press[q]) +
                           " disagrees with the EOS, p(rho = " + num(rho[q]) + ", eps = " + num(eps[q]) + ", Ye = " +
                           num(ye[q]) + ") = " + num(p_eos) + ", by " + num(100 * dev) + " % at " + where(L, q) +
                           " (HandOff::eos_tolerance = " + num(policy.eos_tolerance) + "): is EOS:: the data's EOS?");
        }
        if (had_p) press[q] = p_eos;  // the target's EOS decides the conserved energy
      }
    });
  }
  return notes;
}

std::vector<std::string> add_conserved(SourceData& src) {
  std::vector<std::string> notes;
  const bool metric = has_metric_fields(src);
  if (!metric) notes.push_back("no ADMBase::gxx..gzz in the data: a flat 3-metric densitises the conserved variables");
  if (!src.has("alp")) notes.push_back("no ADMBase::alp in the data: the lapse is not compared");
  const bool have_cons = src.has("Dt"), have_lapse = src.has("alp");
  const bool magnetic = has_magnetic_field(src);
  for (auto& L : src.levels) {
    const std::size_t n = L.size();
    const auto& rho = L.fields.at("rho");
    const auto& eps = L.fields.at("eps");
    const auto& press = L.fields.at("press");
    const auto& ye = L.fields.at("Ye");
    const double* v[3] = {L.fields.at("vel[0]").data(), L.fields.at("vel[1]").data(), L.fields.at("vel[2]").data()};
    const LevelMetric g(L, metric);
    const double* B[3] = {};
    if (magnetic)
      for (int a = 0; a < 3; ++a) B[a] = L.fields.at("Bvec[" + std::to_string(a) + "]").data();
    auto& gamma13 = L.fields["gamma13"];
    gamma13.assign(n, 1.0);
    if (!have_lapse) L.fields["alp"].assign(n, 1.0);
    std::vector<double>* out[6] = {};
    if (!have_cons)
      for (int c = 0; c < 6; ++c) {
        out[c] = &L.fields[conserved_fields()[static_cast<std::size_t>(c)]];
        out[c]->assign(n, 0.0);
      }
    for (std::size_t q = 0; q < n; ++q) {
      if (!L.valid[q]) continue;
      const auto [m, det] = metric_at(g, q);
      if (!(det > 0)) throw RunError("HandOff: the 3-metric (ADMBase::gxx..gzz) is not positive definite at " + where(L, q));
      gamma13[q] = std::cbrt(det);
      if (have_cons) continue;
      double vl[3] = {0, 0, 0}, v2 = 0;
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) vl[a] += m[a][b] * v[b][q];
        v2 += vl[a] * v[a][q];
      }
      if (!(v2 < 1))
        throw RunError("HandOff: " + file_of(src, "vel[0]") + ": HydroBase::vel is not slower than light (v^2 = " + num(v2) +
                       ") at " + where(L, q));
      if (!(rho[q] > 0)) continue;
      const double sg = std::sqrt(det), W = 1 / std::sqrt(1 - v2);
      const double h = 1 + eps[q] + press[q] / rho[q];
      const double D = sg * rho[q] * W, z = rho[q] * h * W * W;
      // The magnetic terms (Con2Prim's prim_to_cons): S_i = (z + B^2) v_i - (B.v) B_i,
      // tau = z - p + B^2 (1 + v^2) / 2 - (B.v)^2 / 2 - D.
      double Bl[3] = {0, 0, 0}, B2 = 0, Bv = 0;
      if (magnetic)
        for (int a = 0; a < 3; ++a) {
          for (int b = 0; b < 3; ++b) Bl[a] += m[a][b] * B[b][q];
          B2 += Bl[a] * B[a][q], Bv += Bl[a] * v[a][q];
        }
      (*out[0])[q] = D;
      for (int a = 0; a < 3; ++a) (*out[1 + a])[q] = sg * ((z + B2) * vl[a] - Bv * Bl[a]);
      (*out[4])[q] = sg * (z - press[q] + 0.5 * B2 * (1 + v2) - 0.5 * Bv * Bv) - D;
      (*out[5])[q] = D * ye[q];
    }
  }
  return notes;
}

}  // namespace remnant::handoff
