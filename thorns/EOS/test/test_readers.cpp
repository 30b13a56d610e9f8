// The same SFHo data in StellarCollapse HDF5, CompOSE ASCII and CompOSE HDF5: the readers agree.
#include <random>

#include "EOS/errors.hpp"
#include "EOS/readers.hpp"
#include "EOS/tabulated.hpp"
#include "eos_test_util.hpp"

using namespace remnant::eos;

namespace {

const std::string kSC = eos_test::shared_eos("SFHo_reduced_39r_39t_20y.h5");
const std::string kCompose = eos_test::shared_eos("SFHo_reduced_compose");
const std::string kComposeH5 = eos_test::shared_eos("SFHo_reduced_39r_39t_20y_compose.h5");

// The StellarCollapse file was converted from CompOSE with relativistic cs2 (without the
// have_rel_cs2 flag) and with mu_e = mu_l; these options read all three files alike.
ReadOptions sc_options() {
  ReadOptions o;
  o.sc_cs2 = Cs2Convention::relativistic;
  return o;
}
ReadOptions compose_options(double eps_shift) {
  ReadOptions o;
  o.compose_mu_e = ComposeElectronMu::mu_l;
  o.eps_shift = eps_shift;
  return o;
}

double rel(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300}); }

// Every stored quantity at every grid point, relative difference (eps relative to eps + shift).
void compare_grids(const TableData& a, const TableData& b, bool with_cs2, double tol) {
  ASSERT_EQ(a.points(), b.points());
  EXPECT_NEAR(a.lrho.x0, b.lrho.x0, 1e-13);
  EXPECT_NEAR(a.lrho.dx, b.lrho.dx, 1e-13);
  EXPECT_NEAR(a.lT.x0, b.lT.x0, 1e-13);
  EXPECT_NEAR(a.ye.x0, b.ye.x0, 1e-15);
  double worst[kThermoFields] = {};
  for (std::size_t i = 0; i < a.points(); ++i) {
    const double* p = &a.thermo[i * kThermoStride];
    const double* q = &b.thermo[i * kThermoStride];
    worst[kLogP] = std::max(worst[kLogP], rel(std::exp(p[kLogP]), std::exp(q[kLogP])));
    worst[kLogEps] = std::max(worst[kLogEps], rel(std::exp(p[kLogEps]), std::exp(q[kLogEps])));
    for (int k : {kCs2, kEntropy, kMuE, kMuP, kMuN}) worst[k] = std::max(worst[k], rel(p[k], q[k]));
  }
  const char* names[] = {"p", "eps+shift", "cs2", "s", "mu_e", "mu_p", "mu_n"};
  for (int k = 0; k < kThermoFields; ++k) {
    if (k == kCs2 && !with_cs2) continue;
    EXPECT_LT(worst[k], tol) << names[k] << " between " << a.file << " and " << b.file;
  }
}

// Interpolated values at random points between the nodes.
void compare_between(const Tabulated<>& a, const Tabulated<>& b, bool with_cs2, double tol) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const Bounds& bd = a.bounds();
  for (int k = 0; k < 5000; ++k) {
    const double rho = bd.rho_min * std::pow(bd.rho_max / bd.rho_min, u(rng));
    const double T = bd.T_min * std::pow(bd.T_max / bd.T_min, u(rng));
    const double ye = bd.ye_min + (bd.ye_max - bd.ye_min) * u(rng);
    const Thermo x = a.thermo(rho, T, ye), y = b.thermo(rho, T, ye);
    EXPECT_LT(rel(x.press, y.press), tol);
    EXPECT_LT(rel(x.eps + a.table().eps_shift, y.eps + b.table().eps_shift), tol);
    if (with_cs2) {
      EXPECT_LT(rel(x.cs2, y.cs2), tol);
    }
    EXPECT_LT(rel(x.entropy, y.entropy), tol);
    const ChemPot m = a.chem(rho, T, ye), n = b.chem(rho, T, ye);
    EXPECT_LT(rel(m.mu_e, n.mu_e), tol);
    EXPECT_LT(rel(m.mu_p, n.mu_p), tol);
    EXPECT_LT(rel(m.mu_n, n.mu_n), tol);
  }
}

}  // namespace

TEST(EOSReaders, StellarCollapseAndCompOSEHdf5Agree) {
  REQUIRE_TABLE(kSC);
  REQUIRE_TABLE(kComposeH5);
  auto sc = load_table(kSC, sc_options());
  auto ch = load_table(kComposeH5, compose_options(sc->eps_shift));
  EXPECT_EQ(sc->lrho.n, 39);
  EXPECT_EQ(sc->lT.n, 39);
  EXPECT_EQ(sc->ye.n, 20);
  EXPECT_EQ(ch->format, "CompOSE HDF5");
  compare_grids(*sc, *ch, true, 1e-12);
  compare_between(Tabulated<>(sc), Tabulated<>(ch), true, 1e-12);
}

