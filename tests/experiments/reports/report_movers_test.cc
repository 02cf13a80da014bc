// The report's movers (experiments/reports/report_movers.h): which times a view marks, and that a
// marked mover is drawn where its keyframes put it then, and only when near the character.
#include "sightline/experiments/reports/report_movers.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sightline::experiments {
namespace {

// The character walks 10 m along +z in 10 s; one mover crosses her path along +x at z = 5.
camera::Scene crossing_scene() {
  camera::Scene scene("crossing", {}, {}, camera::CharacterShape{},
                      camera::Trajectory({{0, {0, 0, 0}, 0}, {10, {0, 0, 10}, 0}}), 60);
  scene.set_movers({camera::Mover("walker", {1, 2, 1}, {{0, {-5, 0, 5}}, {10, {5, 0, 5}}})});
  return scene;
}

// One row a second; the look-at point hidden at rows 3-4 and 8, a cut at row 6.
std::vector<TraceRow> trace_with_events() {
  std::vector<TraceRow> trace;
  for (int i = 0; i <= 10; ++i) {
    TraceRow row;
    row.frame = i;
    row.t = i;
    row.character = {0, 0, static_cast<double>(i)};
    row.camera = {0, 2.5, i - 4.0};
    row.target = row.character + Eigen::Vector3d(0, 1.5, 0);
    row.cut = i == 6;
    trace.push_back(row);
  }
  return trace;
}

// Top view in metres: x right, z down, no scaling, so pixel text is world coordinates.
Eigen::Vector2d top(const Eigen::Vector3d& p) { return {p.x(), p.z()}; }

TEST(MoverMarkTimes, AreTheOnsetsOfOcclusionsAndTheCuts) {
  const std::vector<TraceRow> trace = trace_with_events();
  RunDrawing run;
  run.trace = &trace;
  run.occluded = {0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0};
  EXPECT_EQ(mover_mark_times(run), (std::vector<double>{3, 6, 8}));
  EXPECT_EQ(mover_mark_times(run, 2).size(), 2u);
}

TEST(MoverMarkTimes, AreThreeEvenlySpacedTimesWhenNothingHappens) {
  std::vector<TraceRow> trace = trace_with_events();
  trace[6].cut = false;
  RunDrawing run;
  run.trace = &trace;
  run.occluded.assign(trace.size(), 0);
  const std::vector<double> times = mover_mark_times(run);
  ASSERT_EQ(times.size(), 3u);
  EXPECT_LT(times[0], times[1]);
  EXPECT_LT(times[1], times[2]);
  EXPECT_TRUE(mover_mark_times(RunDrawing{}).empty());
}

TEST(MoversSvg, DrawsTheMoverWhereItWasAtEachMarkedTime) {
  const camera::Scene scene = crossing_scene();
  const std::vector<TraceRow> trace = trace_with_events();
  RunDrawing run;
  run.trace = &trace;
  run.occluded = {0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0};
  const std::string svg = movers_svg(scene, run, top);
  // At 3 s the walker's box spans x -2.5..-1.5, z 4.5..5.5; at 6 s x 0.5..1.5; at 8 s x 2.5..3.5.
  for (const char* corner : {"-2.5,4.5", "-1.5,5.5", "0.5,4.5", "1.5,5.5", "2.5,4.5", "3.5,5.5"}) {
    EXPECT_NE(svg.find(corner), std::string::npos) << corner;
  }
  for (const char* label : {">3.0 s<", ">6.0 s<", ">8.0 s<"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  // Not at a time nobody marked: at 1 s its box spanned x -4.5..-3.5.
  EXPECT_EQ(svg.find("-4.5,4.5"), std::string::npos);
}

TEST(MoversSvg, LeavesOutMarkedMoversFarFromTheCharacterButKeepsTheirPath) {
  const camera::Scene scene = crossing_scene();
  const std::vector<TraceRow> trace = trace_with_events();
  RunDrawing run;
  run.trace = &trace;
  run.occluded = {0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0};
  const std::string svg = movers_svg(scene, run, top, /*near=*/0.5);
  EXPECT_EQ(svg.find(" s<"), std::string::npos);  // no time labels: every mark was too far
  // The swept area still spans the whole walk, -5.5..5.5 in x.
  EXPECT_NE(svg.find("-5.5,4.5"), std::string::npos);
  EXPECT_NE(svg.find("5.5,5.5"), std::string::npos);
}

TEST(MoversSvg, IsEmptyWithoutMovers) {
  camera::Scene scene = crossing_scene();
  scene.set_movers({});
  const std::vector<TraceRow> trace = trace_with_events();
  RunDrawing run;
  run.trace = &trace;
  EXPECT_EQ(movers_svg(scene, run, top), "");
}

}  // namespace
}  // namespace sightline::experiments
