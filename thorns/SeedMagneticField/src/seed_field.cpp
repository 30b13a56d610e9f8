#include "seed_field.hpp"

#include <cmath>

#include "HydroBase/vector_potential.hpp"
#include "cell_interpolation.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"

namespace remnant::seed {

namespace {
// Coordinate cylindrical radius of a point.
double cylindrical_radius(CoordinateSystem c, const Point3& x) {
  switch (c) {
    case CoordinateSystem::cartesian: return std::hypot(x[0], x[1]);
    case CoordinateSystem::cylindrical: return std::abs(x[0]);
    case CoordinateSystem::spherical: return std::abs(x[0] * std::sin(x[1]));
  }
  return 0.0;
}
}  // namespace

void set_poloidal_faces(const Block& b, const PoloidalLaw& law, Field press, const std::array<Field, 3>& faces,
                        int quadrature_points) {
  const CellInterpolator p(b, press);
  const CoordinateSystem c = b.coordinates;
  auto a_phi = [&](const Point3& x) { return law.a_phi(cylindrical_radius(c, x), p(x)); };
  hydrobase::set_faces_from_potential(b, hydrobase::covariant_from_phi_component(c, a_phi), faces, quadrature_points);
}

double toroidal_densitised_bphi(const Block& b, const ToroidalLaw& law, const StarFields& in, int i, int j, int k) {
  const double rho = in.rho(i, j, k);
  if (!(rho > law.rho_cut)) return 0.0;
  const double h = 1.0 + in.eps(i, j, k) + in.press(i, j, k) / rho;
  const double R = cylindrical_radius(b.coordinates, cell_point(b, i, j, k));
  return law.densitised_bphi(R, in.alpha(i, j, k), in.psi(i, j, k), rho, h);
}

void add_toroidal_phi_faces(const Block& b, const ToroidalLaw& law, const StarFields& in, Field phi_faces) {
  for_interior(b, [&](int i, int j, int k) { phi_faces(i, j, k) += toroidal_densitised_bphi(b, law, in, i, j, k); });
}

double field_strength(const Block& b, const std::array<Field, 3>& faces, Field psi, int i, int j, int k) {
  const Point3 v = hydrobase::cell_orthonormal_densitised_field(b, faces, i, j, k);
  const double psi2 = psi(i, j, k) * psi(i, j, k);
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / (psi2 * psi2);
}

}  // namespace remnant::seed
