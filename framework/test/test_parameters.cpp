#include <yaml-cpp/yaml.h>

#include "remnant/parameters.hpp"
#include "test_helpers.hpp"

using namespace remnant;
using remnant::test::expect_error;

namespace {
ParamSpec spec(ParamType t, const char* range = nullptr, bool array = false, int length = -1) {
  ParamSpec s;
  s.thorn = "T";
  s.name = "p";
  s.type = t;
  s.is_array = array;
  s.length = length;
  if (range) s.range = ParamRange::parse(range, {"x.yaml", 1, 1});
  return s;
}
ParamValue parse(const ParamSpec& s, const std::string& yaml) {
  return parse_param_value(s, YAML::Load(yaml), {"par.yaml", 3, 7});
}
}  // namespace

TEST(ParamRange, OpenClosedAndUnboundedEnds) {
  auto r = ParamRange::parse("(0:1]", {});
  EXPECT_FALSE(r.contains(0.0));
  EXPECT_TRUE(r.contains(1e-300));
  EXPECT_TRUE(r.contains(1.0));
  EXPECT_FALSE(r.contains(1.0000001));
  auto s = ParamRange::parse("[1:*)", {});
  EXPECT_TRUE(s.contains(1));
  EXPECT_TRUE(s.contains(1e300));
  EXPECT_FALSE(s.contains(0.999));
  auto t = ParamRange::parse("[0:)", {});
  EXPECT_TRUE(t.contains(0));
  EXPECT_FALSE(t.contains(-1e-300));
  EXPECT_FALSE(ParamRange::parse("[*:*]", {}).contains(std::nan("")));
}

TEST(ParamRange, BadSyntaxNamesLocation) {
  expect_error<InputError>([] { ParamRange::parse("0:1", {"t.yaml", 4, 12}); }, {"t.yaml:4:12", "bad range"});
  expect_error<InputError>([] { ParamRange::parse("[2:1]", {"t.yaml", 4, 12}); }, {"bad range"});
  expect_error<InputError>([] { ParamRange::parse("[a:1]", {"t.yaml", 4, 12}); }, {"bad range"});
}

TEST(ParamValue, TypesAreChecked) {
  EXPECT_EQ(std::get<std::int64_t>(parse(spec(ParamType::integer), "42")), 42);
  EXPECT_DOUBLE_EQ(std::get<double>(parse(spec(ParamType::real), "2.5e-3")), 2.5e-3);
  EXPECT_DOUBLE_EQ(std::get<double>(parse(spec(ParamType::real), "3")), 3.0);
  EXPECT_EQ(std::get<bool>(parse(spec(ParamType::boolean), "true")), true);
  expect_error<InputError>([] { parse(spec(ParamType::integer), "4.5"); }, {"par.yaml:3:7", "T::p expects an integer", "'4.5'"});
  expect_error<InputError>([] { parse(spec(ParamType::real), "fast"); }, {"expects a real number", "'fast'"});
  expect_error<InputError>([] { parse(spec(ParamType::boolean), "maybe"); }, {"expects true or false"});
  expect_error<InputError>([] { parse(spec(ParamType::real), "[1, 2]"); }, {"got a list"});
  expect_error<InputError>([] { parse(spec(ParamType::real), ".nan"); }, {"must be finite"});
}

TEST(ParamValue, RangesShowAllowedValues) {
  auto s = spec(ParamType::real, "(0:1]");
  EXPECT_NO_THROW(parse(s, "0.5"));
  expect_error<InputError>([&] { parse(s, "1.5"); }, {"out of range", "(0:1]", "par.yaml:3:7"});
  expect_error<InputError>([&] { parse(s, "0"); }, {"out of range", "(0:1]"});
  auto i = spec(ParamType::integer, "[1:*)");
  expect_error<InputError>([&] { parse(i, "0"); }, {"out of range", "[1:*)"});
}

TEST(ParamValue, KeywordsSuggestNearest) {
  auto s = spec(ParamType::keyword);
  s.keywords = {"hll", "hllc", "llf"};
  EXPECT_EQ(std::get<std::string>(parse(s, "hllc")), "hllc");
  expect_error<InputError>([&] { parse(s, "hlc"); }, {"one of: hll, hllc, llf", "did you mean"});
}

TEST(ParamValue, ArraysCheckLengthAndElements) {
  auto s = spec(ParamType::integer, "[1:*)", true, 3);
  EXPECT_EQ(std::get<std::vector<std::int64_t>>(parse(s, "[4, 5, 6]")), (std::vector<std::int64_t>{4, 5, 6}));
  expect_error<InputError>([&] { parse(s, "[4, 5]"); }, {"exactly 3 values"});
  expect_error<InputError>([&] { parse(s, "[4, 0, 1]"); }, {"out of range"});
  expect_error<InputError>([&] { parse(s, "4"); }, {"expects a list"});
  auto k = spec(ParamType::keyword, nullptr, true);
  k.keywords = {"outflow", "periodic"};
  EXPECT_EQ(std::get<std::vector<std::string>>(parse(k, "[outflow, periodic]")).size(), 2u);
  expect_error<InputError>([&] { parse(k, "[outflow, perodic]"); }, {"did you mean 'periodic'"});
}

TEST(Parameters, TypedReferencesStayValid) {
  Parameters p;
  auto s = spec(ParamType::real, "(0:1]");
  s.default_value = 0.3;
  p.declare(s);
  const double& cfl = p.get<double>("T", "p");
  EXPECT_DOUBLE_EQ(cfl, 0.3);
  p.set("T", "p", 0.25, {});
  EXPECT_DOUBLE_EQ(cfl, 0.25);  // the same reference sees the new value
  EXPECT_THROW(p.get<std::int64_t>("T", "p"), RunError);
  EXPECT_THROW(p.declare(s), InputError);
  EXPECT_EQ(p.to_yaml({"T"}), "T:\n  p: 0.25\n");
}

// The start-up checks of HeadOn and RotatingStar print numbers through this one formatter.
TEST(Parameters, FormatNumberForMessages) {
  EXPECT_EQ(format_number(0.1 + 0.2), "0.3");
  EXPECT_EQ(format_number(1.28e-3), "0.00128");
  EXPECT_EQ(format_number(123456789.0), "1.23457e+08");
  EXPECT_EQ(format_number(0.1 + 0.2, 17), "0.30000000000000004");
  EXPECT_EQ(format_number(3.0, 17), "3");
}
