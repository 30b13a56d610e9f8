#include "remnant/scheduler.hpp"

#include "remnant/group_view.hpp"

#include <limits>

#include <yaml-cpp/yaml.h>

#include "remnant/thorn_spec.hpp"

#include "test_helpers.hpp"

using namespace remnant;
using remnant::test::expect_error;

namespace {

// A grid with one small block that records which groups it was asked to synchronise.
class RecordingGrid final : public GridDriver {
 public:
  explicit RecordingGrid(const VariableRegistry& vars)
      : block_(0, 0, {0, 0, 0}, {4, 1, 1}, {1, 0, 0}, {0, 0, 0}, {0.25, 1, 1}, vars) {
    blocks_.push_back(&block_);
  }
  int dimension() const override { return 1; }
  std::span<Block* const> local_blocks() override { return blocks_; }
  void synchronize(std::span<const int> groups) override { synced.insert(synced.end(), groups.begin(), groups.end()); }
  double reduce(int, int, ReductionKind) override { return 0; }
  std::int64_t global_cells() const override { return 4; }
  double min_spacing() const override { return 0.25; }
  std::string describe() const override { return "recording grid"; }
  MPI_Comm comm() const override { return MPI_COMM_WORLD; }
  CoordinateSystem coordinates() const override { return CoordinateSystem::cartesian; }
  std::vector<BlockKey> all_blocks() const override { return {BlockKey{}}; }
  void restore_blocks(std::span<const BlockKey>) override {}
  std::vector<int> synced;
  Block block_;
  std::vector<Block*> blocks_;
};

struct Harness {
  std::vector<ThornSpec> specs;
  VariableRegistry vars;
  Parameters params;
  ImplementationTable impl;
  std::vector<std::string> calls;

  // `settings`: parameter values applied before the groups get storage, as a parfile would.
  explicit Harness(std::initializer_list<const char*> yamls,
                   std::initializer_list<std::pair<const char*, const char*>> settings = {}) {
    int i = 0;
    for (const char* y : yamls) specs.push_back(parse_thorn_spec(y, "thorn" + std::to_string(i++) + ".yaml"));
    for (const auto& s : specs)
      for (const auto& p : s.parameters) params.declare(p);
    for (const auto& [name, value] : settings) {
      const std::string full = name;
      const auto sep = full.find("::");
      const std::string thorn = full.substr(0, sep), param = full.substr(sep + 2);
      params.set(thorn, param, parse_param_value(*params.find(thorn, param), YAML::Node(std::string(value)), {}), {});
    }
    for (const auto& s : specs) {
      register_variable_groups(s, params, vars);
      for (const auto& it : s.schedule)
        if (!it.is_group) {
          const std::string name = it.thorn + "::" + it.name;
          impl.functions[name] = [this, name](Context&) { calls.push_back(name); };
        }
    }
    vars.resolve_rhs();
  }
  std::vector<const ThornSpec*> ptrs() const {
    std::vector<const ThornSpec*> out;
    for (const auto& s : specs) out.push_back(&s);
    return out;
  }
  Scheduler make() { return Scheduler(ptrs(), vars, params, impl); }
};

const char* kProducerConsumer = R"(thorn: A
variables:
  - {group: u, tensor: [scalar u], role: evolved, rhs: u_rhs}
  - {group: u_rhs, tensor: [scalar u]}
  - {group: diag, tensor: [scalar d]}
schedule:
  - function: Analyse
    in: analysis
    reads: [u_rhs]
    writes: [diag]
    description: reads u_rhs, so runs after its writer
  - function: Rhs
    in: analysis
    reads: [u(everywhere)]
    writes: [u_rhs]
    description: writes u_rhs
  - function: Late
    in: analysis
    description: explicitly last
    after: [Analyse]
  - function: First
    in: analysis
    before: [Rhs]
    description: explicitly first
)";

}  // namespace

