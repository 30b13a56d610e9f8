// The flesh checks thorn.yaml declarations against the C++ registrations.
#include "remnant/driver.hpp"
#include "remnant/registrar.hpp"
#include "test_helpers.hpp"

using namespace remnant;
using remnant::test::expect_error;

namespace {

const char* kYaml = R"Y(thorn: Toy
schedule:
  - {function: Toy_Init, in: initial, description: declared and implemented}
  - {function: Toy_Missing, in: analysis, description: "declared, not implemented"}
)Y";
const char* kYamlOk = R"Y(thorn: Toy
schedule:
  - {function: Toy_Init, in: initial, description: declared and implemented}
)Y";

void register_init_only(ThornRegistrar& r) { r.function("Toy_Init", [](Context&) {}); }
void register_extra(ThornRegistrar& r) {
  r.function("Toy_Init", [](Context&) {});
  r.function("Toy_Undeclared", [](Context&) {});
}

}  // namespace

TEST(ThornCatalog, DeclaredFunctionWithoutImplementation) {
  const ThornEntry entries[] = {{"Toy", "thorns/Toy/thorn.yaml", kYaml, &register_init_only}};
  expect_error<InputError>([&] { ThornCatalog c(entries); },
                           {"thorns/Toy/thorn.yaml:4:5", "'Toy_Missing' is declared", "no C++ implementation"});
}

TEST(ThornCatalog, ImplementationWithoutDeclaration) {
  const ThornEntry entries[] = {{"Toy", "thorns/Toy/thorn.yaml", kYamlOk, &register_extra}};
  expect_error<InputError>([&] { ThornCatalog c(entries); },
                           {"thorns/Toy/thorn.yaml", "registers a C++ function 'Toy_Undeclared'", "does not declare"});
}

TEST(ThornCatalog, BadSchemaNamesTheFile) {
  const ThornEntry entries[] = {{"Toy", "thorns/Toy/thorn.yaml", "thorn: Toy\nschedule:\n  - {function: F, in: initial}\n",
                                 &register_init_only}};
  expect_error<InputError>([&] { ThornCatalog c(entries); }, {"thorns/Toy/thorn.yaml:3:5", "needs a 'description'"});
}

TEST(ThornCatalog, ConsistentThornIsAccepted) {
  const ThornEntry entries[] = {{"Toy", "thorns/Toy/thorn.yaml", kYamlOk, &register_init_only}};
  ThornCatalog c(entries);
  EXPECT_EQ(c.names(), std::vector<std::string>{"Toy"});
  EXPECT_NE(c.describe("Flesh").find("Flesh::out_dir"), std::string::npos);
}
