#pragma once
// Shared by the CompOSE readers: the CompOSE thermo quantities Q1..Q7 (and cs2, composition
// where present) on a grid, converted into a RawTable.
#include <array>
#include <string>
#include <vector>

#include "EOS/readers.hpp"

namespace remnant::eos::detail {

struct ComposeGrid {
  std::string file;            // for messages
  std::string thermo_dataset;  // "eos.thermo" or "Q" (HDF5)
  std::vector<double> nb, T, yq;  // fm^-3, MeV, 1
  double m_n = 0, m_p = 0;        // MeV
  // Q[k] for k = 0..6 (Q1..Q7), each in [iyq][iT][inb] order (nb fastest).
  std::array<std::vector<double>, 7> Q;
  std::vector<double> cs2;        // units of c^2, same order; empty: computed by differences
  std::string cs2_dataset = "cs2";
  // Optional composition, same order; already mass fractions and nucleus A, Z.
  std::vector<double> Xa, Xh, Xn, Xp, Abar, Zbar;
};

RawTable compose_to_raw(ComposeGrid g, const ReadOptions& opts, const std::string& format);

// cs2 from finite differences of p and eps on the (ln rho, ln T) grid at fixed Ye.
void cs2_from_differences(RawTable& raw);

}  // namespace remnant::eos::detail
