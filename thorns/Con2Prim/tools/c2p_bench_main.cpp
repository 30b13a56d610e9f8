// remnant-c2p-bench: the paper's primitive-recovery benchmarks on any table. Writes
//   OUT/rhoT_<method>.tsv, OUT/Wb_<method>.tsv (per-point maps) and OUT/summary.tsv,
// and prints the summary. utils/plot_c2p draws the paper's two figures from OUT.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "Atmosphere/atmosphere.hpp"
#include "EOS/readers.hpp"
#include "EOS/units.hpp"
#include "bench_options.hpp"
#include "bench_planes.hpp"

using namespace c2p_bench;
namespace c2p = remnant::con2prim;
namespace eos = remnant::eos;

namespace {

std::string describe(const Options& o, const eos::Bounds& b) {
  char top[64] = "the table's rho_max";
  if (o.rho_T_max_cgs > 0) std::snprintf(top, sizeof top, "%g g/cm^3", o.rho_T_max_cgs);
  const std::string rho_top = top;
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "# table %s\n# rho %.4e .. %.4e g/cm^3, T %.4e .. %.4e MeV\n"
                "# rho-T plane: %d x %d, W = %g, b^2/2p = %g, Ye = %g, rho up to %s\n"
                "# W-b plane: rho = %g g/cm^3, T = %g MeV, Ye = %g, log10(W-1) %g:%g:%d, log10(b^2/2p) %g:%g:%d\n"
                "# B %s; tolerance %g, max iterations %d, eps->T %s, secant polish %s, flat metric\n",
                o.table.c_str(), b.rho_min / remnant::units::rho_cgs_to_code,
                b.rho_max / remnant::units::rho_cgs_to_code, b.T_min, b.T_max, o.n_rho, o.n_T, o.W, o.b2p, o.ye,
                rho_top.c_str(),
                o.rho_cgs, o.T, o.ye, o.log_Wm1.lo, o.log_Wm1.hi, o.log_Wm1.n, o.log_b2p.lo, o.log_b2p.hi,
                o.log_b2p.n, o.random_B ? "in random directions" : "antiparallel to v", o.settings.tolerance,
                o.settings.max_iterations, o.settings.eps_to_T == eos::InversionMethod::brent ? "brent" : "exact",
                o.settings.secant_polish ? "on" : "off");
  std::string out = buf;
  if (o.hint >= 0) {
    std::snprintf(buf, sizeof buf, "# T hint passed to recover(): T_true exp(%g u), u uniform in [-1, 1]\n", o.hint);
    out += buf;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  bool ok;
  if (!parse_options(argc, argv, o, ok)) return ok ? 0 : (argc > 1 && std::string(argv[1]) == "--help" ? 0 : 2);
  try {
    const auto table = eos::load_table(o.table);
    try {
      check_against_table(o, table->bounds);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "remnant-c2p-bench: %s\n", e.what());
      return 2;
    }
    const eos::Tabulated<> plain(table);
    const eos::Tabulated<eos::CountCalls> counted(table);
    remnant::atmosphere::Atmosphere atm;
    atm.rho_thr = o.rho_thr;
    std::filesystem::create_directories(o.out_dir);

    const std::string header = describe(o, plain.bounds());
    std::fputs(header.c_str(), stdout);
    const std::string summary_path = o.out_dir + "/summary.tsv";
    FILE* sum = std::fopen(summary_path.c_str(), "w");
    if (!sum) throw std::runtime_error("cannot write " + summary_path);
    std::fputs(header.c_str(), sum);
    std::fprintf(sum, "plane\tmethod\tpoints\tmean_eps_recov\tmax_eps_recov\tmean_iterations\tmax_iterations\t"
                      "mean_evaluations\tmean_eos_calls\tfailures\tflagged\tsilently_wrong\tpolicy\tnan\timprecise\t"
                      "ns_per_recovery\n");
    std::printf("%-5s %-10s %7s %10s %10s %7s %4s %7s %9s %8s %7s %6s %6s %4s %9s %9s\n", "plane", "method",
                "points", "eps_recov", "max", "iter", "max", "evals", "eos_calls", "failures", "flagged", "silent",
                "policy", "nan", "imprecise", "ns/recov");

    std::vector<Plane> planes;
    if (o.fuzz > 0) {
      planes.push_back(fuzz_states(plain, o));
    } else {
      if (o.plane_rho_T) planes.push_back(rho_T_plane(plain, o));
      if (o.plane_W_b) planes.push_back(W_b_plane(plain, o));
    }
    for (Plane& plane : planes) add_hints(plane, o);
    std::size_t bad = 0;
    for (const Plane& plane : planes) {
      for (c2p::Method m : o.methods) {
        c2p::Settings s = o.settings;
        s.method = m;
        const auto results = run_counted(counted, s, atm, plane);
        Summary su = summarise(results, s.accuracy);
        bad += su.silently_wrong + su.nan;
        if (o.time_it) su.ns_per_recovery = time_ns_per_recovery(plain, s, atm, plane, o.min_time);
        write_tsv(o.out_dir + "/" + plane.name + "_" + c2p::to_string(m) + ".tsv", plane, results);
        std::printf("%-5s %-10s %7zu %10.3e %10.3e %7.3f %4d %7.3f %9.2f %8zu %7zu %6zu %6zu %4zu %9zu %9.1f\n",
                    plane.name.c_str(), c2p::to_string(m), su.points, su.mean_eps_recov, su.max_eps_recov,
                    su.mean_iterations, su.max_iterations, su.mean_evaluations, su.mean_eos_calls, su.failures,
                    su.flagged, su.silently_wrong, su.policy, su.nan, su.imprecise, su.ns_per_recovery);
        std::fprintf(sum, "%s\t%s\t%zu\t%.6e\t%.6e\t%.4f\t%d\t%.4f\t%.3f\t%zu\t%zu\t%zu\t%zu\t%zu\t%zu\t%.2f\n",
                     plane.name.c_str(), c2p::to_string(m), su.points, su.mean_eps_recov, su.max_eps_recov,
                     su.mean_iterations, su.max_iterations, su.mean_evaluations, su.mean_eos_calls, su.failures,
                     su.flagged, su.silently_wrong, su.policy, su.nan, su.imprecise, su.ns_per_recovery);
      }
    }
    std::fclose(sum);
    std::printf("wrote %s/<plane>_<method>.tsv and summary.tsv\n", o.out_dir.c_str());
    std::printf("  iter: root-finder steps on the master function; evals: master-function evaluations (steps +\n"
                "  bracket ends); failures: not converged, no bracket, non-finite or atmosphere; flagged: status\n"
                "  inaccurate or ambiguous; silent: status ok but the primitives miss the conserved variables by\n"
                "  more than the accuracy %g with no policy rule fired (silently wrong); policy: the same with a\n"
                "  state-moving policy rule fired (reported by its count); nan: NaN/inf primitives; imprecise: ok, the\n"
                "  conserved variables reproduced, but eps_recov > 1e-8 (ill-conditioned: they allow no better)\n",
                o.settings.accuracy);
    if (o.fuzz > 0 && bad > 0) {
      std::fprintf(stderr, "remnant-c2p-bench: %zu silently wrong or NaN recoveries\n", bad);
      return 3;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "remnant-c2p-bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
