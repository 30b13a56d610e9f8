// HandOff_MagneticField: the 3D data's field on the grid's faces from a vector potential on its
// edges (see magnetic_import.hpp).
#include "magnetic_import.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "HandOff/sampler.hpp"
#include "HydroBase/magnetic_field.hpp"
#include "HydroBase/vector_potential.hpp"
#include "magnetic_source.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/vars/HandOff.hpp"
#include "remnant/vars/Spacetime.hpp"

namespace remnant::handoff {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr int kQuadrature = 3;  // Gauss-Legendre points per face direction

// Fluxes of the densitised 3D field through faces of the grid's coordinates.
class FluxQuadrature {
 public:
  FluxQuadrature(const SourceData& src, CoordinateSystem cs, bool phi_average, int phi_param)
      : sampler_(src, densitised_field_names()), cs_(cs), phi_average_(phi_average), phi_param_(phi_param) {
    hydrobase::gauss_legendre(kQuadrature, nodes_, weights_);
  }

  // sqrt(f) Bt^d in the grid's coordinates at x (the mean over phi on 2D grids): a flux per
  // coordinate area.
  double density(Point3 x, int d) const {
    double sqrt_f = 1;
    for (int e = 0; e < 3; ++e) sqrt_f *= coords::volume_factor(cs_, e, x[static_cast<std::size_t>(e)]);
    if (sqrt_f == 0) return 0.0;
    if (!phi_average_) return sqrt_f * component(x, d);
    const double ring = cs_ == CoordinateSystem::cylindrical ? x[0] : x[0] * std::sin(x[1]);
    x[2] = 0;
    const double h = sampler_.spacing_at(coords::to_cartesian(cs_, x));
    const int n = phi_param_ > 0 ? phi_param_ : std::clamp(static_cast<int>(std::ceil(kTwoPi * std::abs(ring) / h)), 8, 4096);
    double sum = 0;
    for (int m = 0; m < n; ++m) {
      x[2] = (m + 0.5) * kTwoPi / n;
      sum += component(x, d);
    }
    return sqrt_f * sum / n;
  }

  // The flux through the face normal to d at x^d = xd spanning [lo[e], hi[e]] in the other two
  // directions; a direction with one point (phi of a 2D grid: the density is its mean) is weighed
  // by its length.
  double flux(int d, double xd, const Point3& lo, const Point3& hi) const {
    const int e1 = d == 0 ? 1 : 0, e2 = d == 2 ? 1 : 2;
    auto points = [&](int e) { return phi_average_ && e == 2 ? 1 : kQuadrature; };
    double sum = 0;
    Point3 x{};
    x[static_cast<std::size_t>(d)] = xd;
    const auto u1 = static_cast<std::size_t>(e1), u2 = static_cast<std::size_t>(e2);
    const double h1 = 0.5 * (hi[u1] - lo[u1]), h2 = 0.5 * (hi[u2] - lo[u2]);
    for (int q2 = 0; q2 < points(e2); ++q2) {
      const double t2 = points(e2) == 1 ? 0.0 : nodes_[static_cast<std::size_t>(q2)];
      const double w2 = points(e2) == 1 ? 2.0 : weights_[static_cast<std::size_t>(q2)];
      x[u2] = 0.5 * (hi[u2] + lo[u2]) + h2 * t2;
      for (int q1 = 0; q1 < points(e1); ++q1) {
        x[u1] = 0.5 * (hi[u1] + lo[u1]) + h1 * nodes_[static_cast<std::size_t>(q1)];
        sum += w2 * weights_[static_cast<std::size_t>(q1)] * density(x, d);
      }
    }
    return sum * h1 * h2;
  }

