#include "compose_common.hpp"

#include <algorithm>
#include <cmath>

#include "EOS/units.hpp"

namespace remnant::eos::detail {

RawTable compose_to_raw(ComposeGrid g, const ReadOptions& opts, const std::string& format) {
  RawTable raw;
  raw.file = g.file;
  raw.format = format;
  raw.rho_dataset = format == "CompOSE ASCII" ? "eos.nb" : "nb";
  raw.T_dataset = format == "CompOSE ASCII" ? "eos.t" : "t";
  raw.ye_dataset = format == "CompOSE ASCII" ? "eos.yq" : "yq";
  const double mn = g.m_n;
  // Mass density uses the neutron mass as the baryon mass (the StellarCollapse convention).
  for (double n : g.nb) raw.rho.push_back(n * mn * units::MeV_fm3_mass_to_code_rho);
  raw.T = g.T;
  raw.ye = g.yq;
  const std::size_t nr = g.nb.size(), n = raw.size();
  auto name = [&](int k) {
    return g.thermo_dataset == "Q" ? "Q" + std::to_string(k) : g.thermo_dataset + " Q" + std::to_string(k);
  };
  raw.press = {name(1), std::vector<double>(n)};
  raw.entropy = {name(2), g.Q[1]};
  raw.eps = {name(7), g.Q[6]};
  raw.mu_n = {name(3), std::vector<double>(n)};
  raw.mu_p = {name(4), std::vector<double>(n)};
  raw.mu_e = {name(5), std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const double nb = g.nb[i % nr];
    raw.press.v[i] = g.Q[0][i] * nb * units::MeV_fm3_to_code_press;
    raw.mu_n.v[i] = g.Q[2][i] * mn;
    raw.mu_p.v[i] = (g.Q[2][i] + g.Q[3][i]) * mn;
    raw.mu_e.v[i] = (opts.compose_mu_e == ComposeElectronMu::mu_l ? g.Q[4][i] : g.Q[4][i] - g.Q[3][i]) * mn;
  }
  raw.eps_shift = opts.eps_shift;
  if (!g.cs2.empty()) {
    raw.cs2 = {g.cs2_dataset, std::move(g.cs2)};
  } else {
    cs2_from_differences(raw);
  }
  auto opt = [](RawField& f, std::vector<double>& v, const char* ds) {
    if (!v.empty()) f = {ds, std::move(v)};
  };
  opt(raw.Xa, g.Xa, "Y[He4]");
  opt(raw.Xh, g.Xh, "Y[N]");
  opt(raw.Xn, g.Xn, "Y[n]");
  opt(raw.Xp, g.Xp, "Y[p]");
  opt(raw.Abar, g.Abar, "A[N]");
  opt(raw.Zbar, g.Zbar, "Z[N]");
  return raw;
}

void cs2_from_differences(RawTable& raw) {
  const int nr = int(raw.rho.size()), nt = int(raw.T.size()), ny = int(raw.ye.size());
  raw.cs2 = {raw.eps.dataset + " (cs2 from finite differences of p, eps)", std::vector<double>(raw.size())};
  const auto& p = raw.press.v;
  const auto& e = raw.eps.v;
  // Differencing ln p is far more accurate on coarse grids (p is close to a power law).
  const bool logp = std::all_of(p.begin(), p.end(), [](double x) { return x > 0; });
  std::vector<double> q(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) q[i] = logp ? std::log(p[i]) : p[i];
  auto idx = [&](int ir, int it, int iy) { return (std::size_t(iy) * nt + it) * nr + ir; };
  // Derivative along one axis of ln-coordinate x: centred inside, one-sided at the ends.
  auto diff = [](const std::vector<double>& f, const std::vector<double>& x, std::size_t i0, std::size_t stride,
                 int k, int n) {
    if (n < 2) return 0.0;
    int a = k > 0 ? k - 1 : k, b = k < n - 1 ? k + 1 : k;
    return (f[i0 + (b - k) * stride] - f[i0 - (k - a) * stride]) / (std::log(x[b]) - std::log(x[a]));
  };
  for (int iy = 0; iy < ny; ++iy)
    for (int it = 0; it < nt; ++it)
      for (int ir = 0; ir < nr; ++ir) {
        const std::size_t i = idx(ir, it, iy);
        const double rho = raw.rho[ir];
        const double dp = logp ? p[i] : 1.0;  // d p = p d ln p
        const double px = dp * diff(q, raw.rho, i, 1, ir, nr), ex = diff(e, raw.rho, i, 1, ir, nr);
        const double h = 1 + e[i] + p[i] / rho;
        double c;
        if (nt < 2) {
          c = px / rho / h;  // cold 1-D table: barotropic
        } else {
          const double py = dp * diff(q, raw.T, i, nr, it, nt), ey = diff(e, raw.T, i, nr, it, nt);
          c = ((px - py * ex / ey) / rho + p[i] / (rho * rho) * (py / ey)) / h;
        }
        raw.cs2.v[i] = c;
      }
}

}  // namespace remnant::eos::detail
