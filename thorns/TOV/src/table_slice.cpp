#include "TOV/table_slice.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "EOS/beta_equilibrium.hpp"

namespace remnant::tov {
namespace {

// The state a cell of the evolution sees: Ye from beta equilibrium at (rho, T_min) and eps, p from the
// table's own (trilinear) interpolation at (rho, T_min, Ye), so that the temperature the evolution
// recovers from eps is T_min and its p(rho, T, Ye) is the star's p. Only the enthalpy-density
// relation H(rho) comes from the sampled slice (a smooth quadrature, sampled on every table interval
// with the nodes included: the interpolated table has kinks there).
class TableColdSlice final : public ColdSlice {
 public:
  TableColdSlice(const eos::Tabulated<>& table, std::unique_ptr<ColdSlice> sampled)
      : table_(table), sampled_(std::move(sampled)) {}
  ColdState at(double H) const override { return exact(sampled_->at(H).rho); }
  double log_enthalpy(double rho) const override { return sampled_->log_enthalpy(rho); }

 private:
  ColdState exact(double rho) const {
    const double T = table_.bounds().T_min;
    const double ye = eos::beta_equilibrium_ye(table_, rho, T).ye;
    const eos::Thermo th = table_.thermo(rho, T, ye);
    return {rho, th.eps, th.press, ye};
  }
  const eos::Tabulated<>& table_;
  std::unique_ptr<ColdSlice> sampled_;
};

}  // namespace

std::unique_ptr<ColdSlice> cold_beta_slice(const eos::Tabulated<>& table, int points_per_interval) {
  const auto& b = table.bounds();
  const eos::Axis& a = table.table().lrho;
  if (a.n < 2) throw std::runtime_error(table.table().file + ": TOV needs a table with at least 2 densities");
  std::vector<double> rhos;
  std::vector<std::size_t> nodes;  // the segments between table nodes
  for (int i = 0; i + 1 < a.n; ++i) {
    nodes.push_back(rhos.size());
    for (int k = 0; k < points_per_interval; ++k) rhos.push_back(std::exp(a.node(i) + a.dx * k / points_per_interval));
  }
  rhos.front() = b.rho_min;  // exp(log(x)) may round outside the table
  rhos.push_back(b.rho_max);
  const eos::BetaSlice s = eos::beta_equilibrium_slice(table, b.T_min, rhos);
  return std::make_unique<TableColdSlice>(table, tabulated_slice_segments(s.rho, s.press, s.eps, s.ye, nodes));
}

}  // namespace remnant::tov