 private:
  double component(const Point3& x, int d) const {
    double Bt[3];
    if (!sampler_.sample(coords::to_cartesian(cs_, x), Bt)) return 0.0;
    return coords::vector_from_cartesian(cs_, x, {Bt[0], Bt[1], Bt[2]})[static_cast<std::size_t>(d)];
  }
  Sampler sampler_;
  CoordinateSystem cs_;
  bool phi_average_;
  int phi_param_;
  std::vector<double> nodes_, weights_;
};

// Face coordinate of the level's global face index g in direction d: the Block's own expression.
struct LevelFaces {
  std::array<double, 3> domain_lo{}, dx{};
  double operator()(int d, std::int64_t g) const {
    const auto ud = static_cast<std::size_t>(d);
    return g == 0 ? domain_lo[ud] : domain_lo[ud] + static_cast<double>(g) * dx[ud];
  }
};

// The cells of one block (a local one, or a finer leaf next to it) in its level's global indices:
// the frame the edge tables are built on.
struct Frame {
  std::array<std::int64_t, 3> first{};  // global index of the first cell (0 in unused directions)
  std::array<int, 3> n{1, 1, 1};
  std::array<bool, 3> used{};
  LevelFaces F;            // the level's face coordinates
  std::int64_t cells_m = 0;  // 2D: the level's cells along the marching direction (R or theta)
  double phi_hi = 0;         // 2D: the upper phi face
};

// Edge integrals of the potential, per direction, in vector_potential.hpp's indexing (cell along
// the edge, faces across it; one index in unused directions).
struct EdgeTable {
  std::array<std::array<int, 3>, 3> extent{};
  std::array<std::vector<double>, 3> value;
  explicit EdgeTable(const Frame& f) {
    for (int a = 0; a < 3; ++a) {
      for (int d = 0; d < 3; ++d) {
        const auto ud = static_cast<std::size_t>(d);
        extent[static_cast<std::size_t>(a)][ud] = d == a || !f.used[ud] ? f.n[ud] : f.n[ud] + 1;
      }
      const auto& e = extent[static_cast<std::size_t>(a)];
      value[static_cast<std::size_t>(a)].assign(static_cast<std::size_t>(e[0]) * static_cast<std::size_t>(e[1]) * static_cast<std::size_t>(e[2]), 0.0);
    }
  }
  double& operator()(int a, int i, int j, int k) {
    const auto& e = extent[static_cast<std::size_t>(a)];
    return value[static_cast<std::size_t>(a)][static_cast<std::size_t>(i + e[0] * (j + e[1] * k))];
  }
  bool contains(int a, const std::array<std::int64_t, 3>& p) const {
    for (std::size_t d = 0; d < 3; ++d)
      if (p[d] < 0 || p[d] >= extent[static_cast<std::size_t>(a)][d]) return false;
    return true;
  }
};

// The table as a potential for EdgeIntegrals with one quadrature point: at the midpoint of an edge
// along a, A_a = (edge integral) / (edge length), so the library's quadrature returns the table.
hydrobase::CovariantPotential table_potential(const Block& b, EdgeTable& t) {
  return [&b, &t](const Point3& x) -> std::array<double, 3> {
    int idx[3] = {0, 0, 0};
    int along = -1;
    for (int d = 0; d < 3; ++d) {
      if (!direction_used(b, d)) {
        if (coords::is_angle(b.coordinates, d)) along = along < 0 ? d : along;  // whole-range edge
        continue;
      }
      const auto ud = static_cast<std::size_t>(d);
      const double s = (x[ud] - b.face_coordinate(d, 0)) / b.dx[ud];
      const double r = std::round(s);
      if (std::abs(s - r) < 1e-6) {
        idx[d] = static_cast<int>(r);
      } else {
        idx[d] = static_cast<int>(std::floor(s));
        along = d;
      }
    }
    std::array<double, 3> A{0, 0, 0};
    if (along < 0) return A;
    const double length = b.face_coordinate(along, idx[along] + 1) - b.face_coordinate(along, idx[along]);
    A[static_cast<std::size_t>(along)] = t(along, idx[0], idx[1], idx[2]) / length;
    return A;
  };
}

// 2D cylindrical (march along R from the axis, fluxes through z faces) or spherical (along theta
// from the pole, through r faces): 2 pi A_phi = Psi at every node of the frame.
// closure: the largest |Psi at the grid's far end| / sum |flux| of a row with field at its far end
// that is taken for the data's interpolation error and removed (HandOff::flux_closure_tolerance).
EdgeTable axisymmetric_edges(const Frame& fr, bool cyl, const FluxQuadrature& q, double closure) {
  const int m = cyl ? 0 : 1, d = cyl ? 1 : 0;
  const auto um = static_cast<std::size_t>(m), ud = static_cast<std::size_t>(d);
  const LevelFaces& F = fr.F;
  EdgeTable t(fr);
  const double phi_lo = F(2, 0), phi_hi = fr.phi_hi;
  std::vector<double> psi(static_cast<std::size_t>(fr.cells_m + 1)), weight(static_cast<std::size_t>(fr.cells_m + 1));
  for (int fd = 0; fd <= fr.n[ud]; ++fd) {
    const double xd = F(d, fr.first[ud] + fd);
    // Psi and the cumulative |flux| at every node of the row, from the axis to the grid's far end.
    psi[0] = weight[0] = 0;
    double last = 0;  // the flux through the row's last face
    for (std::int64_t g = 0; g < fr.cells_m; ++g) {
      Point3 lo{}, hi{};
      lo[um] = F(m, g), hi[um] = F(m, g + 1), lo[2] = phi_lo, hi[2] = phi_hi;
      const double f = q.flux(d, xd, lo, hi);
      const auto u = static_cast<std::size_t>(g);
      psi[u + 1] = psi[u] + f, weight[u + 1] = weight[u] + std::abs(f), last = f;
    }
    // A field that closes inside the grid (none at the row's far end, or a net flux below
    // closure of the row's |flux|) has Psi = 0 there; what is left is the interpolation error of
    // the data: removed in proportion to |flux| (so nothing is added where the data have no field).
    const double total = weight.back(), leak = psi.back();
    const bool close = total > 0 && (last == 0.0 || std::abs(leak) <= closure * total);
    for (int fm = 0; fm <= fr.n[um]; ++fm) {
      const auto u = static_cast<std::size_t>(fr.first[um] + fm);
      t(2, cyl ? fm : fd, cyl ? fd : fm, 0) = close ? psi[u] - leak * (weight[u] / total) : psi[u];
    }
  }
  return t;
}

// 2D: B^phi, the phi-averaged field averaged over each phi face (phi is unused: no divergence).
void toroidal_faces(const Block& b, const FluxQuadrature& q, const std::array<Field, 3>& faces) {
  const double phi_lo = b.face_coordinate(2, 0);
  for (int j = 0; j < b.n[1]; ++j)
    for (int i = 0; i < b.n[0]; ++i) {
      const Point3 lo{b.face_coordinate(0, i), b.face_coordinate(1, j), 0}, hi{b.face_coordinate(0, i + 1), b.face_coordinate(1, j + 1), 0};
      const double area = b.face_area(2, i, j, 0);
      faces[2](i, j, 0) = area > 0 ? q.flux(2, phi_lo, lo, hi) / area : 0.0;
    }
}

// 3D Cartesian: A_z = 0; A_y on the lowest z face from its z fluxes, then A_x, A_y upwards.
EdgeTable cartesian_edges(const Frame& fr, const FluxQuadrature& q) {
  const LevelFaces& F = fr.F;
  const std::int64_t gx = fr.first[0], gy = fr.first[1], gz = fr.first[2];
  const std::int64_t top = gz + fr.n[2];
  EdgeTable t(fr);
  // A_y along y edges at x faces (i), y cells (j): base from the z faces of the lowest plane.
  for (int j = 0; j < fr.n[1]; ++j) {
    const Point3 ylo{0, F(1, gy + j), 0}, yhi{0, F(1, gy + j + 1), 0};
    double base = 0;
    for (std::int64_t g = 0; g <= gx + fr.n[0]; ++g) {
      if (g >= gx) {
        const int i = static_cast<int>(g - gx);
        double ay = base;  // integrate upwards: A_y(k + 1) = A_y(k) - flux through the x face of cell k
        for (std::int64_t h = 0; h <= top; ++h) {
          if (h >= gz) t(1, i, j, static_cast<int>(h - gz)) = ay;
          if (h == top) break;
          ay -= q.flux(0, F(0, g), {0, ylo[1], F(2, h)}, {0, yhi[1], F(2, h + 1)});
        }
      }
      if (g == gx + fr.n[0]) break;
      base += q.flux(2, F(2, 0), {F(0, g), ylo[1], 0}, {F(0, g + 1), yhi[1], 0});
    }
  }
  // A_x along x edges at x cells (i), y faces (j): zero on the lowest plane, + flux through y faces.
  for (int j = 0; j <= fr.n[1]; ++j)
    for (int i = 0; i < fr.n[0]; ++i) {
      double ax = 0;
      for (std::int64_t h = 0; h <= top; ++h) {
        if (h >= gz) t(0, i, j, static_cast<int>(h - gz)) = ax;
        if (h == top) break;
        ax += q.flux(1, F(1, gy + j), {F(0, gx + i), 0, F(2, h)}, {F(0, gx + i + 1), 0, F(2, h + 1)});
      }
    }
  return t;
}

// How a level's edge tables are built: the potential's construction for the grid's coordinates.
struct EdgeBuilder {
  const FluxQuadrature& q;
  CoordinateSystem cs;
  bool phi_average;
  double closure;
  std::array<double, 3> xmin{}, xmax{};
  int m = 0;  // 2D: the marching direction

