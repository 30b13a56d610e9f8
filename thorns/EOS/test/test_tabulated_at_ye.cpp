// TabulatedAtYe (the fixed-Ye slice used by the primitive recovery): the same T, eps, p and flags as
// Tabulated::temperature followed by press, on random points of both shared tables (rules 8/9,
// non-monotone cells, any guess and hint); the hint changes only the cost; its table-call counts.
#include <cmath>
#include <random>

#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "EOS/tabulated_at_ye.hpp"
#include "eos_test_util.hpp"

using namespace remnant::eos;

namespace {

const char* kTables[] = {"SFHo_reduced_39r_39t_20y.h5", "SRO_LS220_157r_89t_49y.h5"};

struct Sample {
  double rho, ye, eps, T_true;
};

// rho, T log-uniform, Ye uniform over the table; eps from (rho, T, Ye), one in 8 pushed below
// eps_low (rule 8) and one in 8 above eps_high (rule 9).
Sample sample(const Tabulated<>& e, std::mt19937_64& rng, int k) {
  std::uniform_real_distribution<double> u(0, 1);
  const Bounds& b = e.bounds();
  Sample s;
  s.rho = b.rho_min * std::pow(b.rho_max / b.rho_min, u(rng));
  s.T_true = b.T_min * std::pow(b.T_max / b.T_min, u(rng));
  s.ye = b.ye_min + (b.ye_max - b.ye_min) * u(rng);
  s.eps = e.eps(s.rho, s.T_true, s.ye);
  const EpsRange r = e.eps_range(s.rho, s.ye);
  if (k % 8 == 1) s.eps = r.low - (0.01 + u(rng)) * std::abs(r.low);
  if (k % 8 == 2) s.eps = r.high + (0.01 + u(rng)) * std::abs(r.high);
  return s;
}

// d ln(eps + shift) / d ln T at T: where it is tiny, T is ill-determined by eps (round-off in the
// node values moves T by round-off / slope), so T is compared through eps there.
double slope(const Tabulated<>& e, const Sample& s, double T) {
  const double sh = e.table().eps_shift;
  return (std::log(e.eps(s.rho, T * 1.001, s.ye) + sh) - std::log(e.eps(s.rho, T / 1.001, s.ye) + sh)) /
         (2 * std::log(1.001));
}

}  // namespace

TEST(EOSTabulatedAtYe, EqualsThePlainInversionAndPressureOnRandomPoints) {
  for (const char* name : kTables) {
    const std::string path = eos_test::shared_eos(name);
    if (!std::filesystem::exists(path)) {
      std::printf("REMNANT_TEST_SKIPPED: no table %s\n", path.c_str());
      continue;
    }
    const Tabulated<> e(load_table(path));
    const Bounds& b = e.bounds();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    int tested = 0, rule8 = 0, rule9 = 0, non_monotone = 0;
    double worst_T = 0, worst_T_eps = 0, worst_p = 0;
    for (int k = 0; k < 40000; ++k) {
      const Sample s = sample(e, rng, k);
      // Guess: none, near the true T, or anywhere; the hint independently so.
      auto pick = [&](int m) {
        if (m == 0) return 0.0;
        if (m == 1) return s.T_true * std::exp(0.3 * (u(rng) - 0.5));
        return b.T_min * std::pow(b.T_max / b.T_min, u(rng));
      };
      const double T_guess = pick(k % 3), T_hint = pick((k / 3) % 3);
      const Inversion plain = e.temperature(s.rho, s.eps, s.ye, T_guess, InversionMethod::exact);
      const double p_plain = e.press(s.rho, plain.T, s.ye);
      const TabulatedAtYe<Tabulated<>> slice(e, s.ye);
      const auto r = slice.invert(s.rho, s.eps, T_guess > 0 ? std::log(T_guess) : -INFINITY,
                                  T_hint > 0 ? std::log(T_hint) : -INFINITY);
      const double T = r.temperature();
      ASSERT_EQ(r.flags, plain.flags) << name << " rho " << s.rho << " eps " << s.eps << " ye " << s.ye;
      EXPECT_NEAR(r.eps, plain.eps, 1e-14 * (std::abs(plain.eps) + e.table().eps_shift));
      rule8 += (r.flags & kInvBelowEpsLow) != 0;
      rule9 += (r.flags & kInvAboveEpsHigh) != 0;
      if (r.flags & (kInvBelowEpsLow | kInvAboveEpsHigh)) {
        EXPECT_EQ(T, plain.T);  // T_min / T_max exactly
      } else {
        // Round-off in the node values (summed in another order) moves T by round-off / slope: T is
        // compared where the slope is not small, and through eps (d ln eps = slope d ln T) everywhere.
        const double sl = slope(e, s, plain.T), dlnT = std::abs(T - plain.T) / plain.T;
        if (sl > 1e-2) worst_T = std::max(worst_T, dlnT);
        worst_T_eps = std::max(worst_T_eps, sl * dlnT);
      }
      worst_p = std::max(worst_p, std::abs(r.press - p_plain) / std::abs(p_plain));
      EXPECT_NEAR(r.press, e.press(s.rho, T, s.ye), 1e-12 * std::abs(r.press));
      const std::size_t ir = std::size_t(std::clamp((std::log(s.rho) - e.table().lrho.x0) * e.table().lrho.inv_dx, 0.0,
                                                    double(e.table().lrho.n - 2)));
      const std::size_t iy = std::size_t(std::clamp((s.ye - e.table().ye.x0) * e.table().ye.inv_dx, 0.0,
                                                    double(e.table().ye.n - 2)));
      non_monotone += e.table().monotone_cell[iy * e.table().lrho.n + ir] == 0;
      ++tested;
    }
    std::printf("[ %s ] %d points (%d rule 8, %d rule 9, %d in non-monotone cells): worst rel. T %.2e "
                "(slope > 1e-2), slope x rel. T %.2e, p %.2e\n",
                name, tested, rule8, rule9, non_monotone, worst_T, worst_T_eps, worst_p);
    EXPECT_GT(rule8, 4000);
    EXPECT_GT(rule9, 4000);
    EXPECT_LT(worst_T, 1e-12);
    EXPECT_LT(worst_T_eps, 1e-14);
    EXPECT_LT(worst_p, 1e-11);
  }
}

