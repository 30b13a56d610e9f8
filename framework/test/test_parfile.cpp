#include "remnant/parfile.hpp"
#include "remnant/thorn_spec.hpp"
#include "test_helpers.hpp"

using namespace remnant;
using remnant::test::expect_error;
using remnant::test::temp_dir;
using remnant::test::write_file;

namespace {

const char* kWaveYaml = R"Y(thorn: Wave
parameters:
  - {name: amplitude, type: real, range: "(0:*)", default: 1.0, description: Amplitude}
  - {name: wavelength, type: real, range: "(0:*)", default: 1.0, description: Wave length}
  - {name: ncells, type: "int[]", length: 3, range: "[1:*)", default: [8, 8, 8], description: Cells}
  - {name: method, type: keyword, values: [rk2, rk3], default: rk3, description: Method}
)Y";

Parameters declared(const std::vector<std::string>& thorns) {
  Parameters p;
  auto spec = parse_thorn_spec(kWaveYaml, "thorns/Wave/thorn.yaml");
  for (const auto& t : thorns)
    if (t == "Wave")
      for (const auto& s : spec.parameters) p.declare(s);
  return p;
}

}  // namespace

TEST(Parfile, IncludesLayerAndOverridesWin) {
  auto d = temp_dir("parfile_include");
  write_file(d / "base.yaml", "active_thorns: [Wave]\nWave:\n  amplitude: 2.0\n  wavelength: 3.0\n");
  auto top = write_file(d / "top.yaml", "include: base.yaml\nWave:\n  amplitude: 5.0\n");
  Parfile pf = Parfile::load(top);
  pf.apply_override("Wave::wavelength=7", 1);
  Parameters p = declared({"Wave"});
  apply_parfile(pf, {"Wave", "Other"}, {"Wave"}, p);
  EXPECT_DOUBLE_EQ(p.get<double>("Wave", "amplitude"), 5.0);
  EXPECT_DOUBLE_EQ(p.get<double>("Wave", "wavelength"), 7.0);
  EXPECT_EQ(pf.active_thorns, std::vector<std::string>{"Wave"});
  EXPECT_EQ(pf.files.size(), 2u);
}

TEST(Parfile, ArrayOverrideFromCommandLine) {
  auto d = temp_dir("parfile_array");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\n");
  Parfile pf = Parfile::load(f);
  pf.apply_override("Wave::ncells=[16,1,1]", 1);
  Parameters p = declared({"Wave"});
  apply_parfile(pf, {"Wave"}, {"Wave"}, p);
  EXPECT_EQ(p.get<std::vector<std::int64_t>>("Wave", "ncells"), (std::vector<std::int64_t>{16, 1, 1}));
}

TEST(Parfile, UnknownParameterNamesNearestValidNames) {
  auto d = temp_dir("parfile_unknown");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\nWave:\n  amplitud: 2.0\n");
  Parfile pf = Parfile::load(f);
  Parameters p = declared({"Wave"});
  expect_error<InputError>([&] { apply_parfile(pf, {"Wave"}, {"Wave"}, p); },
                           {f + ":3:3", "unknown parameter Wave::amplitud", "Wave::amplitude"});
}

TEST(Parfile, BogusOverrideStillSuggestsNames) {
  auto d = temp_dir("parfile_bogus");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\n");
  Parfile pf = Parfile::load(f);
  pf.apply_override("Wave::bogus=1", 2);
  Parameters p = declared({"Wave"});
  expect_error<InputError>([&] { apply_parfile(pf, {"Wave"}, {"Wave"}, p); },
                           {"command line argument 2", "Wave::bogus", "nearest valid names: Wave::"});
}

TEST(Parfile, OutOfRangeShowsRangeAndLocation) {
  auto d = temp_dir("parfile_range");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\nWave:\n  amplitude: -1\n");
  Parfile pf = Parfile::load(f);
  Parameters p = declared({"Wave"});
  expect_error<InputError>([&] { apply_parfile(pf, {"Wave"}, {"Wave"}, p); }, {f + ":3:14", "(0:*)", "out of range"});
}

TEST(Parfile, WrongTypeIsAnError) {
  auto d = temp_dir("parfile_type");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\nWave:\n  method: rk4\n");
  Parfile pf = Parfile::load(f);
  Parameters p = declared({"Wave"});
  expect_error<InputError>([&] { apply_parfile(pf, {"Wave"}, {"Wave"}, p); }, {f + ":3:11", "one of: rk2, rk3"});
}

TEST(Parfile, InactiveAndUnknownThorns) {
  auto d = temp_dir("parfile_thorns");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\nOther:\n  x: 1\n");
  Parameters p = declared({"Wave"});
  expect_error<InputError>([&] { apply_parfile(Parfile::load(f), {"Wave", "Other"}, {"Wave"}, p); },
                           {f + ":2:1", "Other is not in active_thorns"});
  auto g = write_file(d / "b.yaml", "active_thorns: [Wave]\nWav:\n  amplitude: 1\n");
  expect_error<InputError>([&] { apply_parfile(Parfile::load(g), {"Wave", "Other"}, {"Wave"}, p); },
                           {g + ":2:1", "unknown thorn 'Wav'", "did you mean Wave"});
}

