#pragma once
// The vector equation of xCFC, Lap X^i + (1/3) nabla^i (nabla_j X^j) = s^i (flat reference metric),
// solved as X = B - (1/4) grad chi with Lap B = s and Lap chi = div B (then Lap X + grad div X / 3
// = s exactly). B is taken in Cartesian components, which decouple into scalar problems: plain
// Laplacians in Cartesian coordinates and in 3D, and under axisymmetry (2D cylindrical or spherical)
// the x, y components are m = 1 modes, Lap V - V / varpi^2; a spherically symmetric field (1D
// spherical) has only its radial component, Lap V - 2 V / r^2. Parities at the axis, the origin and
// symmetry planes follow from the Cartesian component.
#include <array>
#include <vector>

#include "XCFC/multigrid/composite_multigrid.hpp"

namespace remnant::xcfc {

using VectorField = std::array<CompositeField, 3>;  // interior arrays per component

// The warm-start state of one vector solve: Cartesian B and the scalar chi.
struct VectorPotentials {
  VectorField B;
  CompositeField chi;
};

struct VectorSolveStats {
  SolveStats component[3], chi;
  // Cells this rank visited in the monopole's sums and charge terms (each rank its rows and its
  // share: about 1/N of one rank's on N ranks).
  long long monopole_cells = 0;
  int cycles() const { return component[0].cycles + component[1].cycles + component[2].cycles + chi.cycles; }
  double residual() const;  // largest relative residual of the four solves
  bool converged() const;
};

// Which Cartesian components are solved (a 1D spherical field has only x = radial at phi = 0,
// theta = pi / 2) and the equation of each.
bool cartesian_component_active(const GridShape& s, int a);
ScalarEquation cartesian_component_equation(const GridShape& s, int a);
ScalarEquation chi_equation();

// Coordinate (contravariant) components <-> Cartesian components at the cells' evaluation points.
VectorField to_cartesian_components(const CompositeMultigrid& mg, const VectorField& up);
VectorField to_coordinate_components(const CompositeMultigrid& mg, const VectorField& cart);
// Coordinate components with one ghost layer (boundary conditions of the Cartesian components;
// PartGeometry::at).
VectorField ghosted_coordinate_components(CompositeMultigrid& mg, const VectorField& up);
// The flat divergence of coordinate components, finite volumes with exact face integrals.
CompositeField divergence(CompositeMultigrid& mg, const VectorField& up);

// Solves for X (coordinate components) given s (coordinate components); `warm` is used as the
// initial guess and updated. Equations are those of the base shape's boundaries.
VectorSolveStats solve_vector_poisson(CompositeMultigrid& mg, const VectorField& source_up, VectorPotentials& warm,
                                      VectorField& X_up, const SolveSettings& settings);

}  // namespace remnant::xcfc
