#include "remnant/thorn_spec.hpp"
#include "test_helpers.hpp"

using namespace remnant;
using remnant::test::expect_error;

TEST(ThornSpec, ParsesAFullThorn) {
  auto t = parse_thorn_spec(R"(thorn: Hydro
provides: [hydro]
requires: [grid]
variables:
  - group: cons
    tensor: [scalar D, covector S, scalar tau]
    role: evolved
    rhs: cons_rhs
  - group: cons_rhs
    tensor: [scalar D, covector S, scalar tau]
  - group: B
    centering: face_x
    tensor: [axial_vector B]
parameters:
  - {name: cfl, type: real, range: "(0:1]", default: 0.3, steerable: recover, description: Courant factor}
schedule:
  - function: Hydro_RHS
    in: evol
    reads: [cons(everywhere), Grid::coords]
    writes: [cons_rhs]
    after: [{name: Other, optional: true}]
    every: 2
    if: "Hydro::cfl == 0.3"
    description: right-hand side
)", "thorns/Hydro/thorn.yaml");
  EXPECT_EQ(t.name, "Hydro");
  ASSERT_EQ(t.variables.size(), 3u);
  EXPECT_EQ(t.variables[0].ncomp(), 5);
  EXPECT_EQ(t.variables[0].components[1].name, "S1");
  EXPECT_TRUE(t.variables[0].checkpoint);  // evolved groups are checkpointed by default
  EXPECT_EQ(t.variables[2].centering, Centering::face_x);
  ASSERT_EQ(t.schedule.size(), 1u);
  const auto& s = t.schedule[0];
  EXPECT_EQ(s.reads.size(), 2u);
  EXPECT_EQ(s.reads[0].region, Region::everywhere);
  EXPECT_EQ(s.reads[1].group, "Grid::coords");
  EXPECT_TRUE(s.after[0].optional);
  EXPECT_EQ(s.every, 2);
  EXPECT_EQ(s.condition.op, Condition::Op::equal);
  EXPECT_EQ(t.parameters[0].steerable, Steerable::recover);
}

TEST(ThornSpec, ReflectionParitiesFollowTensorType) {
  auto v = expand_tensor(TensorKind::vector, "v");
  EXPECT_EQ(v[0].reflection_parity, (std::array<int, 3>{-1, 1, 1}));
  EXPECT_EQ(v[2].reflection_parity, (std::array<int, 3>{1, 1, -1}));
  auto b = expand_tensor(TensorKind::axial_vector, "B");
  EXPECT_EQ(b[2].reflection_parity, (std::array<int, 3>{-1, -1, 1}));  // B^z is even across the equator
  auto g = expand_tensor(TensorKind::tensor_dd, "g");
  ASSERT_EQ(g.size(), 6u);
  EXPECT_EQ(g[0].name, "g11");
  EXPECT_EQ(g[0].reflection_parity, (std::array<int, 3>{1, 1, 1}));
  EXPECT_EQ(g[1].name, "g12");
  EXPECT_EQ(g[1].reflection_parity, (std::array<int, 3>{-1, -1, 1}));
}

