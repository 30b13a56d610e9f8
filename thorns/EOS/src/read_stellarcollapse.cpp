// StellarCollapse HDF5 tables (O'Connor & Ott 2010 layout): 3-D datasets [Ye][T][rho], axes
// logrho (log10 g/cm^3), logtemp (log10 MeV), ye; logpress (log10 dyn/cm^2);
// logenergy = log10(eps + energy_shift) with eps in erg/g; cs2 in cm^2/s^2.
#include <cmath>

#include "EOS/errors.hpp"
#include "EOS/readers.hpp"
#include "EOS/units.hpp"
#include "hdf5_file.hpp"

namespace remnant::eos {

RawTable read_stellarcollapse(const std::string& path, const ReadOptions& opts) {
  detail::H5File f(path);
  RawTable raw;
  raw.file = path;
  raw.format = "StellarCollapse HDF5";

  auto axis = [&](const char* name) {
    auto dims = f.shape(name);
    if (dims.size() != 1) throw TableError(path, name, "axis must be one-dimensional");
    return f.read(name);
  };
  std::vector<double> logrho = axis("logrho"), logtemp = axis("logtemp");
  raw.ye = axis("ye");
  const hsize_t nr = logrho.size(), nt = logtemp.size(), ny = raw.ye.size();
  // The points* scalars, where present, must agree with the axes.
  for (auto [name, n] : {std::pair{"pointsrho", nr}, {"pointstemp", nt}, {"pointsye", ny}}) {
    if (f.has(name) && f.scalar(name) != double(n))
      throw TableError(path, name, "says " + std::to_string(f.scalar(name)) + " points but the axis has " +
                                       std::to_string(n));
  }
  for (double x : logrho) raw.rho.push_back(std::pow(10.0, x) * units::rho_cgs_to_code);
  for (double x : logtemp) raw.T.push_back(std::pow(10.0, x));

  const std::vector<hsize_t> shape{ny, nt, nr};
  const double shift_cgs = f.scalar("energy_shift");
  auto logpress = f.read("logpress", shape);
  auto logenergy = f.read("logenergy", shape);
  auto cs2 = f.read("cs2", shape);
  const std::size_t n = logpress.size();

  raw.press = {"logpress", std::vector<double>(n)};
  raw.eps = {"logenergy", std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    raw.press.v[i] = std::pow(10.0, logpress[i]) * units::press_cgs_to_code;
    raw.eps.v[i] = (std::pow(10.0, logenergy[i]) - shift_cgs) * units::eps_cgs_to_code;
  }
  raw.eps_shift = opts.eps_shift >= 0 ? opts.eps_shift : shift_cgs * units::eps_cgs_to_code;

  Cs2Convention conv = opts.sc_cs2;
  if (conv == Cs2Convention::from_file) {
    conv = opts.sc_cs2_default;
    if (f.has("have_rel_cs2"))
      conv = f.scalar("have_rel_cs2") != 0 ? Cs2Convention::relativistic : Cs2Convention::newtonian;
  }
  raw.cs2 = {"cs2", std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    double c = cs2[i] * units::cs2_cgs_to_code;
    if (conv == Cs2Convention::newtonian) {
      const std::size_t ir = i % nr;
      const double h = 1 + raw.eps.v[i] + raw.press.v[i] / raw.rho[ir];
      c /= h;
    }
    raw.cs2.v[i] = c;
  }

  // Abar and Zbar may be stored as integers (nucleon numbers); all else must be floating point.
  auto optional = [&](RawField& field, const char* name, bool allow_integer = false) {
    if (f.has(name)) field = {name, f.read(name, shape, allow_integer)};
  };
  optional(raw.entropy, "entropy");
  optional(raw.mu_e, "mu_e");
  optional(raw.mu_p, "mu_p");
  optional(raw.mu_n, "mu_n");
  optional(raw.Xa, "Xa");
  optional(raw.Xh, "Xh");
  optional(raw.Xn, "Xn");
  optional(raw.Xp, "Xp");
  optional(raw.Abar, "Abar", true);
  optional(raw.Zbar, "Zbar", true);
  return raw;
}

}  // namespace remnant::eos
