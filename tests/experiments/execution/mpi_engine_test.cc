// MpiEngine's launch detection (experiments/execution/mpi_engine.h): the program decides between the
// thread pool and the MPI engine from the variables an MPI launcher sets, before MPI starts.
// Rank 0's final reading of the folder waits for runs a worker reported but the file system
// does not show yet (NFS). The engine itself is tested end to end under mpirun
// (tests/apps/mpi_run_test.cc).
#include "sightline/experiments/execution/mpi_engine.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "tests/experiments/suite_test_files.h"

namespace sightline::experiments {
namespace {

// Sets the launcher variables for one test and clears them after.
class LaunchEnvironment : public ::testing::Test {
 protected:
  void SetUp() override { clear(); }
  void TearDown() override { clear(); }
  static void clear() {
    ::unsetenv("OMPI_COMM_WORLD_SIZE");
    ::unsetenv("PMI_SIZE");
  }
};

TEST_F(LaunchEnvironment, AProcessNotStartedByALauncherIsAlone) { EXPECT_EQ(mpi_launch_size(), 1); }

TEST_F(LaunchEnvironment, ReadsOpenMpisWorldSizeFirstThenPmi) {
  ::setenv("PMI_SIZE", "8", 1);
  EXPECT_EQ(mpi_launch_size(), 8);
  ::setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  EXPECT_EQ(mpi_launch_size(), 3);
}

TEST_F(LaunchEnvironment, IgnoresSizesThatAreNotPositiveWholeNumbers) {
  for (const char* bad : {"", "0", "-2", "3x", "many"}) {
    ::setenv("OMPI_COMM_WORLD_SIZE", bad, 1);
    EXPECT_EQ(mpi_launch_size(), 1) << bad;
  }
}

namespace fs = std::filesystem;
using testing::ScratchDir;

const char* kTwoRuns = R"(name: two
problems:
  instances: [{nqueens: [5, 6]}]
  solvers: [bnb]
)";

TEST(RecordedState, ReadsTheFolderOnceWhenEveryRecordedRunShows) {
  ScratchDir dir("recorded-there");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTwoRuns));
  const std::vector<SuiteRun> runs = expand_runs(suite);
  fs::create_directories(dir.path("out/runs"));
  run_and_record(suite, runs[1], dir.path("out"));
  const SuiteState state = read_recorded_state(suite, dir.path("out"), {1}, 0);
  EXPECT_FALSE(state.finished[0]);
  EXPECT_TRUE(state.finished[1]);
  EXPECT_EQ(state.pending, std::vector<std::size_t>{0});
}

TEST(RecordedState, WaitsForARecordedRunThatShowsLate) {
  ScratchDir dir("recorded-late");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTwoRuns));
  const std::vector<SuiteRun> runs = expand_runs(suite);
  // Run 0 recorded elsewhere, and renamed into the folder after a while, as another node's
  // file would appear to a node that cached its absence.
  fs::create_directories(dir.path("elsewhere/runs"));
  fs::create_directories(dir.path("out/runs"));
  run_and_record(suite, runs[0], dir.path("elsewhere"));
  const std::string name = "runs/" + runs[0].id + ".result";
  std::thread late([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    fs::rename(dir.path("elsewhere/" + name), dir.path("out/" + name));
  });
  const SuiteState state = read_recorded_state(suite, dir.path("out"), {0}, 30);
  late.join();
  EXPECT_TRUE(state.finished[0]);
  EXPECT_FALSE(state.finished[1]);
}

TEST(RecordedState, SaysHowManyRecordedRunsNeverShowed) {
  ScratchDir dir("recorded-missing");
  const Suite suite = read_suite_file(dir.write("suite.yaml", kTwoRuns));
  try {
    read_recorded_state(suite, dir.path("out"), {0, 1}, 1);
    FAIL() << "no error for runs that never showed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("2 run(s) reported as recorded do not show in " +
                                         dir.path("out") + "/runs after 1 s"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sightline::experiments