TEST(Scheduler, WriterBeforeReaderAndExplicitOrdering) {
  Harness h{kProducerConsumer};
  Scheduler s = h.make();
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  RecordingGrid grid(h.vars);
  ctx.set_grid(&grid);
  s.run_bin("analysis", ctx);
  EXPECT_EQ(h.calls, (std::vector<std::string>{"A::First", "A::Rhs", "A::Analyse", "A::Late"}));
  const std::string printed = s.print();
  EXPECT_LT(printed.find("startup:"), printed.find("evol:"));
  EXPECT_LT(printed.find("evol:"), printed.find("analysis:"));
  EXPECT_NE(printed.find("A::Rhs"), std::string::npos);
}

TEST(Scheduler, SynchronisesStaleGhostsOnlyWhenNeeded) {
  Harness h{R"(thorn: A
variables:
  - {group: u, tensor: [scalar u]}
schedule:
  - function: Write
    in: evol
    writes: [u(interior)]
    description: leaves ghosts stale
  - function: Read
    in: evol
    reads: [u(everywhere)]
    description: needs ghosts
  - function: ReadAgain
    in: evol
    reads: [u(everywhere)]
    after: [Read]
    description: ghosts still valid
)"};
  Scheduler s = h.make();
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  RecordingGrid grid(h.vars);
  ctx.set_grid(&grid);
  s.run_bin("evol", ctx);
  EXPECT_EQ(grid.synced, (std::vector<int>{0}));  // once, before Read; not again before ReadAgain
  s.run_bin("evol", ctx);                          // Write stales them again
  EXPECT_EQ(grid.synced, (std::vector<int>{0, 0}));
}

TEST(Scheduler, CycleIsReportedWithItsPath) {
  Harness h{R"(thorn: Cyc
variables:
  - {group: a, tensor: [scalar a]}
  - {group: b, tensor: [scalar b]}
schedule:
  - function: MakeA
    in: evol
    reads: [b]
    writes: [a]
    description: needs b
  - function: MakeB
    in: evol
    reads: [a]
    writes: [b]
    description: needs a
)"};
  expect_error<InputError>([&] { h.make(); }, {"schedule cycle in 'evol'", "Cyc::MakeA -> Cyc::MakeB -> Cyc::MakeA",
                                               "writes Cyc::a, which 'MakeB' reads"});
}

TEST(Scheduler, ExplicitCycleAcrossThorns) {
  Harness h{R"(thorn: X
schedule:
  - {function: F, in: initial, before: [G], description: f}
)",
            R"(thorn: Y
schedule:
  - {function: G, in: initial, before: [F], description: g}
)"};
  expect_error<InputError>([&] { h.make(); }, {"schedule cycle in 'initial'", "X::F -> Y::G -> X::F", "declares before: G"});
}

TEST(Scheduler, UnknownTargetsAndContainers) {
  Harness bad_target{R"(thorn: X
schedule:
  - {function: F, in: initial, after: [Missing], description: f}
)"};
  expect_error<InputError>([&] { bad_target.make(); }, {"thorn0.yaml:3:40", "'Missing'", "not scheduled"});
  Harness optional_target{R"(thorn: X
schedule:
  - {function: F, in: initial, after: [{name: Missing, optional: true}], description: f}
)"};
  EXPECT_NO_THROW(optional_target.make());
  Harness bad_bin{R"(thorn: X
schedule:
  - {function: F, in: evolve, description: f}
)"};
  expect_error<InputError>([&] { bad_bin.make(); }, {"neither a bin nor a group", "did you mean evol"});
}

// A hook into another thorn's group (`in: {name: G, optional: true}`) runs inside G when that thorn
// is active and is dropped when it is not; without `optional` a missing group stays an error.
TEST(Scheduler, OptionalContainerIsAHookIntoAnotherThornsGroup) {
  const char* matter = R"(thorn: Matter
schedule:
  - {function: Recover, in: {name: Recovery, optional: true}, description: hook}
  - {function: Step, in: evol, description: always}
)";
  const char* solver = R"(thorn: Solver
