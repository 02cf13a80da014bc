#include "sightline/domains/camera/constraints/frame_parameters.h"

#include <iterator>

namespace sightline::camera {

FrameParameters FrameParameters::add_to(csp::Parameters& table) {
  auto add = [&](const char* name, double value) {
    return csp::ParameterRef(&table, table.add(name, value));
  };
  FrameParameters p;
  p.first = table.size();
  p.char_x = add("char_x", 0);
  p.char_y = add("char_y", 0);
  p.char_z = add("char_z", 0);
  p.char_yaw = add("char_yaw", 0);
  p.char_vx = add("char_vx", 0);
  p.char_vy = add("char_vy", 0);
  p.char_vz = add("char_vz", 0);
  p.look_x = add("look_x", 0);
  p.look_y = add("look_y", 0);
  p.look_z = add("look_z", 0);
  p.last_cam_x = add("last_cam_x", 0);
  p.last_cam_y = add("last_cam_y", 0);
  p.last_cam_z = add("last_cam_z", 0);
  p.dt = add("dt", 1.0 / 60.0);
  p.t = add("t", 0);
  p.desired_height = add("desired_height", 0);
  p.desired_distance = add("desired_distance", 0);
  p.desired_orientation = add("desired_orientation", 0);
  p.clearance_radius = add("clearance_radius", 0.2);
  return p;
}

void FrameParameters::write(csp::Parameters& table, const FrameValues& v) const {
  // The same order as add_to.
  const double values[] = {v.feet.x(),          v.feet.y(),           v.feet.z(),
                           v.yaw,               v.velocity.x(),       v.velocity.y(),
                           v.velocity.z(),      v.look_at.x(),        v.look_at.y(),
                           v.look_at.z(),       v.last_camera.x(),    v.last_camera.y(),
                           v.last_camera.z(),   v.dt,                 v.t,
                           v.desired_height,    v.desired_distance,   v.desired_orientation,
                           v.clearance_radius};
  for (std::size_t i = 0; i < std::size(values); ++i) table.set(first + i, values[i]);
}

}  // namespace sightline::camera