TEST(EOSReaders, StellarCollapseAndCompOSEAsciiAgree) {
  REQUIRE_TABLE(kSC);
  REQUIRE_TABLE(kCompose);
  auto sc = load_table(kSC, sc_options());
  auto ca = load_table(kCompose, compose_options(sc->eps_shift));
  EXPECT_EQ(ca->format, "CompOSE ASCII");
  // eos.thermo has no cs2: the ASCII reader derives it from differences (compared below).
  compare_grids(*sc, *ca, false, 1e-12);
  compare_between(Tabulated<>(sc), Tabulated<>(ca), false, 1e-12);
}

TEST(EOSReaders, CompOSEAsciiAndHdf5AgreeBitForBitOnQ) {
  REQUIRE_TABLE(kCompose);
  REQUIRE_TABLE(kComposeH5);
  auto ca = load_table(kCompose), ch = load_table(kComposeH5);
  EXPECT_EQ(ca->eps_shift, ch->eps_shift);  // automatic shift from the same data
  compare_grids(*ca, *ch, false, 1e-15);
}

TEST(EOSReaders, FiniteDifferenceCs2IsCloseToTheTabulatedOne) {
  REQUIRE_TABLE(kCompose);
  REQUIRE_TABLE(kComposeH5);
  auto ca = load_table(kCompose), ch = load_table(kComposeH5);
  std::vector<double> d;
  for (std::size_t i = 0; i < ca->points(); ++i) {
    const double a = ca->thermo[i * kThermoStride + kCs2], b = ch->thermo[i * kThermoStride + kCs2];
    d.push_back(std::abs(a - b) / b);
  }
  std::sort(d.begin(), d.end());
  const double median = d[d.size() / 2];
  std::printf("[ CompOSE ] cs2 by differences vs PyCompOSE cs2: median rel. diff %.3g, 90%% %.3g\n", median,
              d[d.size() * 9 / 10]);
  EXPECT_LT(median, 0.05);
}

TEST(EOSReaders, ElectronChemicalPotentialConvention) {
  REQUIRE_TABLE(kComposeH5);
  // CompOSE: mu_e = mu_l - mu_q. In dilute hot matter electrons are non-degenerate: mu_e ~ 0.
  Tabulated<> phys(load_table(kComposeH5));
  Tabulated<> as_mul(load_table(kComposeH5, compose_options(-1)));
  const double rho = phys.bounds().rho_min, T = 0.1, ye = 0.01;
  EXPECT_LT(std::abs(phys.chem(rho, T, ye).mu_e), 0.01);
  EXPECT_GT(std::abs(as_mul.chem(rho, T, ye).mu_e), 1.0);
}

TEST(EOSReaders, SfhoPressureSanityPoint) {
  REQUIRE_TABLE(kComposeH5);
  // SOURCES.md: nb = 0.1048 fm^-3, yq = 0.1032, T = 0.1 MeV gives P = 0.813 MeV/fm^3.
  Tabulated<> eos(load_table(kComposeH5));
  const double rho = 0.1048 * 939.56535 * remnant::units::MeV_fm3_mass_to_code_rho;
  const double p = eos.press(rho, 0.1, 0.1032) / remnant::units::MeV_fm3_to_code_press;
  EXPECT_NEAR(p, 0.813, 0.01);
}

TEST(EOSReaders, CompOSEHdf5WithComposition) {
  const std::string path = eos_test::shared_eos("SFHo_psolver_compose.h5");
  REQUIRE_TABLE(path);
  auto t = load_table(path);
  EXPECT_TRUE(t->has_compo);
  Tabulated<> eos(t);
  const Composition c = eos.composition(eos.bounds().rho_max * 0.5, 10.0, 0.3);
  EXPECT_GE(c.Xn, 0.0);
  EXPECT_GE(c.Xp, 0.0);
  EXPECT_NEAR(c.Xa + c.Xh + c.Xn + c.Xp, 1.0, 0.05);
}

TEST(EOSReaders, SmallHempelStellarCollapseTable) {
  const std::string path = eos_test::shared_eos("Hempel_SFHoEOS_rho222_temp180_ye60_version_1.1_20120817_simple.h5");
  REQUIRE_TABLE(path);
  auto t = load_table(path);
  EXPECT_EQ(t->lrho.n, 13);
  EXPECT_TRUE(t->has_chem);
  EXPECT_TRUE(t->has_compo);
  std::printf("[ Hempel ] checks:\n%s", t->report.str().c_str());
}

TEST(EOSReaders, CompOSEAsciiParserOnRgNjl) {
  // A real 1-D cold CompOSE set: parsed, then rejected with a message naming the axis file.
  const std::string dir = eos_test::shared_eos("RG-NJL1");
  REQUIRE_TABLE(dir);
  RawTable raw = read_compose_ascii(dir);
  EXPECT_EQ(raw.rho.size(), 146u);
  EXPECT_EQ(raw.T.size(), 1u);
  try {
    build_table(raw);
    ADD_FAILURE() << "RG-NJL1 has T = 0 and a non-uniform nb axis";
  } catch (const TableError& e) {
    EXPECT_NE(std::string(e.what()).find("eos."), std::string::npos) << e.what();
  }
}
