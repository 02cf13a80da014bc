#include "sightline/experiments/runs/edit_run.h"

namespace sightline::experiments {

std::vector<TraceRow> edit_trace(const camera::Scene& scene, const camera::Edit& edit) {
  std::vector<TraceRow> rows;
  rows.reserve(edit.frames.size());
  for (std::size_t f = 0; f < edit.frames.size(); ++f) {
    const camera::EditedFrame& frame = edit.frames[f];
    TraceRow r;
    r.frame = static_cast<int>(f);
    r.t = frame.t;
    const camera::CharacterState who = scene.character_at(frame.t);
    r.character = who.position;
    r.character_yaw = who.yaw;
    r.camera = frame.pose.position;
    r.target = frame.pose.look_at;
    r.cut = frame.cut;
    r.cost = frame.cost;
    r.solve_us = 0;  // edited offline: the edit's time is reported as a whole
    r.cut_reason = frame.cut ? "edit" : "none";
    r.fov = frame.pose.fov;
    r.roll = frame.pose.roll;
    r.shot = edit.footage.candidates[frame.shot].name;
    rows.push_back(std::move(r));
  }
  return rows;
}

bool is_edit_scene(const camera::Scene& scene) {
  return !scene.shot() && !scene.has_character() &&
         (scene.script() != nullptr || !scene.named_shots().empty());
}

}  // namespace sightline::experiments