TEST(Parfile, YamlSyntaxErrorShowsLineAndColumn) {
  auto d = temp_dir("parfile_syntax");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\nWave:\n  amplitude: [1, 2\n  wavelength: 3\n");
  expect_error<InputError>([&] { Parfile::load(f); }, {f + ":", "YAML syntax error"});
  try {
    Parfile::load(f);
  } catch (const InputError& e) {
    EXPECT_GT(e.where().line, 1);
    EXPECT_GT(e.where().column, 0);
  }
}

TEST(Parfile, IncludeCycleAndMissingInclude) {
  auto d = temp_dir("parfile_cycle");
  write_file(d / "a.yaml", "include: b.yaml\n");
  auto b = write_file(d / "b.yaml", "include: a.yaml\n");
  expect_error<InputError>([&] { Parfile::load(b); }, {"include cycle"});
  auto c = write_file(d / "c.yaml", "include: missing.yaml\n");
  expect_error<InputError>([&] { Parfile::load(c); }, {c + ":1:10", "does not exist"});
}

TEST(Parfile, MalformedOverride) {
  Parfile pf;
  expect_error<InputError>([&] { pf.apply_override("Wave:amplitude=1", 3); }, {"command line argument 3", "Thorn::parameter=value"});
}

// yaml-cpp keeps the last of two equal keys silently; the parfile reader refuses them.
TEST(Parfile, DuplicateKeysAreErrors) {
  auto d = temp_dir("parfile_dupkey");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\nWave:\n  amplitude: 1\n  amplitude: 2\n");
  expect_error<InputError>([&] { Parfile::load(f); }, {f + ":4:3", "duplicate key 'amplitude'", "first at line 3:3"});
  auto g = write_file(d / "b.yaml", "active_thorns: [Wave]\nWave:\n  amplitude: 1\nWave:\n  wavelength: 2\n");
  expect_error<InputError>([&] { Parfile::load(g); }, {g + ":4:1", "duplicate key 'Wave'"});
}

TEST(Parfile, SecondYamlDocumentIsAnError) {
  auto d = temp_dir("parfile_docs");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave]\n---\nWave:\n  amplitude: 2\n");
  expect_error<InputError>([&] { Parfile::load(f); }, {f + ":3:1", "second YAML document"});
  // A leading '---' and an empty trailing document are one document.
  auto g = write_file(d / "b.yaml", "---\nactive_thorns: [Wave]\n---\n");
  EXPECT_EQ(Parfile::load(g).active_thorns, std::vector<std::string>{"Wave"});
}

TEST(Parfile, IncludeOfADirectoryIsAnError) {
  auto d = temp_dir("parfile_incdir");
  std::filesystem::create_directories(d / "sub");
  auto f = write_file(d / "a.yaml", "include: sub\nactive_thorns: [Wave]\n");
  expect_error<InputError>([&] { Parfile::load(f); }, {f + ":1:10", "is a directory"});
}

TEST(Parfile, ThornListedTwiceIsAnError) {
  auto d = temp_dir("parfile_twice");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave, Other, Wave]\n");
  expect_error<InputError>([&] { Parfile::load(f); }, {f + ":1:30", "thorn 'Wave' is listed twice", "first at " + f + ":1:17"});
  // Repeating a thorn of an included file is layering, not a slip.
  write_file(d / "base.yaml", "active_thorns: [Wave]\n");
  auto g = write_file(d / "b.yaml", "include: base.yaml\nactive_thorns: [Wave, Other]\n");
  EXPECT_EQ(Parfile::load(g).active_thorns, (std::vector<std::string>{"Wave", "Other"}));
}

// The thorn list can be changed from the command line like any parameter (it used to be taken for a
// second parfile): "=" replaces the list, "+=" adds to it.
TEST(Parfile, ActiveThornsOverrideReplacesOrAdds) {
  auto d = temp_dir("parfile_active_override");
  auto f = write_file(d / "a.yaml", "active_thorns: [Wave, Other]\n");
  Parfile replaced = Parfile::load(f);
  replaced.apply_override("active_thorns=[Wave]", 1);
  EXPECT_EQ(replaced.active_thorns, std::vector<std::string>{"Wave"});
  EXPECT_NE(replaced.active_thorns_where.str().find("command line argument 1"), std::string::npos);

  Parfile added = Parfile::load(f);
  added.apply_override("active_thorns+=[Third, Wave]", 2);
  added.apply_override("active_thorns+=Fourth", 3);
  EXPECT_EQ(added.active_thorns, (std::vector<std::string>{"Wave", "Other", "Third", "Fourth"}));
  EXPECT_TRUE(is_active_thorns_override("active_thorns+=[X]"));
  EXPECT_FALSE(is_active_thorns_override("active_thornsX=[X]"));
}

TEST(Parfile, MalformedActiveThornsOverride) {
  Parfile pf;
  expect_error<InputError>([&] { pf.apply_override("active_thorns=Wave", 4); },
                           {"command line argument 4", "active_thorns=[Thorn, ...]"});
  expect_error<InputError>([&] { pf.apply_override("active_thorns=[Wave, Wave]", 5); }, {"listed twice"});
  expect_error<InputError>([&] { pf.apply_override("active_thorns=[]", 6); }, {"non-empty list"});
  expect_error<InputError>([&] { pf.apply_override("active_thorns=[a, [b]]", 7); }, {"thorn names"});
}
