// MpiEngine's launch detection (experiments/mpi_engine.h): the program decides between the
// thread pool and the MPI engine from the variables an MPI launcher sets, before MPI starts.
// The engine itself is tested end to end under mpirun (tests/apps/mpi_run_test.cc).
#include "experiments/mpi_engine.h"

#include <gtest/gtest.h>

#include <cstdlib>

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

TEST_F(LaunchEnvironment, AProcessNotStartedByALauncherIsAlone) {
  EXPECT_EQ(mpi_launch_size(), 1);
}

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

}  // namespace
}  // namespace sightline::experiments