schedule:
  - {group: Recovery, in: evol, after: [Step], description: the hook's group}
)";
  Harness alone{matter};
  Scheduler s1 = alone.make();
  Context c1(alone.params, alone.vars, MPI_COMM_WORLD);
  s1.run_bin("evol", c1);
  EXPECT_EQ(alone.calls, (std::vector<std::string>{"Matter::Step"}));
  Harness both{matter, solver};
  Scheduler s2 = both.make();
  Context c2(both.params, both.vars, MPI_COMM_WORLD);
  s2.run_bin("evol", c2);
  EXPECT_EQ(both.calls, (std::vector<std::string>{"Matter::Step", "Matter::Recover"}));
  Harness required{R"(thorn: Matter
schedule:
  - {function: Recover, in: {name: Recovery}, description: hook}
)"};
  expect_error<InputError>([&] { required.make(); }, {"neither a bin nor a group"});
}

TEST(Scheduler, EveryConditionAndRepeatedGroup) {
  Harness h{R"(thorn: M
parameters:
  - {name: enabled, type: bool, default: false, description: switch}
  - {name: method, type: keyword, values: [a, b], default: b, description: choice}
schedule:
  - {group: Loop, in: evol, repeat_while: MoreSubsteps, description: substeps}
  - {function: Substep, in: Loop, description: one substep}
  - {function: Sometimes, in: evol, after: [Loop], every: 2, description: every second iteration}
  - {function: Never, in: evol, if: "M::enabled", description: disabled}
  - {function: WhenB, in: evol, if: "M::method == b", description: enabled by keyword}
)"};
  int remaining = 0;
  h.impl.predicates["M::MoreSubsteps"] = [&](Context&) { return remaining-- > 0; };
  Scheduler s = h.make();
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  for (int it = 0; it < 2; ++it) {
    ctx.clock().iteration = it;
    remaining = 3;
    s.run_bin("evol", ctx);
  }
  EXPECT_EQ(h.calls, (std::vector<std::string>{"M::Substep", "M::Substep", "M::Substep", "M::Sometimes", "M::WhenB",
                                               "M::Substep", "M::Substep", "M::Substep", "M::WhenB"}));
  EXPECT_NE(s.timer_table().find("M::Substep"), std::string::npos);
}

TEST(Scheduler, DebugModeCatchesUndeclaredWritesAndUnwrittenOutputs) {
  Harness h{R"(thorn: D
variables:
  - {group: u, tensor: [scalar u]}
  - {group: v, tensor: [scalar v]}
schedule:
  - {function: Sneaky, in: evol, writes: [u], description: also writes v}
  - {function: Lazy, in: analysis, writes: [v], description: writes nothing}
  - {function: Honest, in: initial, writes: [u, v], description: writes both}
)"};
  h.impl.functions["D::Sneaky"] = [](Context& c) {
    for (Block* b : c.grid().local_blocks()) {
      for_interior(*b, [&](int i, int j, int k) { b->field(0, 0)(i, j, k) = 1; });
      b->field(1, 0)(0, 0, 0) = 42;  // not declared
    }
  };
  h.impl.functions["D::Lazy"] = [](Context&) {};
  h.impl.functions["D::Honest"] = [](Context& c) {
    for (Block* b : c.grid().local_blocks())
      for_interior(*b, [&](int i, int j, int k) { b->field(0, 0)(i, j, k) = b->field(1, 0)(i, j, k) = 2; });
  };
  Scheduler s = h.make();
  s.set_debug(true);
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  RecordingGrid grid(h.vars);
  ctx.set_grid(&grid);
  EXPECT_NO_THROW(s.run_bin("initial", ctx));
  expect_error<RunError>([&] { s.run_bin("evol", ctx); }, {"D::Sneaky changed D::v without declaring it"});
  expect_error<RunError>([&] { s.run_bin("analysis", ctx); }, {"after D::Lazy", "D::v", "are NaN"});
}

