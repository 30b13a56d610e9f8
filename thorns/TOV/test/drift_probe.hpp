#pragma once
// Drift norms of a static star, sampled every Analysis iteration: Analysis_Star is wrapped (as the
// rotating-flow test wraps GRMHD's initial data) so that after each row it also measures how far
// rho has moved from its initial profile.
//  - mass: sum_cells w |rho - rho0| / sum_cells w rho0 with w = psi0^6 dV (psi0, rho0 at t = 0), over
//    the whole grid: the rest-mass-weighted mean of |rho/rho0 - 1| (each shell counts by its mass;
//    mass that leaves the star for the atmosphere counts fully). A packet of width dx focused at
//    r = 0 weighs ~ dx^3 here, so the norm measures the star, not the focusing at the centre.
//  - centre: |rho_c/rho_c0 - 1| (the cell nearest the origin), for comparison.
#include <mpi.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

#include "remnant/driver.hpp"
#include "remnant/forwarding_registrar.hpp"
#include "remnant/vars/HydroBase.hpp"
#include "remnant/vars/Spacetime.hpp"

std::span<const remnant::ThornEntry> remnant_compiled_thorns();

namespace remnant::test {

struct DriftSample {
  double time, mass, centre;
};

struct DriftProbe {
  std::map<std::int64_t, std::vector<double>> rho0, weight;  // per block gid, interior cells
  double mass0 = 0;
  std::vector<DriftSample> series;
  double snapshot_time = -1;                   // > 0: keep (r, rho0, rho) of the first sample at or after it
  std::vector<std::array<double, 3>> snapshot;
};

inline DriftProbe& drift_probe() {
  static DriftProbe probe;
  return probe;
}

inline void measure_drift(Context& ctx) {
  using Prim = vars::HydroBase::prim;
  using Metric = vars::Spacetime::metric;
  DriftProbe& p = drift_probe();
  const bool first = p.series.empty();
  double num = 0, centre = 0, r_min = 1e300;
  const bool snap = p.snapshot_time > 0 && p.snapshot.empty() && ctx.time() >= p.snapshot_time;
  for (Block* b : ctx.grid().local_blocks()) {
    const Field rho = Prim(ctx, *b).field(Prim::idx::rho);
    const Field psi = Metric(ctx, *b).field(Metric::idx::psi);
    auto& r0 = p.rho0[b->gid];
    auto& w = p.weight[b->gid];
    std::size_t c = 0;
    for_interior(*b, [&](int i, int j, int k) {
      if (first) {
        r0.push_back(rho(i, j, k));
        w.push_back(std::pow(psi(i, j, k), 6) * b->cell_volume(i, j, k));
        p.mass0 += w.back() * r0.back();
      }
      num += w[c] * std::abs(rho(i, j, k) - r0[c]);
      const double r = b->centroid(0, i);
      if (snap) p.snapshot.push_back({r, r0[c], rho(i, j, k)});
      if (r < r_min) r_min = r, centre = std::abs(rho(i, j, k) / r0[c] - 1);
      ++c;
    });
  }
  p.series.push_back({ctx.time(), num / p.mass0, centre});
}

// Forwards a thorn's registration, with Analysis_Star followed by measure_drift.
class WithDriftProbe : public ForwardingRegistrar {
 public:
  using ForwardingRegistrar::ForwardingRegistrar;
  void function(const std::string& name, ScheduledFunction fn) override {
    if (name != "Analysis_Star") return ForwardingRegistrar::function(name, std::move(fn));
    ForwardingRegistrar::function(name, [fn = std::move(fn)](Context& ctx) {
      fn(ctx);
      measure_drift(ctx);
    });
  }
};

inline void (*analysis_register)(ThornRegistrar&) = nullptr;
inline void register_analysis_with_probe(ThornRegistrar& r) {
  WithDriftProbe w(r);
  analysis_register(w);
}

inline const ThornCatalog& drift_catalog() {
  static const std::vector<ThornEntry> entries = [] {
    std::vector<ThornEntry> e(remnant_compiled_thorns().begin(), remnant_compiled_thorns().end());
    for (ThornEntry& t : e)
      if (std::string(t.name) == "Analysis") {
        analysis_register = t.register_fn;
        t.register_fn = register_analysis_with_probe;
      }
    return e;
  }();
  static const ThornCatalog catalog(entries);
  return catalog;
}

// Runs the parfile (one rank) with the overrides and returns the drift series, one sample per step.
inline std::vector<DriftSample> drift_series(const std::string& parfile, std::vector<std::string> overrides) {
  SimulationOptions o;
  o.parfile_path = std::string(REMNANT_SOURCE_DIR) + "/parfiles/" + parfile;
  o.quiet = true;
  const auto out = std::filesystem::temp_directory_path() / ("remnant_drift_" + std::to_string(::getpid()));
  overrides.push_back("Flesh::out_dir=" + out.string());
  overrides.push_back("Analysis::every=1");
  o.overrides = std::move(overrides);
  const double snapshot_time = drift_probe().snapshot_time;
  drift_probe() = DriftProbe{};
  drift_probe().snapshot_time = snapshot_time;
  {
    Simulation sim(drift_catalog(), o, MPI_COMM_SELF);
    sim.setup_output_and_grid();
    sim.run();
  }
  std::filesystem::remove_all(out);
  return std::move(drift_probe().series);
}

// Largest value of a norm over samples with time <= t_max.
inline double max_until(const std::vector<DriftSample>& s, double t_max, double DriftSample::*norm) {
  double m = 0;
  for (const DriftSample& d : s)
    if (d.time <= t_max + 1e-9) m = std::max(m, d.*norm);
  return m;
}

}  // namespace remnant::test
