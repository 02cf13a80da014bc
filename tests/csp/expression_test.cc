// The `expression` kind: muparser formulas as constraints.
#include "sightline/csp/kinds/expression.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sightline/csp/kinds/builder.h"
#include "sightline/csp/files/problem_file.h"
#include "incremental_check.h"

namespace sightline::csp {
namespace {

std::unique_ptr<Problem> with_formula(const std::string& formula) {
  ProblemBuilder b;
  b.real("x", -10, 10);
  b.real("y", -10, 10);
  b.parameter("gap", 2);
  b.constrain("expression", {"x", "y"}, spec_from({{"formula", formula}}));
  return b.build();
}

double violation_at(const Problem& p, double x, double y) {
  const double v[] = {x, y};
  return p.constraint(0).violation(v);
}

TEST(ExpressionConstraint, ValueIsTheViolationWithNegativesClampedToZero) {
  const auto p = with_formula("x - 2");
  EXPECT_DOUBLE_EQ(violation_at(*p, 5, 0), 3);
  EXPECT_DOUBLE_EQ(violation_at(*p, 2, 0), 0);
  EXPECT_DOUBLE_EQ(violation_at(*p, -4, 0), 0);
  EXPECT_EQ(p->constraint(0).kind(), "expression");
  EXPECT_FALSE(p->constraint(0).has_exact_gradient());
}

TEST(ExpressionConstraint, IntegerFunctionsForDerivedValues) {
  // idiv and mod as Python's // and %, floor and ceil; a zero divisor is undefined.
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("idiv(x, 3)"), 7, 0), 2);
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("-idiv(x, 3)"), -7, 0), 3);  // -7 // 3 = -3
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("mod(x, 3)"), 7, 0), 1);
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("mod(x, 3)"), -7, 0), 2);    // -7 % 3 = 2
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("floor(x)"), 2.7, 0), 2);
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("ceil(x)"), 2.2, 0), 3);
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("idiv(x, 3) != idiv(y, 3)"), 4, 5), 0);
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("idiv(x, 3) != idiv(y, 3)"), 4, 7), 1);
  EXPECT_GE(violation_at(*with_formula("mod(x, y)"), 4, 0), 1e9);
}

TEST(ExpressionConstraint, PositionalNamesServeEveryScopeOfAList) {
  EXPECT_DOUBLE_EQ(violation_at(*with_formula("_1 - 2 * _2"), 7, 3), 1);
  const auto p = parse_problem(R"(name: shared
variables:
  - {names: [a, b, c, d], int: [0, 9]}
constraints:
  - {kind: expression, scopes: [[a, b], [c, d]], formula: "abs(_1 - _2) > 2"}
)", "shared.yaml");
  ASSERT_EQ(p->num_constraints(), 2u);
  const double v[] = {1, 5, 4, 5};
  EXPECT_EQ(p->constraint(0).violation(v), 1);  // |1 - 5| > 2
  EXPECT_EQ(p->constraint(1).violation(v), 0);  // |4 - 5| <= 2
}

TEST(ExpressionConstraint, ComparisonsMakeZeroOneConstraints) {
  const auto p = with_formula("x + y != 3");
  EXPECT_EQ(violation_at(*p, 1, 2), 0);
  EXPECT_EQ(violation_at(*p, 1, 1), 1);
  const auto q = with_formula("abs(x - y)");
  EXPECT_DOUBLE_EQ(violation_at(*q, 1, 4.5), 3.5);
}

TEST(ExpressionConstraint, ParametersAreReadAfterEverySet) {
  const auto p = with_formula("abs(x - y) - gap");
  EXPECT_DOUBLE_EQ(violation_at(*p, 0, 5), 3);
  p->parameters().set("gap", 4.5);
  EXPECT_DOUBLE_EQ(violation_at(*p, 0, 5), 0.5);
  p->parameters().set("gap", 0);
  EXPECT_DOUBLE_EQ(violation_at(*p, 0, 5), 5);
}

TEST(ExpressionConstraint, UndefinedValuesCountAsAHugeViolation) {
  const auto p = with_formula("sqrt(x)");
  EXPECT_EQ(violation_at(*p, -1, 0), ExpressionConstraint::kUndefinedViolation);
  EXPECT_DOUBLE_EQ(violation_at(*p, 4, 0), 2);
  const auto q = with_formula("1 / (x - y)");
  EXPECT_EQ(violation_at(*q, 1, 1), ExpressionConstraint::kUndefinedViolation);
}

TEST(ExpressionConstraint, FiniteDifferenceGradientMatchesTheAnalyticOne) {
  const auto p = with_formula("x * x + 3 * y + gap");  // > 0 around (1.5, 2): smooth there
  const double v[] = {1.5, 2};
  double g[2];
  EXPECT_DOUBLE_EQ(p->constraint(0).violation_and_gradient(v, g), 1.5 * 1.5 + 6 + 2);
  EXPECT_NEAR(g[0], 3.0, 1e-6);
  EXPECT_NEAR(g[1], 3.0, 1e-6);
}

TEST(ExpressionConstraint, DeltasMatchFullReEvaluationOnRandomMoves) {
  ProblemBuilder b;
  b.integer("a", 0, 4);
  b.integer("b", 0, 4);
  b.real("c", -1, 1);
  b.parameter("k", 2);
  b.constrain("expression", {"a", "b"}, spec_from({{"formula", "a + b != 4"}}), 2);
  b.constrain("expression", {"a", "c"}, spec_from({{"formula", "abs(a * c - k)"}}));
  b.constrain("expression", {"b", "c"}, spec_from({{"formula", "b - c * 3"}}), 1, true);
  const auto p = b.build();
  testing::check_incremental_matches_full(*p, 5, 1000);
}

TEST(ExpressionConstraint, ParseErrorsAndUnknownNamesAreInputErrorsAtTheFormula) {
  const std::string head =
      "variables:\n"
      "  - {names: [x, y], real: [0, 1]}\n"
      "parameters: {gap: 1}\n"
      "constraints:\n";
  for (const char* formula : {"x +* y", "x + zz", "abs(x", "gap - w", "x + + "}) {
    const std::string text =
        head + "  - {kind: expression, scope: [x, y], formula: \"" + formula + "\"}\n";
    try {
      parse_problem(text, "expr.yaml");
      FAIL() << formula << " should not parse";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "expr.yaml");
      EXPECT_EQ(e.where().line, 5) << e.what();
      EXPECT_NE(std::string(e.what()).find(formula), std::string::npos) << e.what();
      // A parse error, never muparser's "Internal error" (what it says of "x + +").
      EXPECT_EQ(std::string(e.what()).find("Internal error"), std::string::npos) << e.what();
    }
  }
}

TEST(ExpressionConstraint, ANameThatIsBothVariableAndParameterIsRefused) {
  Parameters table;
  table.add("x", 1);
  EXPECT_THROW(ExpressionConstraint({0}, {"x"}, "x", &table), std::invalid_argument);
  EXPECT_THROW(ExpressionConstraint({0}, {"x.y"}, "1", nullptr), std::invalid_argument);
  EXPECT_NO_THROW(ExpressionConstraint({0}, {"x"}, "x", nullptr));
}

}  // namespace
}  // namespace sightline::csp
