// Reading the collision columns' references back from a resumed analysis.tsv
// (Analysis/collision_reference.hpp): the first row's rho_max and rho_max_point, the last row's time
// and quad_dI, found by the header's names wherever the optional columns put them.
#include <gtest/gtest.h>

#include <sstream>

#include "Analysis/collision_reference.hpp"

namespace remnant::analysis {
namespace {

const char* header = "# iteration\ttime\trho_max\tJ\trho_max_point\tquad_dI\n";

TEST(CollisionReference, FirstRowNormalisesLastRowDifferentiates) {
  std::istringstream in(std::string(header) +
                        "0\t0\t0.00076010177652040658\t9\t0.0008\t0\n"
                        "5\t8.75\t0.00075\t9\t0.00079\t-0.19026068936762353\n"
                        "10\t17.5\t0.00074\t9\t0.00078\t-0.25\n");
  const auto r = collision_reference_from_tsv(in);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->rho_max, 0.00076010177652040658);  // the %.17g text reads back to the same double
  EXPECT_EQ(r->rho_max_point, 0.0008);
  EXPECT_TRUE(r->has_previous);
  EXPECT_EQ(r->previous_time, 17.5);
  EXPECT_EQ(r->previous_quad_dI, -0.25);
}

TEST(CollisionReference, RowCutShortIsNotTheLastRow) {
  std::istringstream in(std::string(header) + "0\t0\t1e-3\t9\t2e-3\t0\n5\t1\t1e-3\t9\t2e-3\t0.5\n10\t2\t1e-3");
  const auto r = collision_reference_from_tsv(in);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->previous_time, 1.0);
  EXPECT_EQ(r->previous_quad_dI, 0.5);
}

TEST(CollisionReference, NothingWithoutRowsOrColumns) {
  std::istringstream header_only(header);
  EXPECT_FALSE(collision_reference_from_tsv(header_only));
  std::istringstream no_point("# iteration\ttime\trho_max\tquad_dI\n0\t0\t1e-3\t0\n");
  EXPECT_FALSE(collision_reference_from_tsv(no_point));
  std::istringstream empty("");
  EXPECT_FALSE(collision_reference_from_tsv(empty));
}

}  // namespace
}  // namespace remnant::analysis
