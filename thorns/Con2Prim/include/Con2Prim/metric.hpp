#pragma once
// The spatial metric at one point: gamma_ij, its inverse and determinant. Vectors carry their
// index position in the name of the function that made them (lower: ^i -> _i, raise: _i -> ^i).
#include <array>
#include <cmath>

namespace remnant::con2prim {

using Vec3 = std::array<double, 3>;

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct Metric3 {
  // Symmetric components in the order xx, xy, xz, yy, yz, zz.
  std::array<double, 6> g{1, 0, 0, 1, 0, 1};
  std::array<double, 6> ginv{1, 0, 0, 1, 0, 1};
  double det = 1;

  static Metric3 flat() { return {}; }

  // From gamma_ij; the inverse by cofactors.
  static Metric3 from_lower(double xx, double xy, double xz, double yy, double yz, double zz) {
    Metric3 m;
    m.g = {xx, xy, xz, yy, yz, zz};
    const double cxx = yy * zz - yz * yz, cxy = xz * yz - xy * zz, cxz = xy * yz - xz * yy;
    m.det = xx * cxx + xy * cxy + xz * cxz;
    const double id = 1 / m.det;
    m.ginv = {cxx * id, cxy * id, cxz * id, (xx * zz - xz * xz) * id, (xy * xz - xx * yz) * id,
              (xx * yy - xy * xy) * id};
    return m;
  }
  // When the caller already has the inverse (the GRMHD thorn does).
  static Metric3 from_lower_and_inverse(const std::array<double, 6>& lower, const std::array<double, 6>& inverse,
                                        double det) {
    Metric3 m;
    m.g = lower;
    m.ginv = inverse;
    m.det = det;
    return m;
  }

  Vec3 lower(const Vec3& u) const { return contract(g, u); }
  Vec3 raise(const Vec3& w) const { return contract(ginv, w); }
  double norm2_up(const Vec3& u) const { return dot(u, lower(u)); }    // gamma_ij u^i u^j
  double norm2_down(const Vec3& w) const { return dot(w, raise(w)); }  // gamma^ij w_i w_j
  double sqrt_det() const { return std::sqrt(det); }

 private:
  static Vec3 contract(const std::array<double, 6>& m, const Vec3& u) {
    return {m[0] * u[0] + m[1] * u[1] + m[2] * u[2], m[1] * u[0] + m[3] * u[1] + m[4] * u[2],
            m[2] * u[0] + m[4] * u[1] + m[5] * u[2]};
  }
};

}  // namespace remnant::con2prim
