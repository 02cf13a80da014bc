// Problem files: what they build, every kind of mistake reported with file and line, and
// the example files' documented optima confirmed by brute force.
#include "sightline/csp/files/problem_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>

#include "sightline/csp/incremental_evaluator.h"

namespace sightline::csp {
namespace {

const std::string kExamples = std::string(SIGHTLINE_SOURCE_DIR) + "/examples/problems/";

TEST(ProblemFile, ReadsVariablesParametersAndConstraints) {
  const LoadedProblem loaded = load_problem_text(R"(
name: demo
description: a bit of everything
variables:
  - {name: c, labels: [red, green, blue]}
  - {name: q, count: 3, int: [0, 2]}
  - {names: [u, v], values: [0.5, 1, 2]}
  - {name: r, real: [-1, 1]}
parameters:
  limit: 2.5
constraints:
  - {kind: not_equal, scope: [c, q0]}
  - kind: linear
    scope: [q]
    op: "<="
    rhs: limit
  - {kind: abs_deviation, vars: [u, v, r], target: 1, weight: 0.5, label: near one}
  - {kind: not_equal, scopes: [[q0, q1], [q1, q2]], hard: true}
)",
                                                 "demo.yaml");
  const Problem& p = *loaded.problem;
  EXPECT_EQ(p.name(), "demo");
  EXPECT_EQ(loaded.description, "a bit of everything");
  ASSERT_EQ(p.num_variables(), 7u);
  const char* names[] = {"c", "q0", "q1", "q2", "u", "v", "r"};
  for (VariableId v = 0; v < 7; ++v) EXPECT_EQ(p.variable(v).name, names[v]);
  EXPECT_EQ(p.variable(0).domain.describe(), "int[0,2]");
  EXPECT_EQ(p.variable(4).domain.describe(), "{0.5,1,2}");
  EXPECT_EQ(p.variable(6).domain.describe(), "real[-1,1]");
  EXPECT_EQ(loaded.value_name(0, 1), "green");
  EXPECT_EQ(loaded.value_name(1, 1), "1");
  EXPECT_EQ(loaded.value_name(4, 0.5), "0.5");
  EXPECT_DOUBLE_EQ(p.parameters().get("limit"), 2.5);

  ASSERT_EQ(p.num_constraints(), 5u);
  EXPECT_EQ(p.constraint(1).kind(), "linear");
  EXPECT_EQ(p.constraint(1).scope().size(), 3u);  // the array q
  EXPECT_EQ(p.constraint(2).label(), "near one");
  EXPECT_EQ(p.constraint(2).weight(), 0.5);
  EXPECT_TRUE(p.constraint(3).is_hard());
  EXPECT_TRUE(p.constraint(4).is_hard());
  EXPECT_EQ(p.constraint(4).scope()[0], 2u);

