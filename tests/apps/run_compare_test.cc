// `sightline run --compare A,B` end to end through the shell: the Wilcoxon section appears in
// the printed summary and summary.md, cactus.csv and profiles.csv are written, and a name that
// is not a solver of the suite is a clear message with exit status 2 before any run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "run_sightline.h"

namespace sightline::test {
namespace {

namespace fs = std::filesystem;

class Scratch {
 public:
  Scratch()
      : dir_(fs::temp_directory_path() / ("sightline-run-compare-" + std::to_string(::getpid()))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "suite.yaml")
        << "name: pair\nproblems:\n  instances: [{nqueens: [5, 6, 7]}]\n"
           "  solvers: [sls, bnb]\n";
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& relative) const { return (dir_ / relative).string(); }

 private:
  fs::path dir_;
};

TEST(RunCompare, TheFlagAddsAWilcoxonSectionAndTheTimeFiles) {
  Scratch s;
  const Outcome r = run("run '" + s.path("suite.yaml") + "' --out '" + s.path("out") +
                        "' --jobs 1 --no-report --compare bnb,sls");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "### Wilcoxon signed-rank test: `bnb` vs `sls`")) << r.output;
  EXPECT_TRUE(contains(r.output, "### Ranking of problem solvers")) << r.output;
  std::ifstream summary(s.path("out/summary.md"));
  std::stringstream text;
  text << summary.rdbuf();
  EXPECT_TRUE(contains(text.str(), "`bnb` vs `sls`"));
  EXPECT_TRUE(fs::exists(s.path("out/cactus.csv")));
  EXPECT_TRUE(fs::exists(s.path("out/profiles.csv")));
}

TEST(RunCompare, AnUnknownSolverIsRefusedBeforeAnyRun) {
  Scratch s;
  const Outcome r =
      run("run '" + s.path("suite.yaml") + "' --out '" + s.path("out") + "' --compare sls,tabuu");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "--compare: 'tabuu' is not a solver")) << r.output;
  EXPECT_FALSE(fs::exists(s.path("out/results.csv")));
}

}  // namespace
}  // namespace sightline::test
