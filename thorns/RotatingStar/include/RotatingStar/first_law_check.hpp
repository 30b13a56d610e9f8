#pragma once
// How far a table's interpolant departs from the first law along a cold slice. An adiabatic
// compression at fixed Ye changes eps by p / rho^2 drho; the table's interpolant at the slice's
// fixed T changes it by (deps/drho)_{T,Ye}. Where the ratio r = (deps/drho)_{T,Ye} rho^2 / p is
// far from 1, any compression or expansion of the star's matter (its oscillations, truncation
// error) moves eps off the slice: above it the matter heats, below it (T below the table's T_min)
// the recovery raises eps to the slice. Either way a cold star heats and expands; the shared
// 13 x 11 x 7 Hempel SFHo table (r = 0.54 .. 2.3 in a neutron star's core) makes the DD2RNS-type
// star's rho_c fall 5 % in 10 ms where a consistent EOS with the same cold p(rho) loses 1 %.
#include "EOS/tabulated.hpp"
#include "TOV/cold_slice.hpp"

namespace remnant::rotstar {

struct FirstLawDeparture {
  double mean = 0;       // mean |r - 1| over the densities (logarithmically spaced)
  double worst = 0;      // largest |r - 1|
  double rho_worst = 0;  // where (code units)
};

// |r - 1| at `samples` densities logarithmically spaced over [rho_lo, rho_hi], with Ye from the
// slice and T the slice's temperature (MeV).
FirstLawDeparture first_law_departure(const eos::Tabulated<>& table, const tov::ColdSlice& slice, double T, double rho_lo,
                                      double rho_hi, int samples = 400);

// RotatingStar warns when the mean over the star's core (rho_c / 10 .. rho_c) exceeds this: 0.60
// for the Hempel table above, 0.20 for the reduced 39 x 39 x 20 SFHo table and 0.07 for SRO LS220
// (157 x 89 x 49), whose stars hold rho_c like the consistent EOS.
inline constexpr double kFirstLawWarnMean = 0.3;

}  // namespace remnant::rotstar
