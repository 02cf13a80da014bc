#include "sightline/csp/domain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace sightline::csp {
namespace {

TEST(Domain, IntegerRangeEnumeratesItsValuesInOrder) {
  const Domain d = Domain::integer_range(-2, 3);
  EXPECT_EQ(d.kind(), DomainKind::kIntegerRange);
  EXPECT_TRUE(d.is_discrete());
  EXPECT_FALSE(d.is_continuous());
  ASSERT_EQ(d.size(), 6u);
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_EQ(d.value_at(i), -2.0 + static_cast<double>(i));
    EXPECT_EQ(d.index_of(d.value_at(i)), i);
  }
  EXPECT_EQ(d.lower(), -2);
  EXPECT_EQ(d.upper(), 3);
  EXPECT_EQ(d.middle(), 1);  // value_at(6 / 2)
}

TEST(Domain, IntegerRangeRejectsNonMembers) {
  const Domain d = Domain::integer_range(0, 7);
  EXPECT_FALSE(d.index_of(8).has_value());
  EXPECT_FALSE(d.index_of(-1).has_value());
  EXPECT_FALSE(d.index_of(2.5).has_value());
  EXPECT_FALSE(d.contains(2.5));
  EXPECT_FALSE(d.contains(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(d.contains(7));
}

TEST(Domain, SingletonRangeHasOneValue) {
  const Domain d = Domain::integer_range(4, 4);
  EXPECT_EQ(d.size(), 1u);
  EXPECT_EQ(d.value_at(0), 4);
  EXPECT_EQ(d.middle(), 4);
}

TEST(Domain, ValueSetIsSortedAndUnique) {
  const Domain d = Domain::value_set({5, 1, 2, 5, -0.5});
  EXPECT_EQ(d.kind(), DomainKind::kValueSet);
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d.value_at(0), -0.5);
  EXPECT_EQ(d.value_at(1), 1);
  EXPECT_EQ(d.value_at(2), 2);
  EXPECT_EQ(d.value_at(3), 5);
  EXPECT_EQ(d.index_of(2), 2u);
  EXPECT_FALSE(d.index_of(3).has_value());
  EXPECT_EQ(d.lower(), -0.5);
  EXPECT_EQ(d.upper(), 5);
  EXPECT_EQ(d.middle(), 2);
}

TEST(Domain, RealIntervalIsContinuousWithNoIndex) {
  const Domain d = Domain::real_interval(-1, 3);
  EXPECT_TRUE(d.is_continuous());
  EXPECT_EQ(d.size(), 0u);
  EXPECT_FALSE(d.index_of(0).has_value());
  EXPECT_TRUE(d.contains(-1));
  EXPECT_TRUE(d.contains(2.75));
  EXPECT_FALSE(d.contains(3.0001));
  EXPECT_EQ(d.middle(), 1);
}

TEST(Domain, ClampReturnsTheNearestMember) {
  const Domain range = Domain::integer_range(0, 7);
  EXPECT_EQ(range.clamp(-3), 0);
  EXPECT_EQ(range.clamp(9.5), 7);
  EXPECT_EQ(range.clamp(3.4), 3);
  EXPECT_EQ(range.clamp(3.6), 4);

  const Domain set = Domain::value_set({1, 4, 10});
  EXPECT_EQ(set.clamp(-5), 1);
  EXPECT_EQ(set.clamp(2), 1);
  EXPECT_EQ(set.clamp(2.5), 1);  // ties go to the lower value
  EXPECT_EQ(set.clamp(3), 4);
  EXPECT_EQ(set.clamp(8), 10);
  EXPECT_EQ(set.clamp(100), 10);

  const Domain real = Domain::real_interval(-1, 1);
  EXPECT_EQ(real.clamp(0.25), 0.25);
  EXPECT_EQ(real.clamp(-7), -1);
  EXPECT_EQ(real.clamp(7), 1);
  EXPECT_EQ(real.clamp(std::numeric_limits<double>::quiet_NaN()), 0);  // the middle
}

TEST(Domain, DescribeNamesKindAndValues) {
  EXPECT_EQ(Domain::integer_range(0, 7).describe(), "int[0,7]");
  EXPECT_EQ(Domain::value_set({5, 1, 2}).describe(), "{1,2,5}");
  EXPECT_EQ(Domain::real_interval(-1, 1).describe(), "real[-1,1]");
  const std::string many = Domain::value_set({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}).describe();
  EXPECT_NE(many.find("10 values"), std::string::npos) << many;
}

TEST(Domain, FactoriesRefuseEmptyAndNonFiniteDomains) {
  EXPECT_THROW(Domain::integer_range(3, 2), std::invalid_argument);
  EXPECT_THROW(Domain::value_set({}), std::invalid_argument);
  EXPECT_THROW(Domain::value_set({1, std::numeric_limits<double>::quiet_NaN()}),
               std::invalid_argument);
  EXPECT_THROW(Domain::real_interval(1, 0), std::invalid_argument);
  EXPECT_THROW(Domain::real_interval(0, std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  EXPECT_THROW(Domain::real_interval(std::numeric_limits<double>::quiet_NaN(), 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace sightline::csp
