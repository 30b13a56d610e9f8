#pragma once
// Multipole machinery of the equilibrium solver (XNS-style, Bucciantini & Del Zanna 2011):
// Gauss-Legendre nodes in mu = cos(theta) on the upper half (equatorial symmetry), Legendre
// polynomials and their mu-derivatives, and the radial Green's-function solve of
//   u_l'' + 2 u_l' / r - l (l + 1) u_l / r^2 = s_l
// on radial nodes 0 = r_0 < r_1 < ... < r_N (trapezoidal cumulative integrals, second order),
// regular at r = 0 and decaying as r^-(l+1) outside (sources beyond r_N are neglected).
// Scalars (psi, alpha psi) expand in P_l (even l); the phi components of vectors (X, beta) as
// physical components r sin(theta) V^phi expand in sin(theta) P_l'(mu) (odd l), the m = 1
// harmonics, with the same radial operator.
#include <vector>

namespace remnant::rotstar {

struct LegendreTable {
  std::vector<double> mu, weight;  // upper-half Gauss nodes, weights of the full [-1, 1] rule
  int lmax = 0;
  // P[l][j], dP[l][j] = P_l'(mu_j), d2P[l][j] = P_l''(mu_j)
  std::vector<std::vector<double>> P, dP, d2P;
  LegendreTable(int n_half, int lmax);
};

// P_l(mu), P_l'(mu), P_l''(mu) for l = 0..lmax at one mu (|mu| <= 1, exact at the poles).
void legendre(int lmax, double mu, std::vector<double>& P, std::vector<double>& dP, std::vector<double>& d2P);

// Solution u_l(r_i) and derivative du_l/dr(r_i) for one multipole; s has N+1 values.
struct RadialSolution {
  std::vector<double> u, du;
};
RadialSolution solve_radial(int l, const std::vector<double>& r, const std::vector<double>& s);

// Projections of f(r_i, mu_j) (row-major [i][j] over the half nodes) onto multipoles:
// scalar: f_l = (2l+1)/2 int f P_l dmu; m = 1: f_l = (2l+1)/(2l(l+1)) int f sin(theta) P_l' dmu.
std::vector<double> project_scalar(const LegendreTable& t, int l, const std::vector<double>& f, int nr);
std::vector<double> project_m1(const LegendreTable& t, int l, const std::vector<double>& f, int nr);

}  // namespace remnant::rotstar
