// Interrupting a suite (execution/interruption.h): the runner stops starting runs, writes the
// results and summary of what is done, leaves no empty file, and a second invocation runs
// the rest.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "sightline/experiments/execution/interruption.h"
#include "sightline/experiments/execution/suite_runner.h"
#include "sightline/experiments/suite/suite.h"
#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

TEST(SuiteInterruption, StopsStartingRunsSavesWhatIsDoneAndResumes) {
  testing::ScratchDir dir("interrupt");
  // Six runs of a quarter second each (a colouring with too few colours runs to its limit).
  const Suite suite = read_suite_file(dir.write("suite.yaml", R"(name: interrupted
problems:
  instances:
    - {graph: )" + std::string(SIGHTLINE_SOURCE_DIR) + R"(/examples/graphs/myciel5.col, colours: 5}
  solvers: [sls, tabu]
  seeds: [1, 2, 3]
  limits: {time_seconds: 0.25}
isolation: false
)"));
  RunnerOptions options;
  options.out_dir = dir.path("out");
  options.jobs = 1;
  options.progress = false;
  std::thread interrupter([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(600));
    request_interruption();  // what SIGINT's handler does
  });
  const SuiteOutcome first = run_suite(suite, options);
  interrupter.join();
  EXPECT_TRUE(first.interrupted);
  EXPECT_GE(first.results.size(), 1u);
  EXPECT_LT(first.results.size(), 6u);
  EXPECT_EQ(first.ran, first.results.size());
  EXPECT_TRUE(std::filesystem::exists(options.out_dir + "/results.csv"));
  EXPECT_TRUE(std::filesystem::exists(options.out_dir + "/summary.md"));
  for (const auto& entry : std::filesystem::recursive_directory_iterator(options.out_dir)) {
    if (entry.is_regular_file()) {
      EXPECT_GT(entry.file_size(), 0u) << entry.path();
    }
  }
  const SuiteOutcome second = run_suite(suite, options);
  EXPECT_FALSE(second.interrupted);
  EXPECT_EQ(second.reused, first.results.size());
  EXPECT_EQ(second.results.size(), 6u);
}

}  // namespace
}  // namespace sightline::experiments
