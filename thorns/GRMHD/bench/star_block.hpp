#pragma once
// One 3D Cartesian block holding a static TOV star (octant, centre at the corner), with its metric
// and primitives filled everywhere (ghosts too: the star is static, no exchange needed), for kernel
// benchmarks: a full RK3 step is 3 x (con2prim, fluxes, divergence + sources, RK update).
#include <cstdint>
#include <memory>
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
#include "HydroBase/magnetic_field.hpp"
#include "../test/kernel_block.hpp"  // the block and its groups, as the kernel tests build them
#include "constrained_transport.hpp"
#include "groups.hpp"
#include "mhd_fluxes.hpp"
#include "rhs.hpp"
#include "shock_tube_field.hpp"

namespace remnant::grmhd::bench {

class StarBlock {
 public:
  // magnetic: a poloidal field (A_phi = A0 varpi^2 (1 - r^2/49)^3, b^2 / 2p ~ 1e-2 at the centre)
  // evolved by constrained transport as GRMHD_RHS_MHD does (without the Grid's edge correction).
  StarBlock(eos::EOS eos, int n, double extent, bool magnetic = false)
      : eos_(std::move(eos)),
        vars_(test::kernel_registry()),  // the groups as the thorns declare them (thorn.yaml)
        g_(test::hydro_groups(vars_)),
        mg_(test::mhd_groups(vars_)),
        magnetic_(magnetic) {
    matter_ = {g_.cons, g_.prim, g_.metric};
    if (magnetic_) matter_.bvec = mg_.bvec;
    const double dx = extent / n;
    block_ = test::kernel_block(vars_, n, {dx, dx, dx});
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
    if (magnetic_)
      for (int d = 0; d < 3; ++d) {
        const double* f = b.data(mg_.bface[d]);
        std::copy(f, f + b.size(mg_.bface[d]), b0_[d].begin());
      }
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
      if (magnetic_)
        for (int d = 0; d < 3; ++d) {  // the interior faces, in rows along x (as MoL's update, vectorised)
          Field f = b.field(mg_.bface[d], 0), r = b.field(mg_.bface_rhs[d], 0);
          const std::ptrdiff_t off = f.origin - b.data(mg_.bface[d]);
          for (int k = 0; k < b.n[2] + (d == 2); ++k)
            for (int j = 0; j < b.n[1] + (d == 1); ++j) {
              const std::ptrdiff_t o = j * f.sj + k * f.sk;
              double* __restrict x = f.origin + o;
              const double* __restrict x0 = b0_[d].data() + off + o;
              const double* __restrict rhs = r.origin + j * r.sj + k * r.sk;
              for (int i = 0; i < b.n[0] + (d == 0); ++i) x[i] = a[s] * x0[i] + w[s] * (x[i] + dt * rhs[i]);
            }
        }
      recover();
    }
  }
  // Bytes per interior cell of the groups this run has (a magnetic-field group only when magnetic),
  // ghosts and staggered points included.
  double bytes_per_cell() const {
    double bytes = 0;
    for (const auto& spec : vars_.groups()) {
      if (!magnetic_ && !spec.condition.empty()) continue;
      bytes += 8.0 * double(block_->size(spec.id));
    }
    return bytes / double(cells());
  }
  void recover() {
    if (magnetic_) hydrobase::cell_centred_field({mg_.bface, mg_.bvec, g_.metric}, *block_);
    std::string fatal;
    hydrobase::recover_block(eos_, settings_, atm_, matter_, *block_, diag_, fatal);
  }
  void fluxes() {
    if (!magnetic_) return compute_block_fluxes(eos_, rhs_settings_, g_, *block_);
    mhd_sweeps();
    mhd_emfs();
  }
  // The two parts of fluxes() with the field (BM_PartMHD).
  // The face data of the EMFs: per-block scratch, as GRMHD_RHS_MHD keeps them (ct_faces.hpp).
  void mhd_sweeps() {
    compute_block_fluxes_mhd(eos_, rhs_settings_, g_, mg_, ct_.bind(*block_, g_), *block_, EmfScheme::uct_hll);
  }
  void mhd_emfs() { edge_emfs(EmfScheme::uct_hll, mg_, ct_.bind(*block_, g_), *block_); }
  void divergence() {
    if (!magnetic_) return compute_block_rhs(g_, *block_);
    face_rhs(mg_, *block_);
    compute_block_rhs_mhd(g_, mg_.bvec, *block_);
  }
  const con2prim::Diagnostics& diagnostics() const { return diag_; }
  // FNV-1a over the bytes of cons (and of the face fields when magnetic), ghosts included.
  std::uint64_t checksum() const {
    std::uint64_t h = 1469598103934665603ull;
    const auto add = [&](int group) {
      const auto* p = reinterpret_cast<const unsigned char*>(block_->data(group));
      for (std::size_t i = 0; i < block_->size(group) * sizeof(double); ++i) h = (h ^ p[i]) * 1099511628211ull;
    };
    add(g_.cons);
    if (magnetic_)
      for (int d = 0; d < 3; ++d) add(mg_.bface[d]);
    return h;
  }

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
    if (magnetic_) fill_field();
    con2prim::Diagnostics d;
    hydrobase::prim_to_cons_block(eos_, settings_, atm_, matter_, b, d);
  }

  // The face fields of the potential on every face (ghosts too: no exchange here), Bvec everywhere.
  void fill_field() {
    Block& b = *block_;
    // Confined to r < 7 (inside the star, radius about 8.1): no field in the atmosphere.
    const double a0 = 4e-4;
    const CovariantPotential A = [a0](const Point3& x) {
      const double s = std::max(1.0 - (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / 49.0, 0.0);
      const double g = a0 * s * s * s;
      return std::array<double, 3>{-x[1] * g, x[0] * g, 0.0};
    };
    add_potential_field(A, mg_.bface, b, 3);
    const Field psi = b.field(g_.metric, Metric::idx::psi);
    for (int d = 0; d < 3; ++d) {
      const Field f = b.field(mg_.bface[d], 0), out = b.field(mg_.bvec, d);
      for (int k = -3; k < b.n[2] + 3; ++k)
        for (int j = -3; j < b.n[1] + 3; ++j)
          for (int i = -3; i < b.n[0] + 3; ++i) {
            const double p2 = psi(i, j, k) * psi(i, j, k);
            f(i, j, k) *= p2 * p2 * p2;  // psi^6 B (the outermost ghost faces keep B: never read)
            out(i, j, k) = 0;
          }
    }
    for (int d = 0; d < 3; ++d) {
      const Field f = b.field(mg_.bface[d], 0), out = b.field(mg_.bvec, d);
      for (int k = -3; k < b.n[2] + 3 - (d == 2); ++k)
        for (int j = -3; j < b.n[1] + 3 - (d == 1); ++j)
          for (int i = -3; i < b.n[0] + 3 - (d == 0); ++i) {
            int up[3] = {i, j, k};
            ++up[d];
            const double p2 = psi(i, j, k) * psi(i, j, k);
            out(i, j, k) = 0.5 * (f(i, j, k) + f(up[0], up[1], up[2])) / (p2 * p2 * p2);
          }
    }
    for (int d = 0; d < 3; ++d) b0_[d].resize(b.size(mg_.bface[d]));
  }

  eos::EOS eos_;
  VariableRegistry vars_;
  Groups g_;
  MhdGroups mg_;
  CtFaceStorage ct_;
  bool magnetic_ = false;
  std::array<std::vector<double>, 3> b0_;
  hydrobase::MatterGroups matter_;
  std::unique_ptr<Block> block_;
  atmosphere::Atmosphere atm_;
  con2prim::Settings settings_;
  RhsSettings rhs_settings_;
  con2prim::Diagnostics diag_;
  std::vector<double> u0_;
};

}  // namespace remnant::grmhd::bench
