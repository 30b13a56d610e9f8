#include "HydroBase/sweeps.hpp"

#include <algorithm>
#include <cstdio>

#include "Con2Prim/error_policy.hpp"
#include "Con2Prim/prim_to_cons.hpp"
#include "Con2Prim/recover.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::hydrobase {
namespace {

using Prim = vars::HydroBase::prim;
using Cons = vars::HydroBase::cons;
using Metric = vars::Spacetime::metric;

// gamma_ij = psi^4 f_ii at a cell centre, in the form con2prim takes.
con2prim::Metric3 cell_metric(double psi4, const std::array<double, 3>& f) {
  const double a = psi4 * f[0], b = psi4 * f[1], c = psi4 * f[2];
  return con2prim::Metric3::from_lower_and_inverse({a, 0, 0, b, 0, c}, {1 / a, 0, 0, 1 / b, 0, 1 / c}, a * b * c);
}

// The variables of one block, as Fields addressed by one offset o = i + j sj + k sk (every group
// here is cell-centred with the same ghosts, so one offset serves all).
struct CellAccess {
  Field prim[Prim::ncomp], met[Metric::ncomp], cons[Cons::ncomp];
  Field bvec[3];
  bool magnetic = false;
  CellAccess(const MatterGroups& g, Block& b) {
    magnetic = g.bvec >= 0;
    if (magnetic)
      for (int q = 0; q < 3; ++q) bvec[q] = b.field(g.bvec, q);
    const Prim p(b, g.prim);
    const Metric m(b, g.metric);
    const Cons c(b, g.cons);
    for (int q = 0; q < Prim::ncomp; ++q) prim[q] = p.field(q);
    for (int q = 0; q < Metric::ncomp; ++q) met[q] = m.field(q);
    for (int q = 0; q < Cons::ncomp; ++q) cons[q] = c.field(q);
  }
  void store_prim(std::ptrdiff_t o, const con2prim::Primitives& p) const {
    prim[Prim::idx::rho].origin[o] = p.rho;
    for (int c = 0; c < 3; ++c) prim[Prim::idx::vel + c].origin[o] = p.v[c];
    prim[Prim::idx::eps].origin[o] = p.eps;
    prim[Prim::idx::press].origin[o] = p.press;
    prim[Prim::idx::temperature].origin[o] = p.T;
    prim[Prim::idx::Ye].origin[o] = p.ye;
    prim[Prim::idx::W].origin[o] = p.W;
    prim[Prim::idx::cs2].origin[o] = p.cs2;
  }
  void store_cons(std::ptrdiff_t o, const con2prim::Conserved& c, double psi6) const {
    cons[Cons::idx::D].origin[o] = psi6 * c.D;
    for (int i = 0; i < 3; ++i) cons[Cons::idx::S + i].origin[o] = psi6 * c.S[i];
    cons[Cons::idx::tau].origin[o] = psi6 * c.tau;
    cons[Cons::idx::DYe].origin[o] = psi6 * c.DYe;
  }
  con2prim::Conserved load_cons(std::ptrdiff_t o, double ipsi6) const {
    con2prim::Conserved c;
    c.D = cons[Cons::idx::D].origin[o] * ipsi6;
    for (int i = 0; i < 3; ++i) c.S[i] = cons[Cons::idx::S + i].origin[o] * ipsi6;
    c.tau = cons[Cons::idx::tau].origin[o] * ipsi6;
    c.DYe = cons[Cons::idx::DYe].origin[o] * ipsi6;
    if (magnetic) c.B = field(o);
    return c;
  }
  // B^i of the cell (zero without field).
  con2prim::Vec3 field(std::ptrdiff_t o) const {
    if (!magnetic) return {0, 0, 0};
    return {bvec[0].origin[o], bvec[1].origin[o], bvec[2].origin[o]};
  }
};

// The magnetisation cap of the atmosphere (Atmosphere::limit_magnetisation): an atmosphere cell
// (v = 0, so b^2 = B^i B_i) whose field exceeds sigma_max rho gets the larger rho, p, eps, cs2 from
// the EOS at (rho, T_atm, Ye_atm), and its conserved variables. Returns whether it changed.
template <class E>
bool cap_atmosphere_magnetisation(const E& eos, const atmosphere::Atmosphere& atm, const con2prim::Metric3& m,
                                  con2prim::Primitives& p, con2prim::Conserved& c) {
  if (p.rho != atm.rho || !atm.limit_magnetisation(p, m.norm2_up(p.B))) return false;
  const eos::Thermo th = eos.thermo(p.rho, p.T, p.ye);
  p.press = th.press;
  p.eps = th.eps;
  p.cs2 = th.cs2;
  c = con2prim::prim_to_cons(p, m);
  return true;
}

template <class F>
void for_cells(Block& b, const CellAccess& acc, F&& f) {
  const bool cartesian = b.coordinates == CoordinateSystem::cartesian;
  const PolarTrig trig(b);
  std::array<double, 3> fd{1, 1, 1};
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        const std::ptrdiff_t o = i + j * acc.met[0].sj + k * acc.met[0].sk;
        if (!cartesian) fd = coords::metric_diagonal(b.coordinates, cell_point(b, i, j, k), trig.sin_centre(j));
        const double psi = acc.met[Metric::idx::psi].origin[o], p2 = psi * psi;
        f(o, p2 * p2, p2 * p2 * p2, fd);
      }
}