  // c = q0 (1 x 1); q0 + q1 + q2 = 5 > 2.5 by 2.5; |0.5 + 2 + 0 - 1| = 1.5 (x 0.5);
  // q1 = q2 breaks a hard disequality.
  const Assignment a = {1, 1, 2, 2, 0.5, 2, 0};
  EXPECT_DOUBLE_EQ(p.score(a).soft, 1 + 2.5 + 0.75);
  EXPECT_DOUBLE_EQ(p.score(a).hard, 1);
}

TEST(ProblemFile, DefaultsTheNameToTheFileStem) {
  const auto p = parse_problem("variables: [{name: x, int: [0, 1]}]\n", "dir/tiny.yaml");
  EXPECT_EQ(p->name(), "tiny");
  EXPECT_EQ(p->num_constraints(), 0u);
}

struct BadFile {
  const char* what;
  const char* text;
  int line;
  const char* says;  // a piece of the message
};

// Each text is one mistake; the error must name the file and this line.
const BadFile kBadFiles[] = {
    {"malformed YAML", "variables:\n  - {name: x, int: [0, 1]\n", 3, "YAML"},
    {"not a mapping", "- 1\n- 2\n", 1, "expected a problem"},
    {"unknown top-level field", "variables: [{name: x, int: [0, 1]}]\nconstrains: []\n", 2,
     "constrains"},
    {"missing variables", "name: empty\n", 1, "variables"},
    {"unknown kind",
     "variables: [{name: x, int: [0, 1]}]\nconstraints:\n  - {kind: differnt, scope: [x]}\n", 3,
     "not_equal"},
    {"missing kind", "variables: [{name: x, int: [0, 1]}]\nconstraints:\n  - {scope: [x]}\n", 3,
     "kind"},
    {"wrong arity",
     "variables: [{names: [x, y, z], int: [0, 1]}]\nconstraints:\n"
     "  - {kind: not_equal, scope: [x, y, z]}\n",
     3, "exactly 2"},
    {"coefficients of the wrong length",
     "variables: [{names: [x, y], int: [0, 1]}]\nconstraints:\n"
     "  - {kind: linear, scope: [x, y], op: \"<=\", rhs: 1,\n     coefficients: [1, 2, 3]}\n",
     4, "one coefficient per"},
    {"empty integer range", "variables:\n  - {name: x, int: [0, 1]}\n  - {name: y, int: [3, 1]}\n",
     3, "empty"},
    {"empty value set", "variables:\n  - {name: x, values: []}\n", 2, "empty"},
    {"empty labels", "variables:\n  - {name: x, labels: []}\n", 2, "empty"},
    {"real bound not finite", "variables:\n\n  - {name: x, real: [0, inf]}\n", 3, "finite"},
    {"NaN weight",
     "variables: [{name: x, int: [0, 1]}]\nconstraints:\n"
     "  - {kind: abs_deviation, scope: [x], weight: nan}\n",
     3, "weight"},
    {"negative weight",
     "variables: [{name: x, int: [0, 1]}]\nconstraints:\n"
     "  - {kind: abs_deviation, scope: [x], weight: -1}\n",
     3, "weight"},
    {"infinite parameter", "variables: [{name: x, int: [0, 1]}]\nparameters:\n  p: .inf\n", 3,
     "parameter 'p'"},
    {"unknown variable",
     "variables: [{names: [x, y], int: [0, 1]}]\nconstraints:\n"
     "  - {kind: not_equal, scope: [x, why]}\n",
     3, "unknown variable 'why'"},
    {"unknown variable in the second of several scopes",
     "variables: [{names: [x, y], int: [0, 1]}]\nconstraints:\n"
     "  - kind: not_equal\n    scopes:\n      - [x, y]\n      - [y, zed]\n",
     6, "zed"},
    {"duplicate variable", "variables:\n  - {name: x, int: [0, 1]}\n  - {name: x, int: [0, 1]}\n",
     3, "already used"},
    {"variable clashing with an array member",
     "variables:\n  - {name: q, count: 2, int: [0, 1]}\n  - {name: q1, int: [0, 1]}\n", 3, "'q1'"},
    {"parameter clashing with a variable",
     "variables: [{name: x, int: [0, 1]}]\nparameters:\n  x: 1\n", 3, "already used"},
    {"variable repeated in a scope",
     "variables: [{names: [x, y], int: [0, 1]}]\nconstraints:\n"
     "  - {kind: not_equal, scope: [x, x]}\n",
     3, "twice"},
    {"unknown constraint field",
     "variables: [{names: [x, y], int: [0, 1]}]\nconstraints:\n"
     "  - kind: linear\n    scope: [x, y]\n    op: \"<=\"\n    rsh: 1\n",
     6, "rsh"},
    {"unknown variable field", "variables:\n  - {name: x, int: [0, 1], wieght: 2}\n", 2, "wieght"},
    {"two domains", "variables:\n  - {name: x, int: [0, 1],\n     real: [0, 1]}\n", 3,
     "one domain"},
    {"no domain", "variables:\n  - {name: x}\n", 2, "domain"},
    {"bad count", "variables:\n  - {name: q, count: 0, int: [0, 1]}\n", 2, "count"},
    {"bad relation",
     "variables: [{name: x, int: [0, 1]}]\nconstraints:\n"
     "  - {kind: linear, scope: [x], op: \"<\", rhs: 1}\n",
     3, "relation"},
    {"rhs naming no parameter",
     "variables: [{name: x, int: [0, 1]}]\nparameters: {limit: 1}\nconstraints:\n"
     "  - {kind: linear, scope: [x], op: \"<=\", rhs: limt}\n",
     4, "limit"},
    {"both scope and scopes",
     "variables: [{names: [x, y], int: [0, 1]}]\nconstraints:\n"
     "  - {kind: not_equal, scope: [x, y], scopes: [[x, y]]}\n",
     3, "exactly one"},
    {"empty scope",
     "variables: [{name: x, int: [0, 1]}]\nconstraints:\n  - {kind: abs_deviation, scope: []}\n", 3,
     "at least one"},
    {"bad hard flag",
     "variables: [{name: x, int: [0, 1]}]\nconstraints:\n"
     "  - {kind: abs_deviation, scope: [x], hard: maybe}\n",
     3, "true or false"},
    // The alias is the list holding it: once a stack overflow (fuzz/README.md).
    {"alias inside the node its anchor names", "variables: &v\n  - *v\n", 1,
     "nested more than 1000 deep"},
};

class ProblemFileErrors : public ::testing::TestWithParam<BadFile> {};

TEST_P(ProblemFileErrors, NameTheFileAndTheLine) {
  const BadFile& bad = GetParam();
  try {
    parse_problem(bad.text, "bad.yaml");
    FAIL() << bad.what << ": no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "bad.yaml") << bad.what;
    EXPECT_EQ(e.where().line, bad.line) << bad.what << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.yaml:" + std::to_string(bad.line)), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(bad.says), std::string::npos)
        << bad.what << ": " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(EveryMistake, ProblemFileErrors, ::testing::ValuesIn(kBadFiles),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           std::string name;
                           for (const char* c = info.param.what; *c; ++c) {
                             name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
                           }
                           return name;
                         });

TEST(ProblemFile, AMistakeInARealFileNamesItsPathAndLine) {
  // australia.yaml with its sixth disequality pointing at a region that does not exist.
  std::ifstream in(kExamples + "australia.yaml");
  ASSERT_TRUE(in) << "examples/problems/australia.yaml is missing";
  std::string text, line;
  int number = 0, broken_line = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.find("[SA, NSW]") != std::string::npos) {
      line.replace(line.find("NSW"), 3, "NZ");
      broken_line = number;
    }
    text += line + "\n";
  }
  ASSERT_GT(broken_line, 0);
  const std::string path = ::testing::TempDir() + "australia-broken.yaml";
  std::ofstream(path) << text;
  try {
    read_problem_file(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, path);
    EXPECT_EQ(e.where().line, broken_line) << e.what();
    EXPECT_NE(std::string(e.what()).find("'NZ'"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

TEST(ProblemFile, AMissingFileIsAnInputErrorNamingIt) {
  try {
    read_problem_file("/nonexistent/nowhere.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/nowhere.yaml"), std::string::npos);
  }
}

// ---- the examples and their documented optima --------------------------------------------

// Calls visit(assignment) for every assignment of an all-discrete problem.
void for_each_assignment(const Problem& p, const std::function<void(const Assignment&)>& visit) {
  Assignment a(p.num_variables());
  std::vector<std::size_t> index(p.num_variables(), 0);
  for (VariableId v = 0; v < a.size(); ++v) a[v] = p.variable(v).domain.value_at(0);
  while (true) {
    visit(a);
    std::size_t v = 0;
    while (v < a.size() && ++index[v] == p.variable(static_cast<VariableId>(v)).domain.size()) {
      index[v] = 0;
      a[v] = p.variable(static_cast<VariableId>(v)).domain.value_at(0);
      ++v;
    }
    if (v == a.size()) return;
    a[v] = p.variable(static_cast<VariableId>(v)).domain.value_at(index[v]);
  }
}

struct Optimum {
  Score best{1e300, 1e300};
  std::vector<Assignment> where;
  void offer(const Score& s, const Assignment& a) {
    if (s.better_than(best)) {
      best = s;
      where.clear();
    }
    if (!best.better_than(s)) where.push_back(a);
  }
};

TEST(ProblemFileExamples, AustraliaHasEighteenProperColourings) {
  const LoadedProblem loaded = load_problem_file(kExamples + "australia.yaml");
  const Problem& p = *loaded.problem;
  ASSERT_EQ(p.num_variables(), 7u);
  ASSERT_EQ(p.num_constraints(), 9u);
  Optimum o;
  for_each_assignment(p, [&](const Assignment& a) { o.offer(p.score(a), a); });
  EXPECT_EQ(o.best.hard, 0);
  EXPECT_EQ(o.best.soft, 0);
  EXPECT_EQ(o.where.size(), 18u);
  EXPECT_EQ(loaded.value_name(2, 2), "blue");
}

TEST(ProblemFileExamples, SeatingOptimumIsCostTwoAtTheTwoDocumentedSeatings) {
  const auto p = read_problem_file(kExamples + "seating.yaml");
  Optimum o;
  for_each_assignment(*p, [&](const Assignment& a) { o.offer(p->score(a), a); });
  EXPECT_TRUE(o.best.feasible());
  EXPECT_DOUBLE_EQ(o.best.soft, 2.0);
  // ann bob cid dee eve, as the file's comment says.
  EXPECT_EQ(o.where, (std::vector<Assignment>{{1, 2, 5, 3, 4}, {1, 2, 3, 5, 4}}));
  // Over-constrained: no feasible seating meets every wish.
  EXPECT_GT(o.best.soft, 0);
}

TEST(ProblemFileExamples, ShelfOptimumIsTheDocumentedPointAndNoGridPointBeatsIt) {
  const auto p = read_problem_file(kExamples + "shelf.yaml");
  ASSERT_TRUE(p->all_continuous());
  const Assignment optimum = {0.7, 4, 1.2};
  const Score at = p->score(optimum);
  EXPECT_TRUE(at.feasible());
  EXPECT_NEAR(at.soft, 2.3, 1e-12);
  // Piecewise-linear cost with breakpoints on the 0.1 lattice: a 0.1 grid over the box would
  // find anything better. Scanned through the incremental evaluator to keep it fast.
  IncrementalEvaluator ev(*p, Assignment{0, 0, 0});
  double best = 1e300;
  for (int i = 0; i <= 100; ++i) {
    ev.assign(0, i / 10.0);
    for (int j = 0; j <= 100; ++j) {
      ev.assign(1, j / 10.0);
      for (int k = 0; k <= 100; ++k) {
        ev.assign(2, k / 10.0);
        if (ev.score().feasible()) best = std::min(best, ev.score().soft);
      }
    }
  }
  EXPECT_NEAR(best, 2.3, 1e-9);
  // Nearby points are worse, so the optimum is the documented one.
  for (VariableId v = 0; v < 3; ++v) {
    for (double step : {-0.05, 0.05}) {
      Assignment moved = optimum;
      moved[v] += step;
      const Score s = p->score(moved);
      EXPECT_TRUE(!s.feasible() || s.soft > 2.3 + 1e-6) << "variable " << v << " step " << step;
    }
  }
}

}  // namespace
}  // namespace sightline::csp

namespace sightline::csp {
namespace {

// Value labels are an expression's constants: `r == A` reads A as r's value 0.
TEST(ProblemFileLabels, AnExpressionNamesItsScopesValueLabels) {
  const auto p = parse_problem(R"yaml(name: labels
variables:
  - {names: [r, s], labels: [A, B, C]}
parameters:
  limit: 1
constraints:
  - {kind: expression, scope: [r], formula: "r == A", weight: 2}
  - {kind: expression, scope: [r, s], formula: "(r == s) * 5 + (s > B)"}
  - {kind: expression, scope: [s], formula: "s == D", constants: {D: 2}}
)yaml", "labels.yaml");
  for (double r = 0; r < 3; ++r) {
    for (double s = 0; s < 3; ++s) {
      const double want = 2 * (r == 0) + 5 * (r == s) + (s > 1) + (s == 2);
      EXPECT_DOUBLE_EQ(p->score(std::vector<double>{r, s}).soft, want) << r << " " << s;
    }
  }
}

TEST(ProblemFileLabels, ALabelMeaningTwoValuesInOneScopeIsRefusedAtTheScope) {
  try {
    parse_problem(R"yaml(variables:
  - {name: r, labels: [A, B]}
  - {name: s, labels: [B, A]}
constraints:
  - {kind: expression, scope: [r, s], formula: "r == A"}
)yaml", "twice.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("twice.yaml:5:"), std::string::npos) << what;
    EXPECT_NE(what.find("label 'B' is value 1 of r and value 0 of s"), std::string::npos) << what;
  }
  // A constant clashing with a scope variable is refused too.
  EXPECT_THROW(parse_problem(R"yaml(variables: [{name: x, int: [0, 2]}]
constraints:
  - {kind: expression, scope: [x], formula: "x", constants: {x: 1}}
)yaml", "clash.yaml"), InputError);
}

}  // namespace
}  // namespace sightline::csp

namespace sightline::csp {
namespace {

// One label over several scopes names each constraint by its scope too, so messages,
// tables and breakdowns tell them apart; a single scope keeps the label as written, and an
// unlabelled constraint is its kind over its variables' names.
TEST(ProblemFileLabels, ALabelSharedBySeveralScopesNamesEachByItsScope) {
  const auto p = parse_problem(R"yaml(variables:
  - {name: r, count: 4, int: [0, 2]}
constraints:
  - {kind: not_equal, label: no clash, scopes: [[r0, r1], [r2, r3]]}
  - {kind: not_equal, label: alone, scopes: [[r1, r2]]}
  - {kind: equals, scope: [r3], value: 1}
)yaml", "names.yaml");
  ASSERT_EQ(p->num_constraints(), 4u);
  EXPECT_EQ(p->constraint_name(0), "no clash(r0, r1)");
  EXPECT_EQ(p->constraint_name(1), "no clash(r2, r3)");
  EXPECT_EQ(p->constraint_name(2), "alone");
  EXPECT_EQ(p->constraint_name(3), "equals(r3)");
}

}  // namespace
}  // namespace sightline::csp
