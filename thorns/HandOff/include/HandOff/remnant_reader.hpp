#pragma once
// Reader of Remnant's own HDF5 volume output ("remnant-grid-1", thorns/IO/src/grid_file.hpp) of a
// 3D Cartesian run: each block's cell centres are points of its level (the file holds the leaves;
// each refined block's 2^3 means fill the coarser levels beneath it, so levels overlap as Carpet's do),
// HydroBase::prim (rho, eps, press, Ye, temperature, vel), HydroBase::cons (D, S, tau, DYe: taken
// as they are, so the 3D rest mass is the run's own) and Spacetime::metric (psi, alpha -> gamma_ij =
// psi^4 delta_ij). Mirror planes (a run on an octant) come from HandOff::reflection.
#include <array>
#include <string>
#include <vector>

#include "HandOff/source_data.hpp"

namespace remnant::handoff {

SourceData read_remnant_volume(const std::vector<std::string>& files, std::array<bool, 3> reflection = {false, false, false},
                               bool axial_magnetic_field = true);

}  // namespace remnant::handoff
