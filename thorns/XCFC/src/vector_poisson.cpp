#include "XCFC/vector_poisson.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "remnant/comm_counters.hpp"

namespace remnant::xcfc {

double VectorSolveStats::residual() const {
  double r = chi.scale > 0 ? chi.residual / chi.scale : 0;
  for (const auto& c : component) r = std::max(r, c.scale > 0 ? c.residual / c.scale : 0.0);
  return r;
}
bool VectorSolveStats::converged() const {
  return chi.converged && component[0].converged && component[1].converged && component[2].converged;
}

bool cartesian_component_active(const GridShape& s, int a) {
  return !(s.coordinates == CoordinateSystem::spherical && s.dimension == 1 && a != 0);
}

ScalarEquation cartesian_component_equation(const GridShape& s, int a) {
  ScalarEquation eq;
  const bool axisymmetric = s.coordinates != CoordinateSystem::cartesian && s.dimension <= 2;
  if (s.coordinates == CoordinateSystem::spherical && s.dimension == 1) {
    eq.mode = AngularMode::spherical_l1;
    eq.falloff = 2.0;  // exterior solution of Lap V - 2V/r^2 = 0: r^-2
  } else if (axisymmetric && a < 2) {
    eq.mode = AngularMode::axisymmetric_m1;
    eq.falloff = 2.0;  // an m = 1 field has no monopole: its leading exterior term is l = 1, r^-2
  } else if (s.coordinates != CoordinateSystem::cartesian || s.dimension == 3) {
    // The monopole is split off (monopole_split below); the rest starts at l = 1. A rotating star's
    // B^x, B^y are l = 1 (beta^phi -> 2J/r^3): held to r^-1 at the outer faces they took a rigid
    // rotation (a homogeneous solution) of about J/R^3 in beta^phi that did not converge.
    eq.falloff = 2.0;
  }
  // B is a vector in Cartesian components: its parity at each face is that of its declared tensor
  // type under the face's isometry (remnant/domain.hpp). On 3D grids the image across the axis or
  // the origin is the physical point itself (phi turned by pi): Cartesian components are
  // continuous there, only the equatorial mirror (theta kept at the origin) flips z. In 2D the
  // image lies in the same meridional half-plane, i.e. the point at phi + pi seen from phi: x and
  // y flip; the 1D origin is a point reflection. Mirror planes flip their normal component.
  const ComponentSpec B = expand_tensor(TensorKind::vector, "B").at(static_cast<std::size_t>(a));
  const DomainFaces faces = s.faces();
  for (int d = 0; d < 3; ++d)
    for (int side = 0; side < 2; ++side) eq.parity[d][side] = cartesian_face_parity(faces, d, side, B, s.cell_counts());
  return eq;
}

ScalarEquation chi_equation() { return ScalarEquation{}; }

namespace {

VectorField sized(const CompositeMultigrid& mg, bool ghosted) {
  VectorField out;
  for (auto& c : out)
    for (int i = 0; i < mg.parts(); ++i) {
      const PartGeometry& g = mg.part(i);
      c.part.emplace_back(ghosted ? g.frames().points : g.shape.cells(), 0.0);
    }
  return out;
}

// The transformations with the precomputed frames (interior cells; v^i = J[A][i] V^A / f_ii).
VectorField to_cartesian(const CompositeMultigrid& mg, const VectorField& up) {
  bool active[3];
  for (int a = 0; a < 3; ++a) active[a] = cartesian_component_active(mg.base_shape(), a);
  VectorField out = sized(mg, false);
  for (int n = 0; n < mg.parts(); ++n) {
    const PartGeometry& g = mg.part(n);
    const CellFrames& fr = g.frames();
    const auto &u0 = up[0].part[n], &u1 = up[1].part[n], &u2 = up[2].part[n];
    for_share_cells(mg, n, [&](std::size_t q, std::size_t p, int, int, int) {
      const Matrix3& J = fr.jacobian(p);
      for (int a = 0; a < 3; ++a)
        if (active[a]) out[a].part[n][q] = J[a][0] * u0[q] + J[a][1] * u1[q] + J[a][2] * u2[q];
    });
  }
  mg.complete({&out[0], &out[1], &out[2]});
  return out;
}
Point3 from_cartesian(const CellFrames& fr, std::size_t p, double V0, double V1, double V2) {
  const Matrix3& J = fr.jacobian(p);
  const Point3& f = fr.diagonal(p);
  Point3 v;
  for (int c = 0; c < 3; ++c) v[c] = (J[0][c] * V0 + J[1][c] * V1 + J[2][c] * V2) / f[c];
  return v;
}
VectorField to_coordinate(const CompositeMultigrid& mg, const VectorField& cart) {
  VectorField out = sized(mg, false);
  for (int n = 0; n < mg.parts(); ++n) {
    const PartGeometry& g = mg.part(n);
    const CellFrames& fr = g.frames();
    for_share_cells(mg, n, [&](std::size_t q, std::size_t p, int, int, int) {
      const Point3 v = from_cartesian(fr, p, cart[0].part[n][q], cart[1].part[n][q], cart[2].part[n][q]);
      for (int c = 0; c < 3; ++c) out[c].part[n][q] = v[c];
    });
  }
  mg.complete({&out[0], &out[1], &out[2]});
  return out;
}
}  // namespace

// Both with the precomputed frames (coords::jacobian and metric_diagonal at the same points), summed
// from zero in the order of coords::vector_to_cartesian and vector_from_cartesian: the same bits,
// without sin and cos per cell.
VectorField to_cartesian_components(const CompositeMultigrid& mg, const VectorField& up) {
  VectorField out = sized(mg, false);
  for (int n = 0; n < mg.parts(); ++n) {
    const CellFrames& fr = mg.part(n).frames();
    for_part_cells(mg.part(n), [&](std::size_t q, std::size_t p, int, int, int) {
      const Matrix3& J = fr.jacobian(p);
      const double v[3] = {up[0].part[n][q], up[1].part[n][q], up[2].part[n][q]};
      for (int a = 0; a < 3; ++a) {
        double V = 0;
        for (int i = 0; i < 3; ++i) V += J[a][i] * v[i];
        out[a].part[n][q] = cartesian_component_active(mg.base_shape(), a) ? V : 0.0;
      }
    });
  }
  return out;
}

VectorField to_coordinate_components(const CompositeMultigrid& mg, const VectorField& cart) {
  VectorField out = sized(mg, false);
  for (int n = 0; n < mg.parts(); ++n) {
    const CellFrames& fr = mg.part(n).frames();
    for_part_cells(mg.part(n), [&](std::size_t q, std::size_t p, int, int, int) {
      const Matrix3& J = fr.jacobian(p);
      const Point3& f = fr.diagonal(p);
      const double V[3] = {cart[0].part[n][q], cart[1].part[n][q], cart[2].part[n][q]};
      for (int c = 0; c < 3; ++c) {
        double v = 0;
        for (int A = 0; A < 3; ++A) v += J[A][c] * V[A];
        out[c].part[n][q] = v / f[c];
      }
    });
  }
  return out;
}

VectorField ghosted_coordinate_components(CompositeMultigrid& mg, const VectorField& up) {
  const GridShape& s = mg.base_shape();
  const VectorField cart = to_cartesian(mg, up);
  VectorField gc;
  for (int a = 0; a < 3; ++a) gc[a] = mg.with_ghosts(cartesian_component_equation(s, a), cart[a], true);
  VectorField out = sized(mg, true);
  // Every ghosted cell, in storage order: this rank's share of them (CellShare over ghosted arrays).
  const CellShare& share = mg.share(true);
  for (int n = 0; n < mg.parts(); ++n) {
    const CellFrames& fr = mg.part(n).frames();
    const auto [b, e] = share.range(n);
    share.count(e - b);
    for (std::size_t p = b; p < e; ++p) {
      const Point3 v = from_cartesian(fr, p, gc[0].part[n][p], gc[1].part[n][p], gc[2].part[n][p]);
      for (int c = 0; c < 3; ++c) out[c].part[n][p] = v[c];
    }
  }
  mg.complete({&out[0], &out[1], &out[2]}, true);
  return out;
}

CompositeField divergence(CompositeMultigrid& mg, const VectorField& up) {
  const VectorField g = ghosted_coordinate_components(mg, up);
  CompositeField div = mg.field();
  for (int n = 0; n < mg.parts(); ++n) {
    const PartGeometry& pg = mg.part(n);
    const GridShape& s = pg.shape;
    const auto& st = pg.strides;
    // The face factors over the cell integral per direction and index: separable, so 1D tables.
    std::array<std::vector<double>, 3> lo_w, hi_w;
    for (int d = 0; d < s.dimension; ++d) {
      lo_w[d].resize(static_cast<std::size_t>(s.n[d]));
      hi_w[d].resize(static_cast<std::size_t>(s.n[d]));
      for (int i = 0; i < s.n[d]; ++i) {
        const double a = s.face(d, i), b = s.face(d, i + 1);
        const double w = coords::volume_factor_integral(s.coordinates, d, a, b);
        lo_w[d][static_cast<std::size_t>(i)] = coords::volume_factor(s.coordinates, d, a) / w;
        hi_w[d][static_cast<std::size_t>(i)] = coords::volume_factor(s.coordinates, d, b) / w;
      }
    }
    for_share_cells(mg, n, [&](std::size_t q, std::size_t p, int i, int j, int k) {
      const std::array<int, 3> ijk{i, j, k};
      double sum = 0;
      for (int d = 0; d < s.dimension; ++d) {
        const auto& gd = g[d].part[n];
        const double hi = 0.5 * (gd[p] + gd[p + st[d]]), lo = 0.5 * (gd[p] + gd[p - st[d]]);
        const auto m = static_cast<std::size_t>(ijk[d]);
        sum += hi_w[d][m] * hi - lo_w[d][m] * lo;
      }
      div.part[n][q] = sum;
    });
  }
  mg.complete({&div});
  return div;
}

namespace {

// The cell's Cartesian position, coords::to_cartesian(s.coordinates, s.point(i, j, k)) with the same
// bits, without two out-of-line calls per cell on Cartesian grids (the monopole's loops below run
// over every cell of every part on every rank: 10 % of a 3D Cartesian solve's instructions).
inline Point3 cartesian_position(const GridShape& s, int i, int j, int k) {
  if (s.coordinates != CoordinateSystem::cartesian) return coords::to_cartesian(s.coordinates, s.point(i, j, k));
  return {s.centre(0, i), s.used(1) ? s.centre(1, j) : 0.0, s.used(2) ? s.centre(2, k) : 0.0};
}

// A compact, smooth unit charge q = c (1 - r^2/R^2)^2 (r < R) centred at the Cartesian origin, and
// its potential g (Lap g = q, g = -1/(4 pi r) outside).
struct UnitCharge {
  double R = 0, c = 0;
  explicit UnitCharge(double radius) : R(radius), c(105 / (32 * std::numbers::pi * radius * radius * radius)) {}
  double q(double r) const {
    const double u = 1 - r * r / (R * R);
    return r < R ? c * u * u : 0.0;
  }
  double g(double r) const {
    if (r >= R) return -1 / (4 * std::numbers::pi * r);
    const double x = r * r / (R * R);
    return c * R * R * (x / 6 - x * x / 10 + x * x * x / 42 - 19.0 / 210) - 1 / (4 * std::numbers::pi * R);
  }
  // chi_1 = M x_a p(r) solves Lap chi_1 = d_a (M g) (p = h'/r with Lap h = g); its gradient is
  // M (delta_ab p + x_a x_b k), k = p'/r. Outside: p = -1/(8 pi r) + R^2/(72 pi r^3): chi_1 tends to
  // -M x_a / (8 pi r), which does not fall off.
  double p(double r) const {
    if (r >= R) return -1 / (8 * std::numbers::pi * r) + R * R / (72 * std::numbers::pi * r * r * r);
    const double x = r * r / (R * R);
    return c * R * R * (x / 30 - x * x / 70 + x * x * x / 378 - 19.0 / 630) - 1 / (12 * std::numbers::pi * R);
  }
  double k(double r) const {
    if (r >= R) return 1 / (8 * std::numbers::pi * r * r * r) - R * R / (24 * std::numbers::pi * r * r * r * r * r);
    const double x = r * r / (R * R);
    return c * (1.0 / 15 - 2 * x / 35 + x * x / 63);
  }
};

// A Cartesian component with outer faces at r^-2 (cartesian_component_equation) whose source may
// have a monopole (the total linear momentum, for X): the largest charge radius (half the distance
// from the origin to the nearest outer face), or 0 when the component needs no split: an m = 1 or
// l = 1 mode, odd at a mirror plane (its images cancel the monopole), a planar grid, or an origin
// outside the domain.
double monopole_radius(const GridShape& s, const ScalarEquation& eq) {
  if (eq.mode != AngularMode::none || eq.falloff != 2.0) return 0;
  const DomainFaces faces = s.faces();
  double R = 1e300;
  for (int d = 0; d < s.dimension; ++d)
    for (int side = 0; side < 2; ++side) {
      const Boundary b = faces.boundary[d][side];
      const double x = side ? s.face(d, s.n[d]) : s.lo[d];
      if (b == Boundary::reflect && eq.parity[d][side] < 0) return 0;
      const bool radial = (s.coordinates == CoordinateSystem::spherical && d == 0) ||
                          (s.coordinates == CoordinateSystem::cylindrical && d == 0);
      if (!radial && s.coordinates != CoordinateSystem::spherical && !(d == 2 && s.coordinates == CoordinateSystem::cylindrical)) {
        if (side == 0 && x > 0) return 0;  // the origin is not in the domain
        if (side == 1 && x < 0) return 0;
      }
      if (s.coordinates == CoordinateSystem::spherical && d == 0 && side == 0 && x > 0) return 0;
      if (b == Boundary::outflow) R = std::min(R, std::abs(x));
    }
  return R < 1e300 ? 0.5 * R : 0;
}

// The weights M_a of the unit charges that carry the sources' monopoles: each source's volume
// integral over the leaf cells over the charge's (the factors of mirrored or unused directions
// cancel), for the components with radius > 0. The sums go by rows of cells ((j, k) of each part in
// storage order): each rank sums its contiguous range of the rows, the rows' partial sums are
// gathered (MPI_Allgatherv, 6 values a row) and added in row order, so the bits do not depend on
// the number of ranks and no rank loops over every cell.
std::array<double, 3> monopole_weights(const CompositeMultigrid& mg, const VectorField& src, const std::array<double, 3>& radius,
                                       const std::array<UnitCharge, 3>& unit, long long& visited) {
  constexpr std::size_t kPer = 6;  // m_0..2, q_0..2
  std::vector<std::size_t> first_row{0}, row_start{0};  // first row of each part; first cell of each row
  for (int n = 0; n < mg.parts(); ++n) {
    const GridShape& s = mg.part(n).shape;
    first_row.push_back(first_row.back() + static_cast<std::size_t>(s.n[1]) * static_cast<std::size_t>(s.n[2]));
    for (std::size_t r = first_row[first_row.size() - 2]; r < first_row.back(); ++r)
      row_start.push_back(row_start.back() + static_cast<std::size_t>(s.n[0]));
  }
  const std::size_t rows = first_row.back();
  int rank = 0, nranks = 1;
  const MPI_Comm comm = mg.comm();
  if (comm != MPI_COMM_SELF) {
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &nranks);
  }
  // Rows dealt out in contiguous ranges balanced by cells (patch rows are shorter than the base's).
  auto cut = [&](int r) {
    const std::size_t target = row_start.back() * static_cast<std::size_t>(r) / static_cast<std::size_t>(nranks);
    return static_cast<std::size_t>(std::lower_bound(row_start.begin(), row_start.end() - 1, target) - row_start.begin());
  };
  const std::size_t r0 = cut(rank), r1 = cut(rank + 1);
  std::vector<double> partial(kPer * rows, 0.0);
  for (int n = 0; n < mg.parts(); ++n) {
    const std::size_t b = std::max(r0, first_row[static_cast<std::size_t>(n)]), e = std::min(r1, first_row[static_cast<std::size_t>(n) + 1]);
    if (b >= e) continue;
    const GridShape& s = mg.part(n).shape;
    // The cell integrals per direction and index (separable): 1D tables, multiplied per cell.
    std::array<std::vector<double>, 3> w;
    for (int d = 0; d < s.dimension; ++d)
      for (int i = 0; i < s.n[d]; ++i) w[d].push_back(coords::volume_factor_integral(s.coordinates, d, s.face(d, i), s.face(d, i + 1)));
    const auto n0 = static_cast<std::size_t>(s.n[0]), n1 = static_cast<std::size_t>(s.n[1]);
    for (std::size_t row = b; row < e; ++row) {
      const std::size_t local = row - first_row[static_cast<std::size_t>(n)];
      const int j = static_cast<int>(local % n1), k = static_cast<int>(local / n1);
      double* out = &partial[kPer * row];
      visited += s.n[0];
      for (int i = 0; i < s.n[0]; ++i) {
        const std::size_t c = static_cast<std::size_t>(i) + n0 * local;
        if (mg.covered(n, c)) continue;
        const std::array<int, 3> ijk{i, j, k};
        double vol = 1;
        for (int d = 0; d < s.dimension; ++d) vol *= w[d][static_cast<std::size_t>(ijk[d])];
        const Point3 X = cartesian_position(s, i, j, k);
        const double r = std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]);
        for (int a = 0; a < 3; ++a)
          if (radius[a] > 0) {
            out[a] += src[a].part[static_cast<std::size_t>(n)][c] * vol;
            out[3 + a] += unit[a].q(r) * vol;
          }
      }
    }
  }
  if (nranks > 1) {
    std::vector<int> counts(static_cast<std::size_t>(nranks)), displs(static_cast<std::size_t>(nranks));
    for (int r = 0; r < nranks; ++r) {
      counts[static_cast<std::size_t>(r)] = static_cast<int>(kPer * (cut(r + 1) - cut(r)));
      displs[static_cast<std::size_t>(r)] = static_cast<int>(kPer * cut(r));
    }
    MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DOUBLE, partial.data(), counts.data(), displs.data(), MPI_DOUBLE, comm);
    comm::count("xcfc_monopole_allgather", comm::Pattern::allgather, -1, 1,
                static_cast<long long>(sizeof(double) * (partial.size() - kPer * (r1 - r0))));
  }
  std::array<double, 3> m{}, q{}, M{};
  for (std::size_t row = 0; row < rows; ++row)
    for (int a = 0; a < 3; ++a) {
      m[a] += partial[kPer * row + static_cast<std::size_t>(a)];
      q[a] += partial[kPer * row + 3 + static_cast<std::size_t>(a)];
    }
  for (int a = 0; a < 3; ++a) M[a] = radius[a] > 0 && q[a] > 0 ? m[a] / q[a] : 0.0;
  return M;
}