  // The frame of the leaf `key` of blocks shaped like b (all blocks have b's cell counts).
  Frame frame(const Block& b, const BlockKey& key) const {
    Frame f;
    const double scale = std::ldexp(1.0, b.level - key.level);  // exact: spacings halve per level
    for (std::size_t d = 0; d < 3; ++d) {
      f.used[d] = direction_used(b, static_cast<int>(d));
      f.n[d] = b.n[d];
      f.first[d] = f.used[d] ? key.index[d] * b.n[d] : 0;
      f.F.domain_lo[d] = xmin[d];
      f.F.dx[d] = f.used[d] ? b.dx[d] * scale : b.dx[d];
    }
    if (phi_average) {
      f.F.domain_lo[2] = b.face_coordinate(2, 0);
      f.phi_hi = b.face_coordinate(2, 1);
      const auto um = static_cast<std::size_t>(m);
      f.cells_m = static_cast<std::int64_t>(std::llround((xmax[um] - xmin[um]) / f.F.dx[um]));
    }
    return f;
  }
  EdgeTable edges(const Frame& f) const {
    return phi_average ? axisymmetric_edges(f, cs == CoordinateSystem::cylindrical, q, closure) : cartesian_edges(f, q);
  }
};

// Coarse-fine matching: an edge of b that lies on the boundary of a leaf one level finer takes the
// sum of that leaf's edges along it (the coincident node value along an unused direction), so
// that every face of b on the interface carries exactly the sum of the fine fluxes through it
// (the circulations around it agree) and the Grid's restriction and divergence-preserving
// prolongation see consistent levels. All blocks that share such an edge touch that leaf and make
// the same replacement; the leaf itself computes the same fine values (same sums in the same
// order). 2:1 balance across faces, edges and corners: no coarser or finer leaf touches those edges.
void match_finer_leaves(const Block& b, const Frame& fb, const EdgeBuilder& builder, std::span<const BlockKey> leaves,
                        EdgeTable& t) {
  for (const BlockKey& key : leaves) {
    if (key.level != b.level + 1) continue;
    const Frame ff = builder.frame(b, key);
    bool touches = true;  // closed boxes intersect (in the coarse level's indices, times 2)
    for (std::size_t d = 0; d < 3 && touches; ++d)
      if (fb.used[d]) touches = 2 * fb.first[d] <= ff.first[d] + ff.n[d] && ff.first[d] <= 2 * (fb.first[d] + fb.n[d]);
    if (!touches) continue;
    EdgeTable fine = builder.edges(ff);
    for (int a = 0; a < 3; ++a) {
      const auto& e = t.extent[static_cast<std::size_t>(a)];
      for (int k = 0; k < e[2]; ++k)
        for (int j = 0; j < e[1]; ++j)
          for (int i = 0; i < e[0]; ++i) {
            const std::array<int, 3> c{i, j, k};
            std::array<std::int64_t, 3> p{};  // the first fine edge, in the leaf's local indices
            for (std::size_t d = 0; d < 3; ++d) p[d] = fb.used[d] ? 2 * (fb.first[d] + c[d]) - ff.first[d] : 0;
            std::array<std::int64_t, 3> p2 = p;  // the second half along a used edge direction
            const bool halves = fb.used[static_cast<std::size_t>(a)];
            if (halves) p2[static_cast<std::size_t>(a)] += 1;
            if (!fine.contains(a, p) || !fine.contains(a, p2)) continue;
            double v = fine(a, static_cast<int>(p[0]), static_cast<int>(p[1]), static_cast<int>(p[2]));
            if (halves) v += fine(a, static_cast<int>(p2[0]), static_cast<int>(p2[1]), static_cast<int>(p2[2]));
            t(a, i, j, k) = v;
          }
    }
  }
}

}  // namespace

