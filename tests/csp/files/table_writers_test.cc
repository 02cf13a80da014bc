// write_cfn as toulbar2 itself reads it: names are identifiers (labels, v<value>, x<id>),
// costs are exact decimals with the upper bound carrying their precision; and, when the
// toulbar2 program is installed, toulbar2 reads what is written and proves the optimum bnb
// proves (the writer's other round trips are in wcsp_writer_test.cc).
#include "sightline/csp/files/table_writers.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "sightline/csp/files/cfn_reader.h"
#include "sightline/csp/files/problem_file.h"
#include "sightline/csp/kinds/builder.h"
#include "sightline/solvers/registry.h"
#include "sightline/solvers/toulbar2/toulbar2_solver.h"

namespace sightline::csp {
namespace {

const std::string kProblems = std::string(SIGHTLINE_SOURCE_DIR) + "/examples/problems/";

std::string cfn_of(const Problem& p, const std::vector<std::vector<std::string>>& labels = {}) {
  std::ostringstream out;
  write_cfn(p, out, labels);
  return out.str();
}

// Values of awkward kinds, a name toulbar2 would refuse and one it would take, and costs in
// quarters and tenths.
std::unique_ptr<Problem> fractional_model() {
  ProblemBuilder b("fractional costs");  // a space: not a .cfn name either
  b.values("a b", {-1.5, 0, 0.5, 2});  // a space: not a .cfn name
  b.integer("9lives", 0, 3);           // starts with a digit
  b.integer("c", 0, 3);
  b.constrain("abs_deviation", {"a b"}, spec_from({{"target", 1}}), 0.5);
  b.constrain("not_equal", {"9lives", "c"}, Spec::map({}), 1.25);
  b.constrain("linear", {"9lives", "c"}, spec_from({{"op", ">="}, {"rhs", 5}}), 0.1);
  b.constrain("linear", {"c"}, spec_from({{"op", "<="}, {"rhs", 2}}), 1, true);
  return b.build();
}

TEST(CfnWriter, NamesValuesByTheirLabelsElseByVAndTheirValue) {
  const LoadedProblem australia = load_problem_file(kProblems + "australia.yaml");
  const std::string text = cfn_of(*australia.problem, australia.value_labels);
  EXPECT_NE(text.find("\"WA\": [\"red\", \"green\", \"blue\"]"), std::string::npos) << text;
  const std::string plain = cfn_of(*fractional_model());
  EXPECT_NE(plain.find("\"x0\": [\"v-1.5\", \"v0\", \"v0.5\", \"v2\"]"), std::string::npos) << plain;
  EXPECT_NE(plain.find("\"x1\": [\"v0\", \"v1\", \"v2\", \"v3\"]"), std::string::npos) << plain;
  EXPECT_NE(plain.find("\"c\": ["), std::string::npos) << plain;
  EXPECT_NE(plain.find("{\"name\": \"problem\""), std::string::npos) << plain;
}

TEST(CfnWriter, WritesCostsInTheFewestExactDecimalsWithTheBoundAsPrecise) {
  const std::string text = cfn_of(*fractional_model());
  // UB = 1 + 0.5 x 2.5 + 1.25 x 1 + 0.1 x 5 = 4: two places, as 1.25 needs.
  EXPECT_NE(text.find("\"mustbe\": \"<4.00\""), std::string::npos) << text;
  EXPECT_NE(text.find("1.25"), std::string::npos) << text;
  // Read back, every assignment scores as before.
  const auto original = fractional_model();
  const auto back = parse_cfn(text, "fractional.cfn");
  std::vector<double> values(3), indices(3);
  for (std::size_t i = 0; i < 4 * 4 * 4; ++i) {
    for (VariableId v = 0; v < 3; ++v) {
      const std::size_t index = (i >> (2 * v)) & 3;
      values[v] = original->domain(v).value_at(index);
      indices[v] = static_cast<double>(index);
    }
    const Score want = original->score(values), got = back->score(indices);
    ASSERT_EQ(want.feasible(), got.feasible());
    if (want.feasible()) {
      ASSERT_NEAR(want.soft, got.soft, 1e-9);
    }
  }
  // Small costs in fixed notation: toulbar2 reads no exponent.
  ProblemBuilder b("small");
  b.integer("x", 0, 1);
  b.constrain("abs_deviation", {"x"}, spec_from({{"target", 1}}), 0.00001);
  const std::string small = cfn_of(*b.build());
  EXPECT_NE(small.find("0.00001"), std::string::npos) << small;
  EXPECT_EQ(small.find("e-"), std::string::npos) << small;
}

TEST(CfnWriter, RefusesACostToulbar2WouldRoundNamingTheConstraint) {
  ProblemBuilder b("fine");
  b.integer("r5", 0, 2);
  b.constrain("abs_deviation", {"r5"}, spec_from({{"target", 1}}), 0.1234567);
  const auto p = b.build();
  std::ostringstream out;
  try {
    write_cfn(*p, out);
    ADD_FAILURE() << "written";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("abs_deviation(r5)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("decimal places"), std::string::npos) << e.what();
  }
}

// toulbar2 on `text` (a .cfn): its "Optimum:" value, or nothing (its output in `report`).
std::optional<double> toulbar2_optimum(const std::string& text, std::string& report) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("sightline_cfn_" + std::to_string(::getpid()) + ".cfn");
  std::ofstream(file) << text;
  const std::string command = "'" + *solvers::find_toulbar2() + "' '" + file.string() + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) report.append(buffer, n);
  pclose(pipe);
  std::filesystem::remove(file);
  const std::size_t at = report.rfind("Optimum: ");
  if (at == std::string::npos) return std::nullopt;
  return std::stod(report.substr(at + 9));
}

double bnb_optimum(const Problem& p) {
  const solvers::SolverResult r =
      solvers::SolverRegistry::global().create("bnb")->solve(p, p.default_assignment(), {});
  EXPECT_EQ(r.stop, solvers::StopReason::kProvenOptimal);
  return r.cost();
}

TEST(CfnWriter, Toulbar2ReadsWhatIsWrittenAndProvesBnbsOptimum) {
  if (!solvers::find_toulbar2()) GTEST_SKIP() << "toulbar2 is not installed";
  for (const char* file : {"australia.yaml", "seating.yaml"}) {
    const LoadedProblem model = load_problem_file(kProblems + file);
    std::string report;
    const std::optional<double> optimum = toulbar2_optimum(cfn_of(*model.problem, model.value_labels), report);
    ASSERT_TRUE(optimum) << file << ":\n" << report;
    EXPECT_EQ(*optimum, bnb_optimum(*model.problem)) << file << ":\n" << report;
  }
  const auto fractional = fractional_model();
  std::string report;
  const std::optional<double> optimum = toulbar2_optimum(cfn_of(*fractional), report);
  ASSERT_TRUE(optimum) << report;
  EXPECT_NEAR(*optimum, bnb_optimum(*fractional), 1e-9) << report;
}

}  // namespace
}  // namespace sightline::csp
