// `sightline view` end to end, run through the shell as a user would: a trace written here
// by hand in the FORMATS.md columns (not by the program) becomes a replay page whose hidden
// frames are the independent check's (a known answer: a wall between camera and character in
// the last two frames), and every kind of bad input is a message naming the file and line
// and exit status 2, never a crash.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "run_sightline.h"

namespace {

namespace fs = std::filesystem;

using sightline::test::contains;
using sightline::test::Outcome;
using sightline::test::run;

const char* const kHeader =
    "frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,target_x,target_y,target_z,cut,"
    "cost,solve_us\n";

// Five frames (4 per second, t = 0 .. 1) of the character walking from x = 0 to x = 1 with a
// wall at z 1 .. 1.2 on its +z side. The camera films from -z for three frames (visible),
// then cuts to +z, behind the wall (the look-at point hidden in frames 3 and 4).
const char* const kRows =
    "0,0,0,0,0,0,0,2,-3,0,1.5,0,0,0.1,20\n"
    "1,0.25,0.25,0,0,22.5,0.25,2,-3,0.25,1.5,0,0,0.1,21\n"
    "2,0.5,0.5,0,0,45,0.5,2,-3,0.5,1.5,0,0,0.1,19\n"
    "3,0.75,0.75,0,0,67.5,0.75,2,3,0.75,1.5,0,1,0.9,30\n"
    "4,1,1,0,0,90,1,2,3,1,1.5,0,0,0.9,22\n";

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// Standard base64 (the page's typed arrays), for reading the hidden flags back.
std::vector<unsigned char> from_base64(const std::string& text) {
  const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> out;
  unsigned bits = 0;
  int count = 0;
  for (const char c : text) {
    const std::size_t v = alphabet.find(c);
    if (v == std::string::npos) continue;  // padding
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>((bits >> count) & 0xff));
    }
  }
  return out;
}

class ViewCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("sightline_view_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "other");
    std::ofstream(dir_ / "wall-walk.yaml") << "name: wall-walk\n"
                                              "frame_rate: 4\n"
                                              "boxes:\n"
                                              "  - {name: wall, min: [-2, 0, 1], max: [2, 3, 1.2]}\n"
                                              "trajectory:\n"
                                              "  - {t: 0, position: [0, 0, 0], yaw: 0}\n"
                                              "  - {t: 1, position: [1, 0, 0], yaw: 90}\n";
    write("walk.csv", std::string(kHeader) + kRows);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  // `sightline view` of the scene with these traces, to out.html.
  Outcome view(const std::vector<std::string>& traces) const {
    std::string arguments = "view " + path("wall-walk.yaml");
    for (const std::string& t : traces) arguments += " --trace " + path(t);
    return run(arguments + " --out " + path("out.html"));
  }
  // The trace with one row's text replaced.
  static std::string with_row(int frame, const std::string& row) {
    std::istringstream in(kRows);
    std::string line, text = kHeader;
    for (int i = 0; std::getline(in, line); ++i) text += (i == frame ? row : line) + "\n";
    return text;
  }

  fs::path dir_;
};

TEST_F(ViewCommand, WritesAReplayOfAHandWrittenTraceWithTheIndependentChecksHiddenFrames) {
  const Outcome o = view({"walk.csv"});
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_TRUE(contains(o.output, "walk: " + path("walk.csv") + ", 5 frames, look-at point "
                                   "hidden in 2 (independent check), 1 cut"))
      << o.output;
  const std::string html = read(dir_ / "out.html");
  EXPECT_TRUE(contains(html, "class='replay' data-scene='wall-walk'")) << html.substr(0, 400);
  EXPECT_TRUE(contains(html, "\"id\":\"walk\"")) << "run id from the file name";
  // One self-contained page: nothing fetched from elsewhere.
  EXPECT_FALSE(std::regex_search(html, std::regex("(src|href)=['\"]?(https?:)?//")));
  // The per-frame flags (replay.js: 1 cut, 2 hidden) are the known answer.
  std::smatch flags;
  ASSERT_TRUE(std::regex_search(html, flags, std::regex("\"flags\":\"([A-Za-z0-9+/=]*)\"")));
  EXPECT_EQ(from_base64(flags[1].str()), (std::vector<unsigned char>{0, 0, 0, 3, 2}));
}

TEST_F(ViewCommand, TwoTracesOfTheSameNameGetTwoRunIds) {
  fs::copy_file(dir_ / "walk.csv", dir_ / "other" / "walk.csv");
  const Outcome o = view({"walk.csv", "other/walk.csv"});
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_TRUE(contains(o.output, "  walk: ")) << o.output;
  EXPECT_TRUE(contains(o.output, "  walk-2: ")) << o.output;
  const std::string html = read(dir_ / "out.html");
  EXPECT_TRUE(contains(html, "\"id\":\"walk\"") && contains(html, "\"id\":\"walk-2\""));
}