void import_magnetic_field(Context& ctx, const HandOffState& st) {
  const hydrobase::FieldGroups groups = hydrobase::FieldGroups::of(ctx);
  const TargetDomain& t = st.target;
  const bool data = st.source->has("Bt[0]") && !ctx.param<bool>("HandOff", "ignore_magnetic_field");
  if (data && t.dimension == 3 && t.coordinates != CoordinateSystem::cartesian)
    throw RunError("HandOff: importing the data's magnetic field onto a 3D " + t.describe() +
                   " is not implemented (Grid::coordinates = cartesian for 3D, or Grid::dimension = 2)");
  const auto xmin = ctx.param<std::vector<double>>("Grid", "xmin");
  const auto xmax = ctx.param<std::vector<double>>("Grid", "xmax");
  const double closure = ctx.param<double>("HandOff", "flux_closure_tolerance");
  if (data && t.averages_over_phi() && xmin[t.coordinates == CoordinateSystem::cylindrical ? 0 : 1] != 0.0)
    throw RunError("HandOff: the data's magnetic field is imported through the poloidal flux function from the axis: "
                   "the 2D grid must start at the axis (Grid::xmin = " + std::to_string(xmin[0]) + ", " + std::to_string(xmin[1]) + ")");
  std::unique_ptr<FluxQuadrature> q;
  std::unique_ptr<EdgeBuilder> builder;
  std::vector<BlockKey> leaves;
  if (data) {
    q = std::make_unique<FluxQuadrature>(*st.source, t.coordinates, t.averages_over_phi(),
                                         static_cast<int>(ctx.param<std::int64_t>("HandOff", "phi_samples")));
    builder = std::make_unique<EdgeBuilder>(EdgeBuilder{*q, t.coordinates, t.averages_over_phi(), closure});
    for (std::size_t d = 0; d < 3; ++d) builder->xmin[d] = xmin[d], builder->xmax[d] = xmax[d];
    builder->m = t.coordinates == CoordinateSystem::cylindrical ? 0 : 1;
    leaves = ctx.grid().all_blocks();
  }
  for (Block* b : ctx.grid().local_blocks()) {
    const std::array<Field, 3> faces{b->field(groups.bface[0], 0), b->field(groups.bface[1], 0), b->field(groups.bface[2], 0)};
    if (!data) {
      for (int g : groups.bface) std::fill(b->data(g), b->data(g) + b->size(g), 0.0);
    } else {
      const Frame fb = builder->frame(*b, BlockKey{b->level, b->index});
      EdgeTable edges = builder->edges(fb);
      match_finer_leaves(*b, fb, *builder, leaves, edges);
      hydrobase::set_faces_from_edges(*b, hydrobase::EdgeIntegrals(*b, table_potential(*b, edges), 1), faces);
      if (t.averages_over_phi()) toroidal_faces(*b, *q, faces);
    }
    hydrobase::cell_centred_field(groups, *b);
  }
}

