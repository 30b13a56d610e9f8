// Builds the EOS handle from a configuration (the thorn parameters or the command line).
#include <sstream>

#include "EOS/eos.hpp"

namespace remnant::eos {

EOS make_eos(const EosConfig& cfg) {
  Bounds b;
  b.rho_min = cfg.rho_min;
  b.rho_max = cfg.rho_max;
  b.T_max = cfg.T_max;
  if (cfg.type == "ideal_gas") return EOS(IdealGas<>(cfg.gamma, cfg.baryon_mass_MeV, b));
  if (cfg.type == "polytrope")
    return EOS(Polytrope<>(PiecewisePolytrope(cfg.poly_K, cfg.poly_gammas, cfg.poly_rho_bounds), b));
  if (cfg.type == "hybrid")
    return EOS(Hybrid<>(PiecewisePolytrope(cfg.poly_K, cfg.poly_gammas, cfg.poly_rho_bounds), cfg.gamma_th,
                        cfg.baryon_mass_MeV, b));
  if (cfg.type == "tabulated") {
    if (cfg.table_file.empty()) throw EosError("EOS type 'tabulated' needs a table file");
    return EOS(Tabulated<>(load_table(cfg.table_file, cfg.read)));
  }
  throw EosError("unknown EOS type '" + cfg.type + "' (ideal_gas, polytrope, hybrid, tabulated)");
}

std::string EOS::describe() const {
  std::ostringstream o;
  o.precision(6);
  std::visit(
      [&](const auto& e) {
        using E = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<E, IdealGas<>>) o << "ideal gas, Gamma = " << e.gamma();
        else if constexpr (std::is_same_v<E, Polytrope<>>) o << "cold polytrope, " << e.cold().gammas().size() << " piece(s)";
        else if constexpr (std::is_same_v<E, Hybrid<>>)
          o << "hybrid, " << e.cold().gammas().size() << " cold piece(s), Gamma_th = " << e.gamma_th();
        else
          o << "tabulated (" << e.table().format << ") " << e.table().file << ", " << e.table().lrho.n << " x "
            << e.table().lT.n << " x " << e.table().ye.n << " (rho x T x Ye), " << e.table().report.warnings()
            << " warning(s)";
      },
      v_);
  return o.str();
}

}  // namespace remnant::eos
