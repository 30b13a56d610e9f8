#pragma once
// The groups of the magnetic-field evolution (HydroBase::magnetic_field = evolved), resolved once
// per scheduled call: HydroBase's face fields and cell-centred field and GRMHD's edge EMFs (the
// face data of the Riemann problems that the EMFs need are per-block scratch: ct_faces.hpp).
#include <array>

#include "remnant/context.hpp"

namespace remnant::grmhd {

// Components of the face data of the EMFs (CtFaces) at a face normal to a: the HLL speed bounds
// alpha^+ = max(0, lambda^+_L, lambda^+_R) and alpha^- = -min(0, lambda^-_L, lambda^-_R), the
// transport velocity alpha v^a - beta^a of the left and right states, and the HLL fluxes psi^6 F^a
// of B^b and B^c, (a, b, c) cyclic.
enum CtComponent : int { kAlphaPlus = 0, kAlphaMinus, kVtLeft, kVtRight, kFluxNext, kFluxPrev };
inline constexpr int kNumCt = 6;

enum class EmfScheme { uct_hll, arithmetic, uct_contact };

struct MhdGroups {
  std::array<int, 3> bface{-1, -1, -1}, bface_rhs{-1, -1, -1}, emf{-1, -1, -1};
  int bvec = -1;
  static MhdGroups of(const Context& ctx) {
    MhdGroups g;
    for (int d = 0; d < 3; ++d) {
      const std::string n = std::to_string(d + 1);
      const char xyz = static_cast<char>('x' + d);
      g.bface[d] = ctx.var("HydroBase::Bface" + n);
      g.bface_rhs[d] = ctx.var("HydroBase::Bface" + n + "_rhs");
      g.emf[d] = ctx.var(std::string("GRMHD::emf_") + xyz);
    }
    g.bvec = ctx.var("HydroBase::Bvec");
    return g;
  }
};

}  // namespace remnant::grmhd
