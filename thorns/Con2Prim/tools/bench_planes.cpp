// Sampling, recovery and measurement for remnant-c2p-bench.
#include "bench_planes.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "Con2Prim/prim_to_cons.hpp"
#include "Con2Prim/recover.hpp"
#include "Con2Prim/residual.hpp"
#include "Con2Prim/state_builder.hpp"
#include "EOS/units.hpp"

namespace c2p_bench {

using namespace remnant::con2prim;
namespace eos = remnant::eos;

namespace {

// Uniformly distributed unit vectors; B antiparallel to v unless random_B.
struct Directions {
  std::mt19937_64 rng;
  bool random_B;
  Vec3 unit() {
    std::normal_distribution<double> n;
    Vec3 d{n(rng), n(rng), n(rng)};
    const double s = std::sqrt(dot(d, d));
    for (double& x : d) x /= s;
    return d;
  }
  void next(Vec3& v, Vec3& B) {
    v = unit();
    if (random_B) B = unit();
    else B = {-v[0], -v[1], -v[2]};
  }
};

double vec_rel(const Vec3& got, const Vec3& want) {
  double d = 0, n = 0;
  for (int i = 0; i < 3; ++i) d += (got[i] - want[i]) * (got[i] - want[i]), n += want[i] * want[i];
  return n > 0 ? std::sqrt(d / n) : std::sqrt(d);
}
double rel(double got, double want) { return want != 0 ? std::abs(1 - got / want) : std::abs(got); }

}  // namespace

Plane rho_T_plane(const eos::Tabulated<>& e, const Options& o) {
  const eos::Bounds& b = e.bounds();
  Plane p{"rhoT", "log10_rho_cgs", "log10_T_MeV", {}};
  Directions dir{std::mt19937_64(o.seed), o.random_B};
  const double rho_hi = o.rho_T_max_cgs > 0 ? std::min(b.rho_max, o.rho_T_max_cgs * remnant::units::rho_cgs_to_code)
                                            : b.rho_max;
  const double lr0 = std::log10(b.rho_min), lr1 = std::log10(rho_hi);
  const double lt0 = std::log10(b.T_min), lt1 = std::log10(b.T_max);
  const Metric3 g = Metric3::flat();
  for (int j = 0; j < o.n_T; ++j)
    for (int i = 0; i < o.n_rho; ++i) {
      const double lr = lr0 + (lr1 - lr0) * (i + 0.5) / o.n_rho, lt = lt0 + (lt1 - lt0) * (j + 0.5) / o.n_T;
      Vec3 v, B;
      dir.next(v, B);
      PlanePoint pt;
      pt.x = lr - std::log10(remnant::units::rho_cgs_to_code);
      pt.y = lt;
      pt.orig = make_state(e, g, std::pow(10.0, lr), std::pow(10.0, lt), o.ye, o.W, o.b2p, v, B);
      p.points.push_back(pt);
    }
  return p;
}

Plane W_b_plane(const eos::Tabulated<>& e, const Options& o) {
  Plane p{"Wb", "log10_W_minus_1", "log10_b2_over_2p", {}};
  Directions dir{std::mt19937_64(o.seed), o.random_B};
  const double rho = o.rho_cgs * remnant::units::rho_cgs_to_code;
  const Metric3 g = Metric3::flat();
  auto at = [](const Range& r, int k) { return r.n > 1 ? r.lo + (r.hi - r.lo) * k / (r.n - 1) : r.lo; };
  for (int j = 0; j < o.log_b2p.n; ++j)
    for (int i = 0; i < o.log_Wm1.n; ++i) {
      Vec3 v, B;
      dir.next(v, B);
      PlanePoint pt;
      pt.x = at(o.log_Wm1, i);
      pt.y = at(o.log_b2p, j);
      pt.orig = make_state(e, g, rho, o.T, o.ye, 1 + std::pow(10.0, pt.x), std::pow(10.0, pt.y), v, B);
      p.points.push_back(pt);
    }
  return p;
}

Plane fuzz_states(const eos::Tabulated<>& e, const Options& o) {
  const eos::Bounds& b = e.bounds();
  Plane p{"fuzz", "log10_rho_cgs", "log10_T_MeV", {}};
  std::mt19937_64 rng(o.seed);
  auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  Directions dir{std::mt19937_64(o.seed + 1), true};
  const Metric3 g = Metric3::flat();
  const double to_cgs = -std::log10(remnant::units::rho_cgs_to_code);
  p.points.reserve(o.fuzz);
  for (std::size_t k = 0; k < o.fuzz; ++k) {
    const double lr = uni(std::log10(b.rho_min), std::log10(b.rho_max));
    const double lt = uni(std::log10(b.T_min), std::log10(b.T_max));
    const double ye = uni(b.ye_min, b.ye_max);
    const double W = std::pow(10.0, uni(0.0, 4.0)), b2p = std::pow(10.0, uni(-10.0, 10.0));
    Vec3 v, B;
    dir.next(v, B);
    PlanePoint pt;
    pt.x = lr + to_cgs;
    pt.y = lt;
    pt.orig = make_state(e, g, std::pow(10.0, lr), std::pow(10.0, lt), ye, W, b2p, v, B);
    p.points.push_back(pt);
  }
  return p;
}

void add_hints(Plane& plane, const Options& o) {
  if (o.hint < 0) return;
  std::mt19937_64 rng(o.seed + 2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (PlanePoint& pt : plane.points) pt.T_hint = pt.orig.T * std::exp(o.hint * u(rng));
}

double eps_recov(const Primitives& got, const Primitives& orig) {
  return (rel(got.rho, orig.rho) + vec_rel(got.v, orig.v) + rel(got.eps, orig.eps) + vec_rel(got.B, orig.B) +
          rel(got.ye, orig.ye)) /
         5;
}

std::vector<PointResult> run_counted(const eos::Tabulated<eos::CountCalls>& e, const Settings& s,
                                     const remnant::atmosphere::Atmosphere& atm, const Plane& plane) {
  std::vector<PointResult> out;
  out.reserve(plane.points.size());
  const Metric3 g = Metric3::flat();
  for (const PlanePoint& pt : plane.points) {
    Conserved c = prim_to_cons(pt.orig, g);
    Primitives got;
    const Report rep = recover(e, s, atm, g, c, got, pt.T_hint);
    PointResult r;
    r.eps_recov = eps_recov(got, pt.orig);
    r.iterations = rep.iterations;
    r.evaluations = rep.evaluations;
    r.eos_calls = rep.eos_calls;
    r.status = rep.status;
    r.rules = rep.rules;
    r.root_scan = rep.root_scan;
    r.residual = conserved_residual(prim_to_cons(got, g), prim_to_cons(pt.orig, g), g);
    r.nan = !(std::isfinite(got.rho) && std::isfinite(got.eps) && std::isfinite(got.W) && std::isfinite(got.press) &&
              std::isfinite(got.T) && std::isfinite(got.v[0]) && std::isfinite(got.v[1]) && std::isfinite(got.v[2]));
    out.push_back(r);
  }
  return out;
}

double time_ns_per_recovery(const eos::Tabulated<>& e, const Settings& s, const remnant::atmosphere::Atmosphere& atm,
                            const Plane& plane, double min_seconds) {
  const Metric3 g = Metric3::flat();
  std::vector<Conserved> cons;
  for (const PlanePoint& pt : plane.points) cons.push_back(prim_to_cons(pt.orig, g));
  using clock = std::chrono::steady_clock;
  double sink = 0;
  std::size_t done = 0;
  const auto t0 = clock::now();
  double elapsed = 0;
  while (elapsed < min_seconds) {
    const PlanePoint* pt = plane.points.data();
    for (const Conserved& c0 : cons) {
      Conserved c = c0;
      Primitives p;
      recover(e, s, atm, g, c, p, (pt++)->T_hint);
      sink += p.rho;
    }
    done += cons.size();
    elapsed = std::chrono::duration<double>(clock::now() - t0).count();
  }
  volatile double keep = sink;
  (void)keep;
  return elapsed * 1e9 / double(done);
}

Summary summarise(const std::vector<PointResult>& r, double accuracy) {
  Summary s;
  s.points = r.size();
  double se = 0, si = 0, sv = 0, sc = 0;
  for (const PointResult& p : r) {
    s.nan += p.nan;
    if (p.status == Status::inaccurate || p.status == Status::ambiguous) ++s.flagged;
    else if (p.status != Status::ok) ++s.failures;
    else if (p.residual > accuracy && (p.rules & detail::kRulesMovingState)) ++s.policy;
    else if (p.residual > accuracy) ++s.silently_wrong;
    else if (p.eps_recov > 1e-8) ++s.imprecise;
    se += p.eps_recov;
    s.max_eps_recov = std::max(s.max_eps_recov, p.eps_recov);
    si += p.iterations;
    sv += p.evaluations;
    sc += double(p.eos_calls);
    s.max_iterations = std::max(s.max_iterations, p.iterations);
  }
  const double n = r.empty() ? 1.0 : double(r.size());
  s.mean_eps_recov = se / n;
  s.mean_iterations = si / n;
  s.mean_evaluations = sv / n;
  s.mean_eos_calls = sc / n;
  return s;
}

void write_tsv(const std::string& path, const Plane& plane, const std::vector<PointResult>& r) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  std::fprintf(f, "%s\t%s\teps_recov\titerations\tevaluations\teos_calls\tstatus\tresidual\trules\troot_scan\n",
               plane.x_name.c_str(), plane.y_name.c_str());
  for (std::size_t k = 0; k < r.size(); ++k)
    std::fprintf(f, "%.6f\t%.6f\t%.6e\t%d\t%d\t%llu\t%s\t%.3e\t0x%x\t%d\n", plane.points[k].x, plane.points[k].y,
                 r[k].eps_recov, r[k].iterations, r[k].evaluations, (unsigned long long)r[k].eos_calls,
                 to_string(r[k].status), r[k].residual, r[k].rules, int(r[k].root_scan));
  std::fclose(f);
}

}  // namespace c2p_bench
