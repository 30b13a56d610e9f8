#pragma once
// The xCFC equations in the paper's order (section "The CFC approximation and extended-CFC scheme"):
//   1. Lap X^i + (1/3) nabla^i nabla_j X^j = 8 pi f^ij S~_j
//   2. A^ij = nabla^i X^j + nabla^j X^i - (2/3) f^ij nabla_k X^k
//   3. Lap psi = -2 pi psi^-1 E~ - (1/8) psi^-7 A_ij A^ij
//   4. (the caller recovers the primitives with the new psi and computes S~)
//   5. Lap (alpha psi) = alpha psi [2 pi psi^-2 (E~ + 2 S~) + (7/8) psi^-8 A_ij A^ij]
//   6. Lap beta^i + (1/3) nabla^i nabla_j beta^j = 16 pi alpha psi^-6 f^ij S~_j + 2 A^ij d_j(alpha psi^-6)
// with E~ = psi^6 E, S~_j = psi^6 S_j, S~ = psi^6 S: the densitised conserved variables give E~ and
// S~_j directly. Outer boundaries: psi, alpha psi -> 1 + C/r (Schwarzschild), vectors fall off.
#include <array>
#include <vector>

#include "XCFC/multigrid/multigrid.hpp"
#include "XCFC/solver_geometry.hpp"
#include "XCFC/vector_poisson.hpp"

namespace remnant::xcfc {

struct XcfcStats {
  VectorSolveStats X, beta;
  SolveStats psi, alpha_psi;
};

// Everything the solver keeps between solves (warm starts) and returns.
// All fields are composite (one interior array per part of the CompositeMultigrid: the base level,
// then the refined patches; a uniform grid has one part).
struct XcfcState {
  CompositeField psi, alpha_psi;
  VectorPotentials X_potentials, beta_potentials;
  VectorField X, beta;                       // coordinate components
  std::array<CompositeField, 6> A;           // A^ij: 00 01 02 11 12 22
  CompositeField A2;                         // A_ij A^ij
  CompositeField alpha() const;
};

class XcfcSolver {
 public:
  // storage: the base grid multigrid's level storage on several ranks (XCFC::multigrid_storage).
  explicit XcfcSolver(const GridShape& shape, MPI_Comm comm = MPI_COMM_SELF,
                      MultigridStorage storage = MultigridStorage::replicated);  // uniform grid
  explicit XcfcSolver(const CompositeLayout& layout, MPI_Comm comm = MPI_COMM_SELF,
                      MultigridStorage storage = MultigridStorage::replicated);  // refined grid
  const GridShape& shape() const { return mg_.base_shape(); }
  CompositeMultigrid& multigrid() { return mg_; }

  // Steps 1-3. S_dn: covariant coordinate components of S~_j.
  void solve_conformal_factor(const CompositeField& E, const VectorField& S_dn, XcfcState& st, XcfcStats& stats,
                              const SolveSettings& settings);
  // Steps 5-6 (psi from step 3 in st). S_trace: S~.
  void solve_lapse_and_shift(const CompositeField& E, const VectorField& S_dn, const CompositeField& S_trace,
                             XcfcState& st, XcfcStats& stats, const SolveSettings& settings);
  // The same steps one by one, as the schedule runs them (X^i and A^ij; psi; alpha psi; beta^i).
  void solve_vector_potential(const CompositeField& E, const VectorField& S_dn, XcfcState& st, XcfcStats& stats,
                              const SolveSettings& settings);
  // X^i and A^ij from st's X potentials, no V-cycle (updates between solves; update_between_solves.cpp).
  void vector_potential_from_warm_start(XcfcState& st);
  void solve_psi(const CompositeField& E, XcfcState& st, XcfcStats& stats, const SolveSettings& settings);
  void solve_lapse(const CompositeField& E, const CompositeField& S_trace, XcfcState& st, XcfcStats& stats,
                   const SolveSettings& settings);
  void solve_shift(const CompositeField& E, const VectorField& S_dn, XcfcState& st, XcfcStats& stats,
                   const SolveSettings& settings);
  // Residual of the psi equation for the current psi and these sources, relative to its sources
  // (the trigger of an early solve).
  double conformal_factor_residual(const CompositeField& E, const XcfcState& st);
  // The geometry-only factors of the current multigrid (built on first use and again whenever the
  // multigrid no longer matches them).
  const SolverGeometry& geometry();

 private:
  void compute_A(XcfcState& st);
  CompositeMultigrid mg_;
  SolverGeometry geometry_;
};

ScalarEquation conformal_factor_equation();
ScalarEquation lapse_equation();

}  // namespace remnant::xcfc