TEST(ThornSpec, SchemaErrorsNameFileAndLine) {
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nparameters:\n  - {name: x, type: real, description: d}\n", "a.yaml"); },
                           {"a.yaml:3:5", "needs a 'default'"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nparameters:\n  - {name: x, type: float, default: 1, description: d}\n", "a.yaml"); },
                           {"a.yaml:3", "type 'float' is not one of"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nschedul: []\n", "a.yaml"); }, {"a.yaml:2:1", "did you mean 'schedule'"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nschedule:\n  - function: f\n    in: evol\n", "a.yaml"); },
                           {"a.yaml:3:5", "needs a 'description'"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nvariables:\n  - group: u\n    tensor: [spinor u]\n", "a.yaml"); },
                           {"a.yaml:4:14", "kind one of"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nvariables:\n  - group: u\n    tensor: [scalar u]\n    role: evolved\n", "a.yaml"); },
                           {"needs 'rhs"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nschedule:\n  - function: f\n    in: evol\n    reads: [u(ghosts)]\n    description: d\n", "a.yaml"); },
                           {"a.yaml:5:13", "region 'ghosts'"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nparameters: [\n", "a.yaml"); }, {"a.yaml:", "YAML syntax error"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nvariables:\n  - group: u\n    centering: face_q\n    tensor: [scalar u]\n", "a.yaml"); },
                           {"a.yaml:4:", "centering 'face_q' is not one of: cell, face_x, face_y, face_z, edge_x"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nvariables:\n  - group: B\n    centering: face_x\n    tensor: [scalar B]\n    role: evolved\n    rhs: B_rhs\n", "a.yaml"); },
                           {"a.yaml:3:", "evolved face_x-centred group 'B' needs a grid for staggered variables", "staggered_grid"});
  EXPECT_NO_THROW(parse_thorn_spec("thorn: A\nrequires: [staggered_grid]\nvariables:\n  - group: B\n    centering: face_x\n    tensor: [scalar B]\n    role: evolved\n    rhs: B_rhs\n", "a.yaml"));
}

TEST(ThornSpec, BasisOfVectorComponents) {
  const auto t = parse_thorn_spec(
      "thorn: A\nvariables:\n  - {group: B, tensor: [vector B], basis: cartesian}\n  - {group: v, tensor: [vector v]}\n"
      "  - {group: w, tensor: [vector w], basis: coordinate}\n",
      "a.yaml");
  EXPECT_TRUE(t.variables[0].cartesian_basis);
  EXPECT_FALSE(t.variables[1].cartesian_basis);
  EXPECT_FALSE(t.variables[2].cartesian_basis);
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nvariables:\n  - {group: B, tensor: [vector B], basis: polar}\n", "a.yaml"); },
                           {"a.yaml:3:", "basis 'polar' is not one of: coordinate, cartesian"});
}

// One component of a vector ("axial_vector B[2]", e.g. a face field of one direction) carries that
// component's index and parities, not a scalar's.
TEST(ThornSpec, SingleComponentOfAVector) {
  const auto t = parse_thorn_spec("thorn: A\nvariables:\n  - {group: B2, centering: face_y, tensor: [\"axial_vector B[2]\"]}\n", "a.yaml");
  ASSERT_EQ(t.variables[0].components.size(), 1u);
  const auto& c = t.variables[0].components[0];
  EXPECT_EQ(c.name, "B2");
  EXPECT_EQ(c.kind, TensorKind::axial_vector);
  EXPECT_EQ(c.indices[0], 1);
  EXPECT_EQ(c.reflection_parity, (std::array<int, 3>{-1, 1, -1}));
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nvariables:\n  - {group: u, tensor: [\"scalar u[1]\"]}\n", "a.yaml"); },
                           {"a.yaml:3:", "<name>[N]"});
}

// `ghosts: N` (issue 21, memory): fewer ghost layers for groups no one synchronises; bad values
// and evolved groups are refused with the file and line.
TEST(ThornSpec, GhostLayersPerGroup) {
  const auto t = parse_thorn_spec(
      "thorn: A\nvariables:\n  - {group: u, tensor: [scalar u]}\n  - {group: f, tensor: [scalar f], ghosts: 1}\n"
      "  - {group: r, tensor: [scalar r], ghosts: 0}\n",
      "a.yaml");
  EXPECT_EQ(t.variables[0].ghosts, -1) << "absent: the Grid's ghost zones";
  EXPECT_EQ(t.variables[1].ghosts, 1);
  EXPECT_EQ(t.variables[2].ghosts, 0);
  for (const std::string bad : {"-1", "9", "x", "1.5", "[1]"})
    expect_error<InputError>([&] { parse_thorn_spec("thorn: A\nvariables:\n  - {group: u, tensor: [scalar u], ghosts: " + bad + "}\n", "a.yaml"); },
                             {"a.yaml:3:", "ghosts", "of group 'u'", "0 to 8"});
  expect_error<InputError>([] { parse_thorn_spec("thorn: A\nvariables:\n  - {group: u, tensor: [scalar u], role: evolved, rhs: r, ghosts: 1}\n  - {group: r, tensor: [scalar r]}\n", "a.yaml"); },
                           {"a.yaml:3:", "evolved group 'u' cannot declare 'ghosts'"});
}