TEST(Scheduler, EveryFromParameterAndAllPseudoGroup) {
  Harness h{R"Y(thorn: P
parameters:
  - {name: out_every, type: int, range: "[0:*)", default: 3, description: cadence}
variables:
  - {group: u, tensor: [scalar u]}
schedule:
  - {function: Output, in: analysis, reads: ["@all"], every: P::out_every, description: reads everything}
  - {function: Produce, in: analysis, writes: [u], description: must run before Output}
)Y"};
  Scheduler s = h.make();
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  for (int it = 0; it < 7; ++it) {
    ctx.clock().iteration = it;
    s.run_bin("analysis", ctx);
  }
  // Produce runs every iteration, Output only at 0, 3, 6 and always after Produce.
  std::vector<std::string> expected;
  for (int it = 0; it < 7; ++it) {
    expected.push_back("P::Produce");
    if (it % 3 == 0) expected.push_back("P::Output");
  }
  EXPECT_EQ(h.calls, expected);
  h.params.set("P", "out_every", std::int64_t{0}, {});
  h.calls.clear();
  s.run_bin("analysis", ctx);
  EXPECT_EQ(h.calls, std::vector<std::string>{"P::Produce"});  // 0 turns it off
}

TEST(Scheduler, ExplicitChainOverridesLoopCarriedDataEdge) {
  // MoL-like substep: CalcRHS reads prim, PostStep writes it for the next pass; the declared chain
  // CalcRHS -> Update -> PostStep must win over the implied PostStep -> CalcRHS edge.
  Harness h{R"Y(thorn: L
variables:
  - {group: cons, tensor: [scalar D], role: evolved, rhs: rhs}
  - {group: rhs, tensor: [scalar D]}
  - {group: prim, tensor: [scalar rho]}
schedule:
  - {function: CalcRHS, in: evol, reads: [prim], writes: [rhs], description: rhs from prim}
  - {function: Update, in: evol, after: [CalcRHS], reads: [cons, rhs], writes: [cons], description: update}
  - {function: PostStep, in: evol, after: [Update], reads: [cons], writes: [prim], description: con2prim}
)Y"};
  Scheduler s = h.make();
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  s.run_bin("evol", ctx);
  EXPECT_EQ(h.calls, (std::vector<std::string>{"L::CalcRHS", "L::Update", "L::PostStep"}));
}

TEST(Scheduler, DebugViewOfUndeclaredGroupIsAnErrorNamingFunctionAndGroup) {
  Harness h{R"Y(thorn: E
variables:
  - {group: u, tensor: [scalar u]}
  - {group: v, tensor: [scalar v]}
schedule:
  - {function: Fine, in: initial, reads: [u], description: views only what it declares}
  - {function: Peek, in: evol, reads: [u], description: views v without declaring it}
)Y"};
  h.impl.functions["E::Fine"] = [](Context& c) {
    for (Block* b : c.grid().local_blocks()) (void)GroupView(c, *b, "E::u", 1);
  };
  h.impl.functions["E::Peek"] = [](Context& c) {
    for (Block* b : c.grid().local_blocks()) (void)GroupView(c, *b, "E::v", 1);
  };
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  RecordingGrid grid(h.vars);
  ctx.set_grid(&grid);
  {
    Scheduler s = h.make();  // without --debug the access is not checked
    EXPECT_NO_THROW(s.run_bin("evol", ctx));
  }
  Scheduler s = h.make();
  s.set_debug(true);
  EXPECT_NO_THROW(s.run_bin("initial", ctx));
  expect_error<RunError>([&] { s.run_bin("evol", ctx); }, {"E::Peek accesses E::v", "does not declare"});
  // After the failed call no check is left behind for code outside scheduled functions.
  EXPECT_NO_THROW((void)GroupView(ctx, *grid.blocks_[0], "E::v", 1));
}

TEST(GroupView, AddressesTheBlocksComponentsAndChecksTheirCount) {
  Harness h{R"Y(thorn: F
variables:
  - {group: w, tensor: [scalar a, vector b, tensor_dd g]}
)Y"};
  RecordingGrid grid(h.vars);
  Block& b = *grid.blocks_[0];
  const GroupView view(b, 0, 10);
  for (int c = 0; c < 10; ++c) EXPECT_EQ(&view(c, 2, 0, 0), &b.field(0, c)(2, 0, 0));
  EXPECT_EQ(&view.field(4).operator()(-1, 0, 0), &b.field(0, 4)(-1, 0, 0));
  EXPECT_EQ(symmetric_index(2, 1), 4);
  EXPECT_EQ(symmetric_index(0, 0), 0);
  EXPECT_EQ(symmetric_index(2, 2), 5);
  expect_error<RunError>([&] { (void)GroupView(b, 0, 9); }, {"expects 9 components", "holds 10"});
}

