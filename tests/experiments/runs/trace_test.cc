// The trace reader (trace.h) on traces written by hand, as another tool would write them:
// what FORMATS.md allows is read, and every malformed input is an InputError naming the
// file, the line and the column at fault.
#include "sightline/experiments/runs/trace.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sightline/csp/input_error.h"

namespace sightline::experiments {
namespace {

namespace fs = std::filesystem;

const std::string kHeader =
    "frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,target_x,target_y,target_z,cut,"
    "cost,solve_us";

class TraceReader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sightline_trace_reader_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& text) {
    const std::string path = (dir_ / ("t" + std::to_string(count_++) + ".csv")).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  // The message of the InputError reading `text` throws, or "" when it reads.
  std::string error(const std::string& text) {
    try {
      read_trace_csv(write(text));
    } catch (const csp::InputError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
  int count_ = 0;
};

TEST_F(TraceReader, ReadsThePublicColumnsWithForeignExtraColumnsQuotesBlanksAndCrLf) {
  const std::string path =
      write("\"frame\",\"t\",\"char_x\",\"char_y\",\"char_z\",\"char_yaw\",\"cam_x\",\"cam_y\","
            "\"cam_z\",\"target_x\",\"target_y\",\"target_z\",\"cut\",\"cost\",\"solve_us\","
            "\"note\",\"desired_distance\"\r\n"
            "0,0.0,1,0,2,90,1,2.5,-2,1,1.5,2,0,0.25,12.5,start,4\r\n"
            " 1 , 0.5 ,1,0,2.5,90,1.5,2.5,-1.5,1,1.5,2.5,1,0.5,13,a cut here,3.5\r\n"
            "\r\n");
  const std::vector<TraceRow> rows = read_trace_csv(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].frame, 1);
  EXPECT_DOUBLE_EQ(rows[1].t, 0.5);
  EXPECT_DOUBLE_EQ(rows[1].character.z(), 2.5);
  EXPECT_DOUBLE_EQ(rows[1].camera.x(), 1.5);
  EXPECT_DOUBLE_EQ(rows[1].target.y(), 1.5);
  EXPECT_TRUE(rows[1].cut);
  EXPECT_FALSE(rows[0].cut);
  EXPECT_DOUBLE_EQ(rows[0].solve_us, 12.5);
  // This project's extra column is read by name; an absent one keeps its default.
  EXPECT_DOUBLE_EQ(rows[1].desired_distance, 3.5);
  EXPECT_TRUE(rows[1].controller_visible);
  EXPECT_EQ(rows[0].line, 2);
  EXPECT_EQ(rows[1].line, 3);
}

TEST_F(TraceReader, AHeaderWithoutAPublicColumnNamesTheMissingOne) {
  // solve_us left out.
  const std::string short_header = kHeader.substr(0, kHeader.rfind(','));
  std::string e = error(short_header + "\n0,0,0,0,0,0,0,2,-3,0,1.5,0,0,0\n");
  EXPECT_NE(e.find(":1: missing column 'solve_us' (column 15)"), std::string::npos) << e;
  // char_y left out: column 4 is then char_z.
  std::string header = kHeader;
  header.erase(header.find("char_y,"), 7);
  e = error(header + "\n");
  EXPECT_NE(e.find(":1:"), std::string::npos) << e;
  EXPECT_NE(e.find("column 4 is 'char_z', expected 'char_y'"), std::string::npos) << e;
  e = error("");
  EXPECT_NE(e.find("empty file"), std::string::npos) << e;
  e = error("time,x,y,z\n0,1,2,3\n");
  EXPECT_NE(e.find("column 1 is 'time', expected 'frame'"), std::string::npos) << e;
}

TEST_F(TraceReader, BadCellsNameTheLineAndColumn) {
  const std::string good = "0,0,0,0,0,0,0,2,-3,0,1.5,0,0,0,10\n";
  std::string e = error(kHeader + "\n" + good + "1,0.1,0,0,0,0,abc,2,-3,0,1.5,0,0,0,10\n");
  EXPECT_NE(e.find(":3:15: column 'cam_x': expected a number, got 'abc'"), std::string::npos)
      << e;
  e = error(kHeader + "\n" + good + "1,0.1,0,0,0,0,nan,2,-3,0,1.5,0,0,0,10\n");
  EXPECT_NE(e.find(":3:15: column 'cam_x': expected a finite number"), std::string::npos) << e;
  e = error(kHeader + "\n" + good + "1,0.1,0,0,0,0,0,2,-3,0,1.5,0,0,,10\n");
  EXPECT_NE(e.find(":3:"), std::string::npos) << e;
  EXPECT_NE(e.find("column 'cost': expected a number, got ''"), std::string::npos) << e;
  e = error(kHeader + "\n" + good + "1.5,0.1,0,0,0,0,0,2,-3,0,1.5,0,0,0,10\n");
  EXPECT_NE(e.find(":3:1: column 'frame': expected a whole number"), std::string::npos) << e;
  // Too few cells: the first missing one is named; too many: rejected, not guessed.
  e = error(kHeader + "\n" + good + "1,0.1,0,0,0,0,0,2,-3,0,1.5,0\n");
  EXPECT_NE(e.find(":3: expected 15 cells as in the header, got 12: missing 'cut' (column 13)"),
            std::string::npos)
      << e;
  e = error(kHeader + "\n" + good + "1,0.1,0,0,0,0,0,2,-3,0,1.5,0,0,0,10,7\n");
  EXPECT_NE(e.find(":3:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 15 cells as in the header, got 16"), std::string::npos) << e;
  // A foreign extra column may hold text; this project's extras must be numbers.
  EXPECT_EQ(error(kHeader + ",comment\n0,0,0,0,0,0,0,2,-3,0,1.5,0,0,0,10,fine\n"), "");
  e = error(kHeader + ",visible\n0,0,0,0,0,0,0,2,-3,0,1.5,0,0,0,10,yes\n");
  EXPECT_NE(e.find(":2:"), std::string::npos) << e;
  EXPECT_NE(e.find("column 'visible': expected a number, got 'yes'"), std::string::npos) << e;
}

TEST_F(TraceReader, AMissingFileIsAnInputError) {
  EXPECT_THROW(read_trace_csv((dir_ / "absent.csv").string()), csp::InputError);
}

}  // namespace
}  // namespace sightline::experiments
