#pragma once
// The 3D data's magnetic field as the hand-off needs it: the gauge-independent densitised field
// Bt^i = sqrt(gamma) B^i (Cartesian components; the paper's sqrt(gamma / f) B^j, whose flux through
// a surface is the magnetic flux), and the magnetic energy densities (per coordinate volume)
// (1/2) sqrt(gamma) gamma_ij B^i B^j and its toroidal part (1/2) sqrt(gamma) gamma^(1/3) B_phi-hat^2,
// B_phi-hat = (-y B^x + x B^y) / varpi (the split of Analysis, exact for a conformally flat metric).
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"

namespace remnant::handoff {

inline const std::vector<std::string>& densitised_field_names() {
  static const std::vector<std::string> f{"Bt[0]", "Bt[1]", "Bt[2]"};
  return f;
}

// True when the data hold all three components of HydroBase::Bvec.
bool has_magnetic_field(const SourceData& src);

// Adds Bt[0..2], Emag and Emagtor from Bvec[0..2] and gxx..gzz (flat where absent); to be called
// before the metric components are dropped. Bvec itself stays (the conserved variables' magnetic
// terms use it).
void add_magnetic_source(SourceData& src);

}  // namespace remnant::handoff
