#pragma once
// One 3D Cartesian block holding a static TOV star (octant, centre at the corner), with its metric
// and primitives filled everywhere (ghosts too: the star is static, no exchange needed), for kernel
// benchmarks: a full RK3 step is 3 x (con2prim, fluxes, divergence + sources, RK update).
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "Atmosphere/make_atmosphere.hpp"
#include "Con2Prim/settings.hpp"
#include "EOS/beta_equilibrium.hpp"
#include "EOS/eos.hpp"
#include "TOV/tov_solver.hpp"
#include "GRMHD/valencia.hpp"
#include "HydroBase/sweeps.hpp"
#include "remnant/grid.hpp"
#include "remnant/thorn_spec.hpp"
#include "groups.hpp"
#include "rhs.hpp"

namespace remnant::grmhd::bench {

class StarBlock {
 public:
  StarBlock(eos::EOS eos, int n, double extent) : eos_(std::move(eos)) {
    // The groups as the thorns declare them (thorn.yaml), not a copy of their layout.
    for (const char* thorn : {"HydroBase", "Spacetime", "GRMHD"}) {
      const std::string path = std::string(REMNANT_SOURCE_DIR) + "/thorns/" + thorn + "/thorn.yaml";
      std::ifstream in(path);
      std::stringstream text;
      text << in.rdbuf();
      for (VariableGroupSpec spec : parse_thorn_spec(text.str(), path).variables) {
        spec.thorn = thorn;
        vars_.add(spec);
      }
    }
    g_.cons = vars_.find("HydroBase::cons");
    g_.cons_rhs = vars_.find("HydroBase::cons_rhs");
    g_.prim = vars_.find("HydroBase::prim");
    g_.metric = vars_.find("Spacetime::metric");
    g_.flux = {vars_.find("GRMHD::flux_x"), vars_.find("GRMHD::flux_y"), vars_.find("GRMHD::flux_z")};
    matter_ = {g_.cons, g_.prim, g_.metric};
    const double dx = extent / n;
    block_ = std::make_unique<Block>(0, 0, std::array<std::int64_t, 3>{0, 0, 0}, std::array<int, 3>{n, n, n},
                                     std::array<int, 3>{3, 3, 3}, std::array<double, 3>{0, 0, 0},
                                     std::array<double, 3>{dx, dx, dx}, vars_);
    atmosphere::AtmosphereConfig ac;
    ac.rho_thr = 1e-10;
    atm_ = eos_.visit([&](const auto& e) { return atmosphere::make_atmosphere(e, ac); });
    fill_star();
    u0_.resize(block_->size(g_.cons));
  }

  Block& block() { return *block_; }
  std::int64_t cells() const { return std::int64_t(block_->n[0]) * block_->n[1] * block_->n[2]; }

  // One SSP-RK3 step with time step dt, con2prim after every substep (3 per step, as the paper).
  void step(double dt) {
    Block& b = *block_;
    const double* u = b.data(g_.cons);
    std::copy(u, u + b.size(g_.cons), u0_.begin());
    static constexpr double a[3] = {0.0, 0.75, 1.0 / 3.0}, w[3] = {1.0, 0.25, 2.0 / 3.0};
    for (int s = 0; s < 3; ++s) {
      fluxes();
      divergence();
      for (int c = 0; c < kNumCons; ++c) {
        Field uc = b.field(g_.cons, c), r = b.field(g_.cons_rhs, c);
        const std::ptrdiff_t off = uc.origin - b.data(g_.cons);
        for_interior(b, [&](int i, int j, int k) {
          double& x = uc(i, j, k);
          x = a[s] * u0_[std::size_t(off + i + j * uc.sj + k * uc.sk)] + w[s] * (x + dt * r(i, j, k));
        });
      }
      recover();
    }
  }
  void recover() {
    std::string fatal;
    hydrobase::recover_block(eos_, settings_, atm_, matter_, *block_, diag_, fatal);
  }
  void fluxes() { compute_block_fluxes(eos_, rhs_settings_, g_, *block_); }
  void divergence() { compute_block_rhs(g_, *block_); }
  const con2prim::Diagnostics& diagnostics() const { return diag_; }

