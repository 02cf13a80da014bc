// Continuity: the rules of continuity editing an editor keeps at a cut, as geometry, and
// what the script says at a time (FORMATS.md "Script and named shots").
//
// - The line of action at t: the ground-plane line through the speaker's and the
//   addressee's aim points, for the line of dialogue under way at t (the latest begun, when
//   two overlap), or, between lines, the last one that ended; none before the first line.
// - Crossing the line: the cameras before and after a cut stand on opposite sides of the
//   line of action at the cut (the 180-degree rule).
// - A jump cut: the view direction turns by less than 30 degrees and the subject's size on
//   screen changes by less than a size step (a factor of 1.5): the audience sees the same
//   picture jump.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "sightline/domains/camera/composition/camera_pose.h"
#include "sightline/domains/camera/composition/shot.h"

namespace sightline::camera {

struct ContinuityRules {
  double jump_angle_degrees = 30;  // a cut turning less than this ...
  double size_step = 1.5;          // ... and changing size by less than this factor is a jump cut
  double line_margin = 0.05;       // metres: a camera this near the line is on neither side
};

// The line of dialogue under way at t (the latest begun), else nullopt. Actions are not lines.
std::optional<std::size_t> line_under_way(const std::vector<ScriptEntry>& script, double t);
// The entry defining the line of action at t: the line under way, else the last line that
// ended at or before t; nullopt before the first line (or without lines).
std::optional<std::size_t> line_of_action_entry(const std::vector<ScriptEntry>& script, double t);

// Signed distance (metres) of `point` from the ground-plane line a-b (the x-z plane), with
// the sign of ((b - a) x (point - a)).y: one side of the line is > 0, the other < 0. 0 when
// a and b coincide on the ground.
double side_of_line(const Eigen::Vector3d& point, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// True when `before` and `after` stand on opposite sides of the line a-b, each farther than
// the margin from it.
bool crosses_line(const Eigen::Vector3d& before, const Eigen::Vector3d& after,
                  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const ContinuityRules& rules);

// The angle between two poses' view directions, degrees in [0, 180].
double view_turn_degrees(const CameraPose& before, const CameraPose& after);

// True when a cut from `before` to `after`, whose subjects fill `size_before` and
// `size_after` of the image height (> 0), is a jump cut.
bool is_jump_cut(const CameraPose& before, double size_before, const CameraPose& after,
                 double size_after, const ContinuityRules& rules);

}  // namespace sightline::camera