// Initial data (issue 16): a NaN in a declared output is fatal without --debug, naming the function,
// the group, the component and the place.
TEST(Scheduler, NaNFromInitialDataIsFatalWithTheFunctionNamed) {
  Harness h{R"(thorn: D
variables:
  - {group: u, tensor: [scalar u]}
schedule:
  - {function: Bad, in: initial, writes: [u], description: writes one NaN}
)"};
  h.impl.functions["D::Bad"] = [](Context& c) {
    for (Block* b : c.grid().local_blocks()) b->field(0, 0)(2, 0, 0) = std::numeric_limits<double>::quiet_NaN();
  };
  Scheduler s = h.make();
  Context ctx(h.params, h.vars, MPI_COMM_WORLD);
  RecordingGrid grid(h.vars);
  ctx.set_grid(&grid);
  EXPECT_NO_THROW(s.run_bin("initial", ctx));  // the check is on for initial data only
  s.set_nan_check(true);
  expect_error<RunError>([&] { s.run_bin("initial", ctx); },
                         {"D::Bad wrote NaN into 1 interior points of D::u", "component u at cell (2, 0, 0)"});
}

// A group with `if:` has storage only when its condition holds; an item that touches it must be
// switched off by its own condition whenever the group is absent.
const char* kConditionalStorage = R"(thorn: M
parameters:
  - {name: field, type: keyword, values: [none, evolved], default: none, steerable: never, description: d}
  - {name: tuned, type: bool, default: false, steerable: always, description: d}
variables:
  - {group: u, tensor: [scalar u]}
  - {group: B, tensor: [scalar B], if: "M::field == evolved"}
schedule:
  - function: Hydro
    in: analysis
    writes: [u]
    description: always
  - function: Magnetic
    in: analysis
    if: "M::field == evolved"
    reads: [u]
    writes: [B]
    description: only with storage for B
)";

TEST(Scheduler, GroupsWithAConditionHaveStorageOnlyWhenItHolds) {
  {
    Harness h({kConditionalStorage});
    EXPECT_EQ(h.vars.find("M::B"), -1);
    ASSERT_NE(h.vars.without_storage("M::B"), nullptr);
    Scheduler s = h.make();  // Magnetic is off: its access to B is not an error
  }
  {
    Harness h({kConditionalStorage}, {{"M::field", "evolved"}});
    EXPECT_GE(h.vars.find("M::B"), 0);
    Scheduler s = h.make();
  }
  // An item that runs while the group is absent is refused, naming both.
  const std::string unguarded = std::string(kConditionalStorage) + R"(  - function: Reader
    in: analysis
    reads: [B]
    description: no condition
)";
  expect_error<InputError>([&] { Harness h({unguarded.c_str()}); h.make(); }, {"Reader", "M::B", "no storage", "M::field == evolved"});
  // Two conditions: a function with its own `if:` inside a schedule group whose fixed `if:` is false
  // cannot run either, so it may access the absent group; once the group's `if:` holds, its own
  // condition decides.
  const std::string nested = std::string(kConditionalStorage) + R"(  - group: MagneticOnly
    in: analysis
    if: "M::field == evolved"
    description: runs only with storage for B
  - function: NestedWriter
    in: MagneticOnly
    if: "!M::tuned"
    writes: [B]
    description: two conditions
)";
  {
    Harness h({nested.c_str()});
    Scheduler s = h.make();
  }
  {
    Harness h({nested.c_str()}, {{"M::field", "evolved"}});
    Scheduler s = h.make();
  }
  // A storage condition on a steerable parameter is refused at the group's line.
  const std::string steerable = std::string(R"(thorn: S
parameters:
  - {name: tuned, type: bool, default: false, steerable: always, description: d}
variables:
  - {group: x, tensor: [scalar x], if: "S::tuned"}
)");
  expect_error<InputError>([&] { Harness h({steerable.c_str()}); }, {"thorn0.yaml", "steerable: never"});
}
