// Test helper: the magnetised TOV star as 3D Carpet data and its hand-off (magnetised_tov.hpp).
#include "magnetised_tov.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <span>

#include "HydroBase/vector_potential.hpp"
#include "remnant/cell_geometry.hpp"
#include "remnant/coordinates.hpp"
#include "remnant/driver.hpp"
#include "synthetic_carpet.hpp"


namespace remnant::handoff::testing {

// max(p - p_cut, 0) and its radial derivative (central difference of the TOV table).
double MagnetisedTov::P(double r) const { return std::max(star.at(r).press - p_cut, 0.0); }
double MagnetisedTov::dP(double r) const {
  const double h = 1e-3;
  return P(r) > 0 ? (star.at(r + h).press - star.at(std::abs(r - h)).press) / (2 * h) : 0.0;
}

std::array<double, 3> MagnetisedTov::densitised(double x, double y, double z) const {
  const double r = std::sqrt(x * x + y * y + z * z);
  const double p = P(r);
  const auto& u = options.uniform;
  if (p <= 0) return u;
  const double g = r > 0 ? 2 * kAb * p * dP(r) / r : 0.0;  // d(A_b P^2)/dx^i = g x^i
  const double t = options.toroidal * p * p * z;          // B^phi (coordinate), densitised
  if (options.octant_symmetric)  // curl of A_b P^2 (x, -y, 0), plus the toroidal field
    return {u[0] + g * y * z - t * y, u[1] + g * x * z + t * x, u[2] - 2 * g * x * y};
  return {u[0] - g * x * z - t * y, u[1] - g * y * z + t * x, u[2] + 2 * kAb * p * p + g * (x * x + y * y)};
}

namespace {

// One folder per data set (several live at once in one process).
std::string folder_of(const MagnetisedTovOptions& o) {
  std::string name = std::string("handoff_mag") + (o.fine ? "_fine" : "") + (o.toroidal == 0 ? "_pol" : "") +
                     (o.octant_symmetric ? "_oct" : "") + (o.uniform != std::array<double, 3>{} ? "_uni" : "");
  for (int d = 0; d < 3; ++d)
    if (o.mirrors[static_cast<std::size_t>(d)]) name += "_m" + std::to_string(d);
  return name;
}

}  // namespace

MagnetisedTov::MagnetisedTov(const MagnetisedTovOptions& o) : TovCarpetData(folder_of(o)), options(o) {
  synthetic::SyntheticCarpet spec;
  spec.variables = {"HYDROBASE::rho", "HYDROBASE::press", "HYDROBASE::eps", "HYDROBASE::vel[0]", "HYDROBASE::vel[1]",
                    "HYDROBASE::vel[2]", "HYDROBASE::Bvec[0]", "HYDROBASE::Bvec[1]", "HYDROBASE::Bvec[2]", "ADMBASE::alp",
                    "ADMBASE::gxx", "ADMBASE::gxy", "ADMBASE::gxz", "ADMBASE::gyy", "ADMBASE::gyz", "ADMBASE::gzz"};
  spec.reflection = o.mirrors;
  spec.levels = {{1.0, {-15.5, -15.5, -15.5}, {32, 32, 32}, 0}, {0.5, {-10, -10, -10}, {41, 41, 41}, 1}};
  if (o.fine) spec.levels.push_back({0.25, {-9, -9, -9}, {73, 73, 73}, 2});
  for (auto& l : spec.levels)  // a mirrored direction keeps the nodes at x >= 0
    for (std::size_t d = 0; d < 3; ++d)
      if (o.mirrors[d]) {
        const int below = static_cast<int>(std::ceil(-l.first[d] / l.h - 1e-9));
        l.first[d] += below * l.h;
        l.nodes[d] -= below;
      }
  spec.iterations = {1024};
  write(spec, [this](const std::string& v, int, double x, double y, double z) {
    const tov::TovPoint p = star.at(std::sqrt(x * x + y * y + z * z));
    const double psi6 = std::pow(p.psi, 6);
    for (int c = 0; c < 3; ++c)
      if (v == "HYDROBASE::Bvec[" + std::to_string(c) + "]") return densitised(x, y, z)[static_cast<std::size_t>(c)] / psi6;
    if (v == "HYDROBASE::rho") return p.rho;
    if (v == "HYDROBASE::press") return p.press;
    if (v == "HYDROBASE::eps") return p.eps;
    if (v == "ADMBASE::alp") return p.alpha;
    if (v == "ADMBASE::gxx" || v == "ADMBASE::gyy" || v == "ADMBASE::gzz") return std::pow(p.psi, 4);
    return 0.0;
  });
}

// Gauss-Legendre in r (the field has a kink at p = p_cut) and theta, over the first quadrant of
// the (varpi, z) plane.
MagnetisedTov::Energy MagnetisedTov::exact_upper_half() const {
  double r_cut = 0;
  for (double r = 0; r < star.isotropic_radius(); r += 1e-4) r_cut = P(r) > 0 ? r : r_cut;
  std::vector<double> xr, wr, xt, wt;
  hydrobase::gauss_legendre(16, xr, wr);
  hydrobase::gauss_legendre(16, xt, wt);
  Energy e;
  const int pieces = 32;
  for (int a = 0; a < pieces; ++a)
    for (std::size_t i = 0; i < xr.size(); ++i) {
      const double r = r_cut * (a + 0.5 * (1 + xr[i])) / pieces, w_r = wr[i] * 0.5 * r_cut / pieces;
      const double psi2 = std::pow(star.at(r).psi, 2);
      for (int b = 0; b < 4; ++b)
        for (std::size_t j = 0; j < xt.size(); ++j) {
          const double th = 0.5 * std::numbers::pi * (b + 0.5 * (1 + xt[j])) / 4, w_t = wt[j] * 0.25 * std::numbers::pi / 4;
          const double x = r * std::sin(th), z = r * std::cos(th);
          const auto B = densitised(x, 0, z);
          const double w = 2 * std::numbers::pi * r * r * std::sin(th) * w_r * w_t * 0.5 / psi2;
          e.total += w * (B[0] * B[0] + B[1] * B[1] + B[2] * B[2]);
          e.toroidal += w * B[1] * B[1];
        }
    }
  return e;
}

double field_outside(Context& ctx) {
  const int g[3] = {ctx.var("HydroBase::Bface1"), ctx.var("HydroBase::Bface2"), ctx.var("HydroBase::Bface3")};
  double m = 0;
  for (Block* b : ctx.grid().local_blocks())
    for_interior(*b, [&](int i, int j, int k) {
      const Point3 X = coords::to_cartesian(b->coordinates, cell_point(*b, i, j, k));
      if (X[0] * X[0] + X[1] * X[1] + X[2] * X[2] < 81) return;
      for (int d = 0; d < 3; ++d) {
        if (!direction_used(*b, d)) continue;  // phi of a 2D grid: B^phi, no flux to close
        const Field F = b->field(g[d], 0);
        m = std::max({m, std::abs(F(i, j, k)), std::abs(F(i + (d == 0), j + (d == 1), k + (d == 2)))});
      }
    });
  MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return m;
}

std::string parfile_without_metric_solve() {
  std::ifstream in(std::string(REMNANT_SOURCE_DIR) + "/parfiles/handoff_tov_cyl_2d.yaml");
  std::string out, line;
  bool in_xcfc = false;
  while (std::getline(in, line)) {
    if (line.rfind("XCFC:", 0) == 0) in_xcfc = true;
    else if (!line.empty() && line[0] != ' ' && line[0] != '#') in_xcfc = false;
    if (in_xcfc) continue;
    if (line.rfind("active_thorns:", 0) == 0)
      if (const auto p = line.find(", XCFC"); p != std::string::npos) line.erase(p, 6);
    out += line + "\n";
  }
  return out;
}

Result hand_off(const MagnetisedTov& data, const std::vector<std::string>& overrides,
                const std::function<void(Context&, Result&)>& inspect, const std::string* parfile_text) {
  SimulationOptions o = handoff_test::handoff_options(
      data, {"HydroBase::magnetic_field=evolved", "MoL::final_time=0", "HandOff::buffer_zones=2", "Analysis::every=1",
             "Flesh::out_dir=" + (data.dir / "out").string()});
  o.parfile_text = parfile_text;
  o.overrides.insert(o.overrides.end(), overrides.begin(), overrides.end());
  Simulation sim(handoff_test::compiled_catalog(), o, MPI_COMM_WORLD);
  sim.setup_output_and_grid();
  sim.run();
  Result r;
  r.report = sim.context().service<handoff::HandOffState>("HandOff::state").report;
  const auto& rows = sim.context().service<analysis::History>("Analysis::history").rows;
  r.first = rows.front();
  r.last = rows.back();
  r.outside = field_outside(sim.context());
  r.interface_mismatch = interface_flux_mismatch(sim.context());
  if (inspect) inspect(sim.context(), r);
  return r;
}

double interface_flux_mismatch(Context& ctx) {
  const int g[3] = {ctx.var("HydroBase::Bface1"), ctx.var("HydroBase::Bface2"), ctx.var("HydroBase::Bface3")};
  const auto blocks = ctx.grid().local_blocks();
  double largest = 0, mismatch = 0;
  for (Block* b : blocks)
    for (int d = 0; d < 3; ++d) {
      if (!direction_used(*b, d)) continue;
      const Field F = b->field(g[d], 0);
      for_interior(*b, [&](int i, int j, int k) { largest = std::max(largest, std::abs(F(i, j, k) * b->face_area(d, i, j, k))); });
    }
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  for (Block* c : blocks)
    for (Block* f : blocks) {
      if (f->level != c->level + 1) continue;
      for (int d = 0; d < 3; ++d) {
        if (!direction_used(*c, d)) continue;
        for (int side = 0; side < 2; ++side) {  // the coarse block's lower (0) or upper (1) face
          const int ic = side ? c->n[static_cast<std::size_t>(d)] : 0, jf = side ? 0 : f->n[static_cast<std::size_t>(d)];
          if (std::abs(c->face_coordinate(d, ic) - f->face_coordinate(d, jf)) > 1e-12 * (1 + std::abs(c->face_coordinate(d, ic))))
            continue;
          // Sum the fine fluxes into the coarse faces they lie on.
          std::vector<double> sum(static_cast<std::size_t>(c->n[0] * c->n[1] * c->n[2]), 0.0);
          std::vector<char> hit(sum.size(), 0);
          const Field Ff = f->field(g[d], 0);
          for_interior(*f, [&](int i, int j, int k) {
            int p[3] = {i, j, k};
            if (p[d] != 0) return;  // one plane of faces
            p[d] = jf;
            int q[3] = {0, 0, 0};
            for (int e = 0; e < 3; ++e) {
              if (e == d || !direction_used(*c, e)) continue;
              const double x = 0.5 * (f->face_coordinate(e, p[e]) + f->face_coordinate(e, p[e] + 1));
              q[e] = static_cast<int>(std::floor((x - c->face_coordinate(e, 0)) / c->dx[static_cast<std::size_t>(e)]));
              if (q[e] < 0 || q[e] >= c->n[static_cast<std::size_t>(e)]) return;
            }
            const auto u = static_cast<std::size_t>(q[0] + c->n[0] * (q[1] + c->n[1] * q[2]));
            sum[u] += Ff(p[0], p[1], p[2]) * f->face_area(d, p[0], p[1], p[2]);
            hit[u] = 1;
          });
          const Field Fc = c->field(g[d], 0);
          for (int k = 0; k < c->n[2]; ++k)
            for (int j = 0; j < c->n[1]; ++j)
              for (int i = 0; i < c->n[0]; ++i) {
                const auto u = static_cast<std::size_t>(i + c->n[0] * (j + c->n[1] * k));
                if (!hit[u]) continue;
                int p[3] = {i, j, k};
                p[d] = ic;
                mismatch = std::max(mismatch, std::abs(Fc(p[0], p[1], p[2]) * c->face_area(d, p[0], p[1], p[2]) - sum[u]));
              }
        }
      }
    }
  MPI_Allreduce(MPI_IN_PLACE, &mismatch, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return largest > 0 ? mismatch / largest : 0.0;
}

std::vector<std::string> with(std::vector<std::string> v, const std::vector<std::string>& more) {
  v.insert(v.end(), more.begin(), more.end());
  return v;
}

}  // namespace remnant::handoff::testing