TEST(EOSTabulatedAtYe, TheHintChangesOnlyTheCost) {
  const std::string path = eos_test::shared_eos(kTables[0]);
  REQUIRE_TABLE(path);
  const Tabulated<CountCalls> e(load_table(path));
  const Tabulated<> plain(e.table_ptr());
  const Bounds& b = e.bounds();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  const int last = e.table().lT.n - 1;
  std::uint64_t calls_no_hint = 0, calls_right_hint = 0;
  int n = 0;
  for (int k = 0; k < 4000; ++k) {
    const Sample s = sample(plain, rng, 8 * k);  // no rule 8/9 push
    const TabulatedAtYe<Tabulated<CountCalls>> slice(e, s.ye);
    const auto ref = slice.invert(s.rho, s.eps, -INFINITY, -INFINITY);
    auto c0 = e.counter().count();
    slice.invert(s.rho, s.eps, -INFINITY, -INFINITY);
    calls_no_hint += e.counter().count() - c0;
    c0 = e.counter().count();
    const auto hinted = slice.invert(s.rho, s.eps, -INFINITY, ref.lnT);
    calls_right_hint += e.counter().count() - c0;
    EXPECT_EQ(hinted.flags, ref.flags);
    EXPECT_NEAR(hinted.lnT, ref.lnT, 1e-13);
    for (int m = 0; m < 4; ++m) {
      const double lnT_hint = std::log(b.T_min) + (std::log(b.T_max) - std::log(b.T_min)) * u(rng);
      const auto r = slice.invert(s.rho, s.eps, -INFINITY, lnT_hint);
      EXPECT_EQ(r.flags, ref.flags);
      EXPECT_NEAR(r.lnT, ref.lnT, 1e-13);
      EXPECT_NEAR(r.press, ref.press, 1e-13 * std::abs(ref.press));
    }
    ++n;
  }
  // A hint in the right interval: one cell read (eps and p together). None: the two end nodes,
  // bisection over the nodes, and the cell for p.
  const double right = double(calls_right_hint) / n, none = double(calls_no_hint) / n;
  std::printf("table calls per inversion: %.2f with the right hint, %.2f without (%d T nodes)\n", right, none, last + 1);
  EXPECT_LE(right, 1.2);
  EXPECT_LE(none, 2 + std::ceil(std::log2(double(last))) + 1);
}

// Cells where eps does not rise with T (none in the shared tables): a synthetic table with a dip in
// eps(T) over half of its rho range. Several T give one eps there; the guess must select the same one
// as Tabulated::temperature, and the hint must not matter.
TEST(EOSTabulatedAtYe, NonMonotoneCellsPickTheSameTemperatureAsThePlainInversion) {
  const eos_test::Synthetic syn;
  RawTable raw = syn.raw();
  const int nr = syn.nr, nt = syn.nt;
  for (int iy = 0; iy < syn.ny; ++iy)
    for (int ir = 0; ir < nr / 2; ++ir) {
      const std::size_t i3 = (std::size_t(iy) * nt + 3) * nr + ir, i5 = (std::size_t(iy) * nt + 5) * nr + ir;
      raw.eps.v[(std::size_t(iy) * nt + 4) * nr + ir] = 0.5 * (raw.eps.v[i3] + raw.eps.v[i5]) - 0.6 * (raw.eps.v[i5] - raw.eps.v[i3]);
    }
  BuildOptions opts;
  opts.max_inconsistent_fraction = 1;
  const Tabulated<> e(build_table(raw, opts));
  const Bounds& b = e.bounds();
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  int non_monotone = 0, several = 0;
  for (int k = 0; k < 20000; ++k) {
    const double rho = std::exp(syn.lr(0) + (syn.lr(nr / 2 - 1) - syn.lr(0)) * u(rng));
    const double ye = b.ye_min + (b.ye_max - b.ye_min) * u(rng);
    const double T0 = std::exp(syn.lt(2) + (syn.lt(6) - syn.lt(2)) * u(rng));
    const double eps = e.eps(rho, T0, ye);
    const double T_guess = k % 4 == 0 ? 0.0 : b.T_min * std::pow(b.T_max / b.T_min, u(rng));
    const Inversion plain = e.temperature(rho, eps, ye, T_guess, InversionMethod::exact);
    const TabulatedAtYe<Tabulated<>> slice(e, ye);
    const double lnT_hint = std::log(b.T_min) + (std::log(b.T_max) - std::log(b.T_min)) * u(rng);
    const auto r = slice.invert(rho, eps, T_guess > 0 ? std::log(T_guess) : -INFINITY, lnT_hint);
    ASSERT_EQ(r.flags, plain.flags);
    EXPECT_NEAR(r.temperature(), plain.T, 1e-12 * plain.T) << "rho " << rho << " ye " << ye << " T0 " << T0;
    EXPECT_NEAR(r.press, e.press(rho, plain.T, ye), 1e-12 * e.press(rho, plain.T, ye));
    several += std::abs(plain.T - T0) > 1e-6 * T0;
    ++non_monotone;
  }
  std::printf("%d inversions in non-monotone cells, %d of them on another T than the sampled one\n", non_monotone,
              several);
  EXPECT_GT(several, 1000);  // the guess did select among several T
}
