// The root scan's jumps over stretches clamped by rule 9 (root_scan.hpp,
// KastaunSolver::clamped_high_between): wherever the proof says a stretch of the bracket is clamped,
// every point inside must evaluate clamped (else a root there could be acceptable and be skipped).
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "Con2Prim/kastaun.hpp"
#include "Con2Prim/prim_to_cons.hpp"
#include "Con2Prim/root_scan.hpp"
#include "Con2Prim/state_builder.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "c2p_test_util.hpp"

using namespace remnant::con2prim;
namespace eos = remnant::eos;

TEST(Con2PrimScanJump, AStretchProvenClampedByRule9IsClampedEverywhere) {
  const std::string path = c2p_test::shared_eos("SRO_LS220_157r_89t_49y.h5");
  if (!std::filesystem::exists(path)) {
    std::printf("REMNANT_TEST_SKIPPED: no table %s\n", path.c_str());
    return;
  }
  const eos::Tabulated<> e(eos::load_table(path));
  const eos::Bounds& b = e.bounds();
  const Metric3 g = Metric3::flat();
  Settings s;
  int proven = 0, checked = 0, refused = 0, must_refuse = 0;
  // The rho-T plane's hot dense corner (where the scans run) and a spread of W and fields.
  for (double W : {1.2, 2.0, 5.0})
    for (double b2p : {1e-3, 1.0})
      for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
          const double rho = b.rho_max * std::pow(10.0, -1.5 * (i + 0.5) / 8);
          const double T = b.T_min * std::pow(b.T_max / b.T_min, (j + 0.5) / 8);
          const Primitives p = make_state(e, g, rho, T, 0.1, W, b2p, {0.6, 0.64, 0.48}, {-0.6, -0.64, -0.48});
          const Conserved c = prim_to_cons(p, g);
          KastaunSolver<eos::Tabulated<>> solver(e, s, g, c, 0.1);
          MasterEval lo, hi;
          RootSolution out;
          if (!solver.bracket(lo, hi, out)) continue;
          auto at = [&](double t) { return solver(lo.x + (hi.x - lo.x) * t); };
          // The scan's jumps, and longer stretches (where the clamped run ends inside, the proof
          // must refuse: both ends clamped, a point inside not).
          for (int span : {kScanJump, 4 * kScanJump, kScanIntervals})
            for (int k = 0; k + span <= kScanIntervals; k += span / 2) {
              const MasterEval a = at(double(k) / kScanIntervals), z = at(double(k + span) / kScanIntervals);
              const bool ends = a.inv_flags & z.inv_flags & eos::kInvAboveEpsHigh;
              bool inside = true;
              if (ends)
                for (int m = 1; m < 4 * span; ++m, ++checked)
                  inside = inside && (at((k + m / 4.0) / kScanIntervals).inv_flags & eos::kInvAboveEpsHigh);
              const bool proof = solver.clamped_high_between(a, z);
              proven += proof;
              refused += ends && !proof;
              must_refuse += ends && !inside;
              if (proof) EXPECT_TRUE(inside) << "rho " << rho << " T " << T << " W " << W << " k " << k;
            }
        }
  std::printf("[ LS220 ] %d stretches proven clamped (%d points inside checked), %d with both ends clamped "
              "not proven, %d of them not clamped inside\n", proven, checked, refused, must_refuse);
  EXPECT_GT(proven, 100);      // the proof is not vacuous
  EXPECT_GT(must_refuse, 10);  // and the check can fail
}