MagneticEnergy grid_magnetic_energy(Context& ctx, bool solved_psi) {
  const hydrobase::FieldGroups groups = hydrobase::FieldGroups::of(ctx);
  double sums[2] = {0, 0};
  for (Block* b : ctx.grid().local_blocks()) {
    const std::array<Field, 3> faces{b->field(groups.bface[0], 0), b->field(groups.bface[1], 0), b->field(groups.bface[2], 0)};
    const vars::Spacetime::metric metric(ctx, *b);
    const vars::HandOff::source_at_cells sm(ctx, *b);
    for_interior(*b, [&](int i, int j, int k) {
      // psi^6 B^2 = |v|^2 / psi^2 with v the orthonormal components of psi^6 B (Analysis).
      const double psi2 = solved_psi ? metric.psi(i, j, k) * metric.psi(i, j, k)
                                     : (sm.gamma13(i, j, k) > 0 ? std::sqrt(sm.gamma13(i, j, k)) : 1.0);
      const Point3 v = hydrobase::cell_orthonormal_densitised_field(*b, faces, i, j, k);
      double tor2 = v[2] * v[2];
      if (b->coordinates == CoordinateSystem::cartesian) {
        const Point3 x = cell_point(*b, i, j, k);
        const double w2 = x[0] * x[0] + x[1] * x[1], bphi = -x[1] * v[0] + x[0] * v[1];
        tor2 = w2 > 0 ? bphi * bphi / w2 : 0.0;
      }
      const double V = b->cell_volume(i, j, k) / psi2;
      sums[0] += 0.5 * V * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      sums[1] += 0.5 * V * tor2;
    });
  }
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, ctx.comm());
  return {sums[0], sums[1]};
}

}  // namespace remnant::handoff