template <class E>
void recover_impl(const E& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm, const MatterGroups& g,
                  Block& b, con2prim::Diagnostics& diag, std::string& fatal_cell) {
  const CellAccess acc(g, b);
  // The mass budget's source component, where the caller has the group (a stand-alone block may not).
  double* const source = g.budget >= 0 ? b.field(g.budget, vars::HydroBase::mass_budget::idx::source).origin : nullptr;
  for_cells(b, acc, [&](std::ptrdiff_t o, double psi4, double psi6, const std::array<double, 3>& fd) {
    con2prim::Conserved c = acc.load_cons(o, 1.0 / psi6);
    con2prim::Primitives p;
    p.T = acc.prim[Prim::idx::temperature].origin[o];
    const con2prim::Metric3 m = cell_metric(psi4, fd);
    // The cell's T from the last recovery starts the table's T search (cost only, not the root).
    const con2prim::Report r = con2prim::recover(eos, s, atm, m, c, p, p.T);
    diag.add(r);
    if (acc.magnetic) cap_atmosphere_magnetisation(eos, atm, m, p, c);
    if (r.fatal() && fatal_cell.empty()) {
      const std::ptrdiff_t i = o % acc.met[0].sj, j = (o / acc.met[0].sj) % (acc.met[0].sk / acc.met[0].sj),
                           k = o / acc.met[0].sk;
      char m[400];
      std::snprintf(m, sizeof m, "block %lld cell (%td,%td,%td) at (%g, %g, %g): D=%g S=(%g,%g,%g) tau=%g -> rho=%g eps=%g T=%g W=%g rules=0x%x",
                    static_cast<long long>(b.gid), i, j, k, b.x(0, int(i)), b.x(1, int(j)), b.x(2, int(k)), c.D,
                    c.S[0], c.S[1], c.S[2], c.tau, p.rho, p.eps, p.T, p.W, r.rules);
      fatal_cell = m;
    }
    acc.store_prim(o, p);
    const double D_before = acc.cons[0].origin[o];
    acc.store_cons(o, c, psi6);
    // What the atmosphere and the policy added to D (mass budget, see mass_budget.hpp).
    if (source) source[o] += acc.cons[0].origin[o] - D_before;
  });
}

template <class E>
void prim_to_cons_impl(const E& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm,
                       const MatterGroups& g, Block& b,
                       con2prim::Diagnostics& diag, double* max_sigma) {
  const CellAccess acc(g, b);
  for_cells(b, acc, [&](std::ptrdiff_t o, double psi4, double psi6, const std::array<double, 3>& fd) {
    con2prim::Primitives p;
    p.rho = acc.prim[Prim::idx::rho].origin[o];
    for (int i = 0; i < 3; ++i) p.v[i] = acc.prim[Prim::idx::vel + i].origin[o];
    p.eps = acc.prim[Prim::idx::eps].origin[o];
    p.ye = acc.prim[Prim::idx::Ye].origin[o];
    p.T = acc.prim[Prim::idx::temperature].origin[o];
    p.B = acc.field(o);
    const con2prim::Metric3 m = cell_metric(psi4, fd);
    if (atm.is_atmosphere(p.rho)) {
      atm.set(p);
      if (acc.magnetic) {
        con2prim::Conserved unused;
        cap_atmosphere_magnetisation(eos, atm, m, p, unused);
      }
    } else {
      p.W = 1.0 / std::sqrt(1.0 - m.norm2_up(p.v));
      if (max_sigma) *max_sigma = std::max(*max_sigma, con2prim::b_squared(p, m) / p.rho);
      diag.add_rules(con2prim::apply_error_policy(eos, s.policy, p, con2prim::ThermoInput::eps));
      const eos::Thermo th = eos.thermo(p.rho, p.T, p.ye);
      p.press = th.press;
      p.cs2 = th.cs2;
      p.eps = th.eps;
    }
    acc.store_prim(o, p);
    acc.store_cons(o, con2prim::prim_to_cons(p, m), psi6);
  });
}

}  // namespace

void recover_block(const eos::EOS& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm,
                   const MatterGroups& g, Block& b, con2prim::Diagnostics& diag, std::string& fatal_cell) {
  eos.visit([&](const auto& e) { recover_impl(e, s, atm, g, b, diag, fatal_cell); });
}

void prim_to_cons_block(const eos::EOS& eos, const con2prim::Settings& s, const atmosphere::Atmosphere& atm,
                        const MatterGroups& g, Block& b, con2prim::Diagnostics& diag, double* max_sigma) {
  eos.visit([&](const auto& e) { prim_to_cons_impl(e, s, atm, g, b, diag, max_sigma); });
}

}  // namespace remnant::hydrobase
