// Edited films: the judge of continuity editing (edit_metrics.h) on a film made by hand (a
// cut across the line, a jump cut, a shot too short), and every shipped conversation
// (experiments/scenes/conversations/) edited by the chain solver: the film keeps the rules
// by the judge's count, its trace reads back with its shots, every frame at a slot replays
// through the composition checker with the satisfaction the editor scored, and the greedy
// editor's edit never costs less in the same model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/editing/editor.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/edit_metrics.h"
#include "sightline/experiments/runs/edit_run.h"
#include "sightline/experiments/sources/conversation_generator.h"
#include "tests/shipped_files.h"

namespace sightline::experiments {
namespace {

TraceRow row_at(double t, Eigen::Vector3d camera, Eigen::Vector3d target, bool cut) {
  TraceRow r;
  r.t = t;
  r.camera = camera;
  r.target = target;
  r.cut = cut;
  r.fov = 50;
  return r;
}

TEST(EditMetrics, JudgesAFilmMadeByHand) {
  const camera::Scene scene = camera::parse_scene(csp::parse_yaml(R"(name: judge
actors:
  - name: ann
    trajectory:
      - {t: 0, position: [-1, 0, 0], yaw: 90}
      - {t: 3, position: [-1, 0, 0], yaw: 90}
  - name: bob
    trajectory:
      - {t: 0, position: [1, 0, 0], yaw: 270}
      - {t: 3, position: [1, 0, 0], yaw: 270}
script:
  - {t: [0, 3], speaker: ann, to: bob}
)", "judge_two.yaml"));
  const Eigen::Vector3d ann(-1, 1.5, 0);
  const Eigen::Vector3d a(1.5, 1.6, 2.5), b(1.5, 1.6, -2.5);  // either side of the line
  const double r = 115 * M_PI / 180, d = std::hypot(2.5, 2.5);
  const Eigen::Vector3d c = ann + Eigen::Vector3d(d * std::sin(r), 0.1, d * std::cos(r));  // 20 deg from b
  std::vector<TraceRow> trace;
  for (int f = 0; f <= 30; ++f) {
    const double t = f / 10.0;
    const Eigen::Vector3d& camera = t < 1 - 1e-9 ? a : t < 1.5 - 1e-9 ? b : c;
    trace.push_back(row_at(t, camera, ann, f == 10 || f == 15));
    trace.back().frame = f;
  }
  const EditMetrics m = edit_metrics(scene, trace, 1.0);
  EXPECT_EQ(m.cuts, 2);
  EXPECT_EQ(m.shots, 3);
  EXPECT_EQ(m.line_crossings, 1);  // a -> b
  EXPECT_EQ(m.jump_cuts, 1);       // b -> c: 20 degrees, the same size
  EXPECT_EQ(m.short_shots, 1);     // b: 0.5 s
  EXPECT_NEAR(m.shortest_shot_seconds, 0.5, 1e-9);
  EXPECT_NEAR(m.seconds, 3.1, 1e-9);
  EXPECT_NEAR(m.mean_shot_seconds, 3.1 / 3, 1e-9);
  EXPECT_NEAR(m.speaking_seconds, 3.0, 1e-9);
  EXPECT_DOUBLE_EQ(m.speaker_shown_percent, 100);
  EXPECT_DOUBLE_EQ(m.speaker_readable_percent, 100);
  // From behind ann (she faces +x): shown, but not from the front.
  for (TraceRow& row : trace) row.camera = Eigen::Vector3d(-4, 1.6, 0.5);
  const EditMetrics behind = edit_metrics(scene, trace, 1.0);
  EXPECT_DOUBLE_EQ(behind.speaker_shown_percent, 100);
  EXPECT_DOUBLE_EQ(behind.speaker_readable_percent, 0);
  // Looking away: not shown.
  for (TraceRow& row : trace) row.target = Eigen::Vector3d(-10, 1.6, 0.5);
  EXPECT_DOUBLE_EQ(edit_metrics(scene, trace, 1.0).speaker_shown_percent, 0);
}

TEST(EditedFilms, EveryShippedConversationKeepsTheRulesOfContinuityEditing) {
  const std::vector<std::string> scenes = shipped_yaml_files("experiments/scenes/conversations");
  ASSERT_GE(scenes.size(), 5u);
  for (const std::string& path : scenes) {
    const camera::Scene scene = camera::read_scene_file(path);
    ASSERT_TRUE(is_edit_scene(scene)) << path;
    camera::EditorOptions options;
    const camera::Edit edit = camera::edit_scene(scene, options);
    const std::vector<TraceRow> rows = edit_trace(scene, edit);
    const std::string out = (std::filesystem::temp_directory_path() / "edited.csv").string();
    write_trace_csv(out, rows);
    const std::vector<TraceRow> back = read_trace_csv(out);
    ASSERT_EQ(back.size(), rows.size());
    const EditMetrics m = edit_metrics(scene, back, options.weights.min_shot_seconds);
    std::printf("%-18s %d shots, %.1f cuts/min, mean shot %.2f s, shortest %.2f s; speaker shown "
                "%.1f%%, readable %.1f%%, action %.1f%%\n",
                scene.name().c_str(), m.shots, m.cuts_per_minute, m.mean_shot_seconds,
                m.shortest_shot_seconds, m.speaker_shown_percent, m.speaker_readable_percent,
                m.action_shown_percent);
    EXPECT_EQ(m.line_crossings, 0) << path;
    EXPECT_EQ(m.jump_cuts, 0) << path;
    EXPECT_EQ(m.short_shots, 0) << path;
    EXPECT_GE(m.speaker_shown_percent, 90) << path;
    EXPECT_GE(m.speaker_readable_percent, 70) << path;
    EXPECT_GE(m.action_shown_percent, 90) << path;
    EXPECT_LE(m.mean_shot_seconds, 10) << path;
    EXPECT_GE(m.shots, 2) << path;
    // Between cuts the camera moves smoothly: never faster than 8 m/s.
    for (std::size_t f = 1; f < back.size(); ++f) {
      if (back[f].cut) continue;
      EXPECT_LE((back[f].camera - back[f - 1].camera).norm() / (back[f].t - back[f - 1].t), 8.0)
          << path << " at " << back[f].t << " s";
    }

    // The trace's shots are the editor's, and a frame at a slot's time replays through the
    // composition checker (FORMATS.md's definitions) with the satisfaction the editor scored.
    const auto& candidates = edit.footage.candidates;
    int replayed = 0;
    for (std::size_t f = 0; f < back.size(); ++f) {
      const auto k = static_cast<std::size_t>(
          std::find_if(candidates.begin(), candidates.end(),
                       [&](const camera::CandidateShot& c) { return c.name == back[f].shot; }) -
          candidates.begin());
      ASSERT_LT(k, candidates.size()) << path << " frame " << f << ": " << back[f].shot;
      ASSERT_EQ(k, edit.frames[f].shot);
      const double slot = (back[f].t - edit.footage.start) / edit.footage.slot_seconds;
      const auto i = static_cast<std::size_t>(std::llround(slot));
      if (std::abs(slot - static_cast<double>(i)) > 1e-6 || i >= edit.footage.slot_times.size()) continue;
      if (i + 1 < edit.costs.slots && edit.costs.jumps[i + 1][k]) continue;  // held, not passed through
      const camera::CompositionProblem check(scene, *candidates[k].shot, back[f].t);
      camera::CameraPose pose;
      pose.position = back[f].camera;
      pose.look_at = back[f].target;
      pose.fov = back[f].fov;
      pose.roll = back[f].roll;
      pose.aspect = candidates[k].shot->aspect;
      EXPECT_NEAR(check.evaluate(pose).satisfaction, edit.footage.takes[i][k].satisfaction, 0.01)
          << path << " frame " << f << " (" << back[f].shot << ")";
      ++replayed;
    }
    EXPECT_GT(replayed, 10) << path;

    // The greedy editor's edit, in the same model, costs no less.
    camera::EditorOptions greedy = options;
    greedy.solver = camera::kGreedyEditor;
    const camera::Edit g = camera::edit_footage(scene, edit.footage, greedy);
    EXPECT_GE(g.score.soft, edit.score.soft - 1e-9) << path;
  }
}

// Conversations nobody tuned the editor for: the seeded generator's, every layout.
TEST(EditedFilms, GeneratedConversationsKeepTheRulesOfContinuityEditing) {
  for (std::uint64_t seed = 101; seed <= 108; ++seed) {
    ConversationOptions o;
    o.seed = seed;
    o.seconds = 30;
    o.layout = static_cast<int>(seed % 4);
    const camera::Scene scene = generate_conversation(o);
    ASSERT_TRUE(is_edit_scene(scene));
    camera::EditorOptions options;
    const camera::Edit edit = camera::edit_scene(scene, options);
    const EditMetrics m = edit_metrics(scene, edit_trace(scene, edit), options.weights.min_shot_seconds);
    std::printf("%-18s layout %d: %d shots, mean shot %.2f s; speaker shown %.1f%%, readable %.1f%%, "
                "action %.1f%%\n", scene.name().c_str(), o.layout, m.shots, m.mean_shot_seconds,
                m.speaker_shown_percent, m.speaker_readable_percent, m.action_shown_percent);
    EXPECT_EQ(m.line_crossings, 0) << scene.name();
    EXPECT_EQ(m.jump_cuts, 0) << scene.name();
    EXPECT_EQ(m.short_shots, 0) << scene.name();
    EXPECT_GE(m.speaker_shown_percent, 90) << scene.name();
    EXPECT_GE(m.speaker_readable_percent, 70) << scene.name();
    EXPECT_LE(m.mean_shot_seconds, 10) << scene.name();
  }
}

}  // namespace
}  // namespace sightline::experiments