// d_a chi_1 for chi_1 = sum_b M_b x_b p_b(r) (UnitCharge::p).
inline double chi1_gradient(int a, const Point3& X, double r, const std::array<double, 3>& M, const std::array<UnitCharge, 3>& unit) {
  double v = 0;
  for (int b = 0; b < 3; ++b)
    if (M[b] != 0) v += M[b] * ((a == b ? unit[b].p(r) : 0.0) + X[a] * X[b] * unit[b].k(r));
  return v;
}

// fn(n, q, X, r) for this rank's share of the cells of every part (covered cells included: they
// hold restrictions), X the Cartesian position; the caller completes what it wrote.
template <class Fn>
void for_share_positions(const CompositeMultigrid& mg, long long& visited, Fn&& fn) {
  for (int n = 0; n < mg.parts(); ++n) {
    const GridShape& s = mg.part(n).shape;
    const auto [b, e] = mg.share().range(n);
    visited += static_cast<long long>(e - b);
    for_share_cells(mg, n, [&](std::size_t c, std::size_t, int i, int j, int k) {
      const Point3 X = cartesian_position(s, i, j, k);
      fn(static_cast<std::size_t>(n), c, X, std::sqrt(X[0] * X[0] + X[1] * X[1] + X[2] * X[2]));
    });
  }
}

