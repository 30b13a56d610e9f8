#pragma once
// The variable groups a GRMHD block kernel touches, resolved once per scheduled call. Component
// layouts come from the generated views (thorn.yaml); the Valencia state vector of valencia.hpp is
// tied to HydroBase::cons and the flux groups at compile time, so a change of either fails to build.
#include <array>

#include "GRMHD/valencia.hpp"
#include "remnant/context.hpp"
#include "remnant/vars/GRMHD.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::grmhd {

using Prim = vars::HydroBase::prim;
using Cons = vars::HydroBase::cons;
using Metric = vars::Spacetime::metric;

static_assert(Cons::ncomp == kNumCons && int{Cons::idx::D} == int{kD} && Cons::idx::S == int{kS1} &&
                  int{Cons::idx::tau} == int{kTau} && int{Cons::idx::DYe} == int{kDYe},
              "the Valencia state vector (valencia.hpp) must match HydroBase::cons (thorn.yaml)");
static_assert(vars::HydroBase::cons_rhs::ncomp == kNumCons && vars::GRMHD::flux_x::ncomp == kNumCons &&
                  vars::GRMHD::flux_y::ncomp == kNumCons && vars::GRMHD::flux_z::ncomp == kNumCons,
              "cons_rhs and the flux groups hold one value per component of cons");

struct Groups {
  int cons = -1, cons_rhs = -1, prim = -1, metric = -1;
  std::array<int, 3> flux{-1, -1, -1};
  int budget = -1, budget_rhs = -1;  // HydroBase::mass_budget (outflow, source) and its rhs
  static Groups of(const Context& ctx) {
    Groups g;
    g.cons = Cons::id(ctx);
    g.cons_rhs = vars::HydroBase::cons_rhs::id(ctx);
    g.prim = Prim::id(ctx);
    g.metric = Metric::id(ctx);
    g.flux = {vars::GRMHD::flux_x::id(ctx), vars::GRMHD::flux_y::id(ctx), vars::GRMHD::flux_z::id(ctx)};
    g.budget = vars::HydroBase::mass_budget::id(ctx);
    g.budget_rhs = vars::HydroBase::mass_budget_rhs::id(ctx);
    return g;
  }
};

}  // namespace remnant::grmhd