TEST_F(ViewCommand, MalformedTracesNameTheFileLineAndColumn) {
  // The header without solve_us.
  std::string header = kHeader;
  header.erase(header.find(",solve_us"), 9);
  write("short.csv", header + kRows);
  Outcome o = view({"short.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("short.csv") + ":1: missing column 'solve_us' (column 15)"))
      << o.output;
  // A misspelt column.
  header = kHeader;
  header.replace(header.find("cam_y"), 5, "cam_h");
  write("misspelt.csv", header + kRows);
  o = view({"misspelt.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("misspelt.csv") + ":1:")) << o.output;
  EXPECT_TRUE(contains(o.output, "column 8 is 'cam_h', expected 'cam_y'")) << o.output;
  // A cell that is not a number, on the file's fourth line.
  write("word.csv", with_row(2, "2,0.5,0.5,0,0,45,0.5,two,-3,0.5,1.5,0,0,0.1,19"));
  o = view({"word.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("word.csv") + ":4:")) << o.output;
  EXPECT_TRUE(contains(o.output, "column 'cam_y': expected a number, got 'two'")) << o.output;
  // A row cut short.
  write("cut.csv", with_row(1, "1,0.25,0.25,0,0,22.5,0.25,2,-3"));
  o = view({"cut.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("cut.csv") + ":3: expected 15 cells as in the header, "
                                                   "got 9: missing 'target_x' (column 10)"))
      << o.output;
  EXPECT_FALSE(fs::exists(dir_ / "out.html"));
}

TEST_F(ViewCommand, ATraceOfAnotherSceneSaysWhichFrameIsOffAndByHowMuch) {
  // The character half a metre off the scene's path in frame 2 (line 4).
  write("moved.csv", with_row(2, "2,0.5,0.5,0,0.5,45,0.5,2,-3,0.5,1.5,0,0,0.1,19"));
  Outcome o = view({"walk.csv", "moved.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("moved.csv") + ":4: frame 2 (row 3) at t = 0.5000 s has "
                                                     "the character at (0.500, 0.000, 0.500), "
                                                     "0.500 m from where scene 'wall-walk' puts "
                                                     "it (0.500, 0.000, 0.000)"))
      << o.output;
  // A time after the scene's last keyframe.
  write("late.csv", with_row(4, "4,1.5,1,0,0,90,1,2,3,1,1.5,0,0,0.9,22"));
  o = view({"late.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("late.csv") + ":6: frame 4 (row 5) is at t = 1.5000 s, "
                                                    "0.5000 s outside scene 'wall-walk''s span "
                                                    "[0.0000, 1.0000] s"))
      << o.output;
  // Times that go backwards.
  write("back.csv", with_row(2, "2,0.2,0.2,0,0,18,0.5,2,-3,0.5,1.5,0,0,0.1,19"));
  o = view({"back.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("back.csv") + ":4: frame 2 (row 3) is at t = 0.2000 s, "
                                                    "not after the frame before it"))
      << o.output;
  EXPECT_FALSE(fs::exists(dir_ / "out.html"));
}

TEST_F(ViewCommand, ATraceWithAnotherFrameCountSaysWhereItParts) {
  // The same walk at 2 frames per second: on the path, but at other times.
  write("slow.csv", std::string(kHeader) +
                        "0,0,0,0,0,0,0,2,-3,0,1.5,0,0,0.1,20\n"
                        "1,0.5,0.5,0,0,45,0.5,2,-3,0.5,1.5,0,0,0.1,19\n"
                        "2,1,1,0,0,90,1,2,3,1,1.5,0,0,0.9,22\n");
  Outcome o = view({"slow.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("slow.csv") + ":3: the trace has 3 frames, scene "
                                                    "'wall-walk' has 5 (t in [0.0000, 1.0000] s "
                                                    "at 4.000 frames per second); frame 1 (row "
                                                    "2) is at t = 0.5000 s, the scene's frame 1 "
                                                    "at t = 0.2500 s (0.2500 s apart)"))
      << o.output;
  // Cut short after three frames.
  std::istringstream rows(kRows);
  std::string text = kHeader, line;
  for (int i = 0; i < 3 && std::getline(rows, line); ++i) text += line + "\n";
  write("short.csv", text);
  o = view({"short.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("short.csv") + ":4: the trace has 3 frames, scene "
                                                     "'wall-walk' has 5"))
      << o.output;
  EXPECT_TRUE(contains(o.output, "the trace stops at t = 0.5000 s, 2 frames (0.5000 s) before "
                                 "the scene ends"))
      << o.output;
}

TEST_F(ViewCommand, NoTraceOrNoSceneIsAMessageAndStatusTwo) {
  Outcome o = run("view " + path("wall-walk.yaml") + " --out " + path("out.html"));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, "--trace")) << o.output;
  o = run("view " + path("absent.yaml") + " --trace " + path("walk.csv") + " --out " +
          path("out.html"));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, "absent.yaml")) << o.output;
  write("broken.yaml", "name: broken\ntrajectory: [1, 2\n");
  o = run("view " + path("broken.yaml") + " --trace " + path("walk.csv") + " --out " +
          path("out.html"));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, "broken.yaml")) << o.output;
  o = view({"absent.csv"});
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, path("absent.csv") + ": cannot open trace file")) << o.output;
  EXPECT_FALSE(fs::exists(dir_ / "out.html"));
}

}  // namespace