void complete_fields(const CompositeMultigrid& mg, const std::vector<CompositeField*>& fields) {
  if (!mg.share().split() || fields.empty()) return;
  std::vector<std::vector<std::vector<double>>*> parts;
  for (CompositeField* f : fields) parts.push_back(&f->part);
  mg.share().complete(parts);
}

}  // namespace

VectorSolveStats solve_vector_poisson(CompositeMultigrid& mg, const VectorField& source_up, VectorPotentials& warm,
                                      VectorField& X_up, const SolveSettings& settings) {
  const GridShape& s = mg.base_shape();
  VectorSolveStats stats;
  // Moved into the equations once the monopoles are measured; each equation's source is freed after
  // its solve (issue 21, memory: fewer composite fields alive at the solver's peak).
  VectorField src = to_cartesian(mg, source_up);
  const CompositeField zero = mg.field();
  // The monopole of each component goes into a unit charge's potential M g; the rest falls off at
  // r^-2 (solved for B - M g). Its divergence's potential chi_1 (UnitCharge::p) tends to -M x / (8 pi r),
  // which a 1/r condition on chi cannot hold: chi is solved for chi - chi_1 (source div(B - M g)) and
  // warm.B keeps B - grad chi_1 / 4, so that X = B - grad chi / 4 of the kept potentials still holds.
  std::array<double, 3> M{}, radius{};
  std::array<UnitCharge, 3> unit{UnitCharge(1.0), UnitCharge(1.0), UnitCharge(1.0)};
  std::array<CompositeEquation, 3> eqs;
  bool active[3];
  for (int a = 0; a < 3; ++a) {
    if (warm.B[a].part.size() != zero.part.size()) warm.B[a] = zero;
    active[a] = cartesian_component_active(s, a);
    if (!active[a]) continue;
    eqs[a].boundary = cartesian_component_equation(s, a);
    radius[a] = monopole_radius(s, eqs[a].boundary);
    unit[a] = UnitCharge(radius[a] > 0 ? radius[a] : 1.0);
  }
  if (radius[0] > 0 || radius[1] > 0 || radius[2] > 0) M = monopole_weights(mg, src, radius, unit, stats.monopole_cells);
  for (int a = 0; a < 3; ++a)
    if (active[a]) eqs[a].s0 = std::move(src[a]);
  const bool split = M[0] != 0 || M[1] != 0 || M[2] != 0;
  if (split) {
    // B += grad chi_1 / 4 - M g, s0 -= M q: on this rank's share, then completed.
    for_share_positions(mg, stats.monopole_cells, [&](std::size_t n, std::size_t c, const Point3& X, double r) {
      for (int a = 0; a < 3; ++a) {
        if (!active[a]) continue;
        double& b = warm.B[a].part[n][c];
        b += 0.25 * chi1_gradient(a, X, r, M, unit);
        if (M[a] != 0) {
          eqs[a].s0.part[n][c] += -M[a] * unit[a].q(r);
          b += -M[a] * unit[a].g(r);
        }
      }
    });
    std::vector<CompositeField*> done;
    for (int a = 0; a < 3; ++a)
      if (active[a]) done.push_back(&warm.B[a]);
    for (int a = 0; a < 3; ++a)
      if (M[a] != 0) done.push_back(&eqs[a].s0);
    complete_fields(mg, done);
  }
  for (int a = 0; a < 3; ++a) {
    if (!active[a]) {
      warm.B[a] = zero;
      stats.component[a].converged = true;
      continue;
    }
    stats.component[a] = mg.solve(eqs[a], warm.B[a], settings);
    eqs[a].s0 = CompositeField{};
  }
  CompositeEquation chi;
  chi.boundary = chi_equation();
  chi.s0 = divergence(mg, to_coordinate(mg, warm.B));
  if (split) {
    // B += M g - grad chi_1 / 4: the kept potentials (see above).
    for_share_positions(mg, stats.monopole_cells, [&](std::size_t n, std::size_t c, const Point3& X, double r) {
      for (int a = 0; a < 3; ++a) {
        if (!active[a]) continue;
        double& b = warm.B[a].part[n][c];
        if (M[a] != 0) b += M[a] * unit[a].g(r);
        b += -0.25 * chi1_gradient(a, X, r, M, unit);
      }
    });
    complete_fields(mg, {&warm.B[0], &warm.B[1], &warm.B[2]});
  }
  VectorField B_up = to_coordinate(mg, warm.B);
  stats.chi = mg.solve(chi, warm.chi, settings);
  // X^i = B^i - f^ii d_i chi / 4 (centred differences).
  const CompositeField gchi = mg.with_ghosts(chi.boundary, warm.chi, true);
  X_up = std::move(B_up);
  for (int n = 0; n < mg.parts(); ++n) {
    const PartGeometry& g = mg.part(n);
    const auto& st = g.strides;
    const auto& gc = gchi.part[n];
    for_share_cells(mg, n, [&](std::size_t q, std::size_t p, int, int, int) {
      const Point3& f = g.frames().diagonal(p);
      for (int d = 0; d < s.dimension; ++d) X_up[d].part[n][q] -= 0.25 * (gc[p + st[d]] - gc[p - st[d]]) / (2 * g.shape.dx[d] * f[d]);
    });
  }
  mg.complete({&X_up[0], &X_up[1], &X_up[2]});
  return stats;
}

}  // namespace remnant::xcfc
