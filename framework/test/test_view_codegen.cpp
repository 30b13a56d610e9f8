#include "remnant/view_codegen.hpp"

#include "test_helpers.hpp"

using namespace remnant;
using remnant::test::expect_error;

namespace {

ThornSpec spec_of(const char* yaml) { return parse_thorn_spec(yaml, "thorns/T/thorn.yaml"); }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(ViewCodegen, AccessorsAndIndicesFollowTheDeclaredTensors) {
  const std::string h = generate_view_header(spec_of(R"(thorn: T
variables:
  - {group: w, tensor: [scalar rho, vector vel, tensor_dd g, scalar Ye], description: test group}
)"));
  EXPECT_TRUE(contains(h, "namespace remnant::vars::T {"));
  EXPECT_TRUE(contains(h, "struct w : GroupView {"));
  EXPECT_TRUE(contains(h, "full_name = \"T::w\""));
  EXPECT_TRUE(contains(h, "ncomp = 11;"));
  EXPECT_TRUE(contains(h, "rho = 0, vel1 = 1, vel2 = 2, vel3 = 3, g11 = 4, g12 = 5, g13 = 6, g22 = 7, g23 = 8, g33 = 9, Ye = 10"));
  EXPECT_TRUE(contains(h, "static constexpr int vel = 1;"));
  EXPECT_TRUE(contains(h, "static constexpr int g = 4;"));
  EXPECT_TRUE(contains(h, "double& rho(int i, int j, int k) const { return (*this)(0, i, j, k); }"));
  EXPECT_TRUE(contains(h, "double& vel(int a, int i, int j, int k) const { return (*this)(idx::vel + a, i, j, k); }"));
  EXPECT_TRUE(contains(h, "double& g(int a, int b, int i, int j, int k) const { return (*this)(idx::g + symmetric_index(a, b), i, j, k); }"));
  EXPECT_TRUE(contains(h, "double& Ye(int i, int j, int k) const { return (*this)(10, i, j, k); }"));
}

TEST(ViewCodegen, NamesThatCannotBeAccessorsAreErrorsWithTheirLocation) {
  expect_error<InputError>([] { generate_view_header(spec_of("thorn: T\nvariables:\n  - {group: w, tensor: [scalar double]}\n")); },
                           {"thorns/T/thorn.yaml:3:", "component 'double' of group T::w"});
  expect_error<InputError>([] { generate_view_header(spec_of("thorn: T\nvariables:\n  - {group: field, tensor: [scalar a]}\n")); },
                           {"group 'field' of group T::field"});
}
