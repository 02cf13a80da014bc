#include "sightline/csp/kinds/builder.h"

#include <gtest/gtest.h>

#include <random>

#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/kinds/not_equal.h"
#include "incremental_check.h"

namespace sightline::csp {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument thrown)";
}

TEST(ProblemBuilder, BuildsTheSameProblemAsTheEquivalentFile) {
  ProblemBuilder b("twin");
  b.integer("x", 0, 4);
  b.values("y", {1, 2, 4, 8});
  b.real("z", -1, 1);
  b.parameter("goal", 3);
  b.constrain("not_equal", {"x", "y"}, Spec(), 1, true);
  b.constrain(
      "linear", {"x", "y", "z"},
      spec_from({{"coefficients", std::vector<double>{1, -1, 2}}, {"op", "<="}, {"rhs", "goal"}}),
      2);
  b.constrain("abs_deviation", {"z"}, spec_from({{"target", 0.5}, {"label", "z near half"}}), 0.5);
  b.constrain("expression", {"x", "z"}, spec_from({{"formula", "x * z - goal"}}));
  const auto built = b.build();

  const auto read = parse_problem(R"(
name: twin
variables:
  - {name: x, int: [0, 4]}
  - {name: y, values: [1, 2, 4, 8]}
  - {name: z, real: [-1, 1]}
parameters: {goal: 3}
constraints:
  - {kind: not_equal, scope: [x, y], hard: true}
  - {kind: linear, scope: [x, y, z], coefficients: [1, -1, 2], op: "<=", rhs: goal, weight: 2}
  - {kind: abs_deviation, scope: [z], target: 0.5, weight: 0.5, label: z near half}
  - {kind: expression, scope: [x, z], formula: "x * z - goal"}
)",
                                  "twin.yaml");

  ASSERT_EQ(built->num_variables(), read->num_variables());
  ASSERT_EQ(built->num_constraints(), read->num_constraints());
  EXPECT_EQ(built->name(), read->name());
  EXPECT_EQ(built->constraint(2).label(), "z near half");
  EXPECT_EQ(read->constraint(2).label(), "z near half");
  std::mt19937 rng(2);
  for (int trial = 0; trial < 200; ++trial) {
    const Assignment a = testing::random_assignment(*built, rng);
    const Score s = built->score(a);
    const Score t = read->score(a);
    EXPECT_DOUBLE_EQ(s.hard, t.hard);
    EXPECT_DOUBLE_EQ(s.soft, t.soft);
  }
  // The parameter is live in both.
  built->parameters().set("goal", -1);
  const Assignment a = {4, 1, 1};
  EXPECT_DOUBLE_EQ(built->constraint(1).violation(a), 6);  // 4 - 1 + 2 = 5 > -1 by 6
}

TEST(ProblemBuilder, AcceptsReadyMadeConstraints) {
  ProblemBuilder b;
  const VariableId x = b.integer("x", 0, 1);
  const VariableId y = b.integer("y", 0, 1);
  b.add(std::make_unique<NotEqual>(x, y));
  const auto p = b.build();
  EXPECT_EQ(p->num_constraints(), 1u);
  EXPECT_EQ(p->cost(Assignment{1, 1}), 1);
}

TEST(ProblemBuilder, ErrorsNameWhatIsWrong) {
  ProblemBuilder b;
  b.integer("x", 0, 3);
  b.integer("y", 0, 3);
  EXPECT_NE(message_of([&] { b.integer("x", 0, 1); }).find("'x'"), std::string::npos);
  EXPECT_NE(message_of([&] { b.integer("e", 3, 1); }).find("'e'"), std::string::npos);
  EXPECT_NE(message_of([&] { b.values("v", {}); }).find("'v'"), std::string::npos);
  EXPECT_NE(message_of([&] { b.real("r", 0, INFINITY); }).find("'r'"), std::string::npos);
  EXPECT_NE(message_of([&] { b.parameter("x", 1); }).find("'x'"), std::string::npos);
  EXPECT_NE(message_of([&] { b.parameter("p", NAN); }).find("'p'"), std::string::npos);

  const std::string unknown_kind = message_of([&] { b.constrain("differnt", {"x", "y"}); });
  EXPECT_NE(unknown_kind.find("differnt"), std::string::npos) << unknown_kind;
  EXPECT_NE(unknown_kind.find("not_equal"), std::string::npos) << unknown_kind;  // the known list

  EXPECT_NE(message_of([&] {
              b.constrain("not_equal", {"x", "w"});
            }).find("'w'"),
            std::string::npos);
  const std::string field = message_of([&] {
    b.constrain("linear", {"x", "y"}, spec_from({{"op", "<="}, {"rsh", 2}}));
  });
  EXPECT_NE(field.find("rsh"), std::string::npos) << field;
  EXPECT_NE(field.find("linear(x, y)"), std::string::npos) << field;
  EXPECT_NE(message_of([&] {
              b.constrain("linear", {"x"}, spec_from({{"weight", 2}}));
            }).find("'weight'"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              b.constrain("not_equal", {"x", "y"}, Spec(), -1);
            }).find("weight"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              b.constrain("not_equal", {"x", "x"});
            }).find("twice"),
            std::string::npos);
  // A number where a word is wanted is quoted as written: '5', not '5.000000'.
  const std::string op = message_of([&] {
    b.constrain("linear", {"x", "y"}, spec_from({{"op", 5}, {"rhs", 2}}));
  });
  EXPECT_NE(op.find("got '5'"), std::string::npos) << op;
  EXPECT_EQ(b.problem().num_constraints(), 0u);
}

TEST(ProblemBuilder, CannotBeUsedAfterBuild) {
  ProblemBuilder b;
  b.integer("x", 0, 1);
  auto p = b.build();
  ASSERT_NE(p, nullptr);
  EXPECT_THROW(b.integer("y", 0, 1), std::logic_error);
  EXPECT_THROW(b.build(), std::logic_error);
}

}  // namespace
}  // namespace sightline::csp
