#pragma once
// The EOS handle that thorns share: a std::variant of the concrete EOS types. Dispatch once per
// loop (eos.visit([&](const auto& e) { for (cells) e.thermo(...); })), never per cell.
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "EOS/hybrid.hpp"
#include "EOS/ideal_gas.hpp"
#include "EOS/polytrope.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"

namespace remnant::eos {

template <class Counter = NoCount>
using AnyEOS = std::variant<IdealGas<Counter>, Polytrope<Counter>, Hybrid<Counter>, Tabulated<Counter>>;

class EOS {
 public:
  template <class E>
  explicit EOS(E e) : v_(std::move(e)) {}
  template <class F>
  decltype(auto) visit(F&& f) const { return std::visit(std::forward<F>(f), v_); }
  const AnyEOS<>& variant() const { return v_; }
  const Bounds& bounds() const {
    return visit([](const auto& e) -> const Bounds& { return e.bounds(); });
  }
  bool is_tabulated() const { return std::holds_alternative<Tabulated<>>(v_); }
  const Tabulated<>* tabulated() const { return std::get_if<Tabulated<>>(&v_); }
  std::string describe() const;

 private:
  AnyEOS<> v_;
};

// Everything needed to build an EOS (the thorn parameters map onto this).
struct EosConfig {
  std::string type = "ideal_gas";  // ideal_gas | polytrope | hybrid | tabulated
  double gamma = 2.0;              // ideal gas
  double baryon_mass_MeV = units::neutron_mass_MeV;
  double poly_K = 100.0;                      // polytrope / hybrid: K of the first piece (code units)
  std::vector<double> poly_gammas{2.0};       // one per piece
  std::vector<double> poly_rho_bounds;        // n-1 divisions (code units)
  double gamma_th = 1.75;                     // hybrid
  double rho_min = 1e-20, rho_max = 1.0;      // analytic validity range (code units)
  double T_max = 1e3;                         // analytic, MeV
  std::string table_file;
  ReadOptions read;
};

EOS make_eos(const EosConfig& cfg);

}  // namespace remnant::eos