 private:
  void fill_star() {
    std::unique_ptr<tov::ColdSlice> slice;
    if (const auto* t = eos_.tabulated()) {
      const auto& bd = t->bounds();
      std::vector<double> rhos;
      for (int i = 0; i < 600; ++i) rhos.push_back(bd.rho_min * std::pow(bd.rho_max / bd.rho_min, i / 599.0));
      rhos.back() = bd.rho_max;
      const eos::BetaSlice s = eos::beta_equilibrium_slice(*t, bd.T_min, rhos);
      slice = tov::tabulated_slice(s.rho, s.press, s.eps, s.ye);
    } else {
      slice = tov::polytrope_slice(100, 2, 0.5);
    }
    const tov::TovStar star(*slice, 1.28e-3);
    Block& b = *block_;
    for (int k = -3; k < b.n[2] + 3; ++k)
      for (int j = -3; j < b.n[1] + 3; ++j)
        for (int i = -3; i < b.n[0] + 3; ++i) {
          const double x = b.x(0, i), y = b.x(1, j), z = b.x(2, k);
          const tov::TovPoint p = star.at(std::sqrt(x * x + y * y + z * z));
          b.field(g_.metric, Metric::idx::psi)(i, j, k) = p.psi;
          b.field(g_.metric, Metric::idx::alpha)(i, j, k) = p.alpha;
          const bool in = p.rho > atm_.rho_thr;
          b.field(g_.prim, Prim::idx::rho)(i, j, k) = in ? p.rho : atm_.rho;
          b.field(g_.prim, Prim::idx::eps)(i, j, k) = in ? p.eps : atm_.eps;
          b.field(g_.prim, Prim::idx::Ye)(i, j, k) = in ? p.ye : atm_.ye;
          b.field(g_.prim, Prim::idx::temperature)(i, j, k) = 0;
          b.field(g_.prim, Prim::idx::W)(i, j, k) = 1;
        }
    // Consistent T, p, cs2 everywhere via the initial-data path on a block with zero ghosts? The
    // sweep covers the interior; fill the ghosts with the same EOS calls.
    eos_.visit([&](const auto& e) {
      for (int k = -3; k < b.n[2] + 3; ++k)
        for (int j = -3; j < b.n[1] + 3; ++j)
          for (int i = -3; i < b.n[0] + 3; ++i) {
            const double rho = b.field(g_.prim, Prim::idx::rho)(i, j, k), eps = b.field(g_.prim, Prim::idx::eps)(i, j, k);
            const double ye = b.field(g_.prim, Prim::idx::Ye)(i, j, k);
            const auto inv = e.temperature(rho, eps, ye);
            const auto th = e.thermo(rho, inv.T, ye);
            b.field(g_.prim, Prim::idx::temperature)(i, j, k) = inv.T;
            b.field(g_.prim, Prim::idx::press)(i, j, k) = th.press;
            b.field(g_.prim, Prim::idx::eps)(i, j, k) = th.eps;
            b.field(g_.prim, Prim::idx::cs2)(i, j, k) = th.cs2;
          }
    });
    con2prim::Diagnostics d;
    hydrobase::prim_to_cons_block(eos_, settings_, atm_, matter_, b, d);
  }

  eos::EOS eos_;
  VariableRegistry vars_;
  Groups g_;
  hydrobase::MatterGroups matter_;
  std::unique_ptr<Block> block_;
  atmosphere::Atmosphere atm_;
  con2prim::Settings settings_;
  RhsSettings rhs_settings_;
  con2prim::Diagnostics diag_;
  std::vector<double> u0_;
};

}  // namespace remnant::grmhd::bench
