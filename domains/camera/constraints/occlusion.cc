#include "sightline/domains/camera/constraints/occlusion.h"

#include <algorithm>
#include <bit>

namespace sightline::camera {

std::array<Eigen::Vector3d, kBodySamples> body_sample_points(const Aabb& body) {
  const Eigen::Vector3d c = body.centre();
  const Eigen::Vector3d h = 0.4 * body.size();  // corners pulled 20% of the way to the centre
  std::array<Eigen::Vector3d, kBodySamples> points;
  points[0] = c;
  int k = 1;
  for (int sx = -1; sx <= 1; sx += 2) {
    for (int sy = -1; sy <= 1; sy += 2) {
      for (int sz = -1; sz <= 1; sz += 2) {
        points[k++] = c + Eigen::Vector3d(sx * h.x(), sy * h.y(), sz * h.z());
      }
    }
  }
  return points;
}

double LookAtVisibleConstraint::violation(std::span<const double> values) const {
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  const Eigen::Vector3d look(frame_.look_x.value(), frame_.look_y.value(), frame_.look_z.value());
  return scene_->line_of_sight(camera, look) ? 0.0 : 1.0;
}

double LookAtVisibleConstraint::violation_and_gradient(std::span<const double> values,
                                                       std::span<double> gradient) const {
  std::fill(gradient.begin(), gradient.end(), 0.0);
  return violation(values);
}

namespace {

// 1 - visible / kBodySamples with the samples' sight lines asked as one fan (a level's ray
// packets): the same value as 1 - visible_fraction.
double hidden_fraction_packed(const SceneAtTime& scene, const Eigen::Vector3d& camera,
                              const Aabb& body) {
  const std::array<Eigen::Vector3d, kBodySamples> points = body_sample_points(body);
  const int visible = std::popcount(scene.lines_of_sight(camera, points));
  return 1.0 - static_cast<double>(visible) / kBodySamples;
}

}  // namespace

double BodyVisibilityConstraint::violation(std::span<const double> values) const {
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  const Eigen::Vector3d feet(frame_.char_x.value(), frame_.char_y.value(), frame_.char_z.value());
  const Aabb body = scene_->scene().character().body_at(feet);
  if (scene_->packs_sight_lines()) return hidden_fraction_packed(*scene_, camera, body);
  return 1.0 - visible_fraction(*scene_, camera, body);
}

double BodyVisibilityConstraint::violation_until(std::span<const double> values,
                                                 double cost_before, double bound,
                                                 double cost_after) const {
  const Eigen::Vector3d camera(values[scope()[0]], values[scope()[1]], values[scope()[2]]);
  const Eigen::Vector3d feet(frame_.char_x.value(), frame_.char_y.value(), frame_.char_z.value());
  // On a level the sight lines cost less in a packet than the rays the count below could
  // skip save: the 8 corners as one packet, then the centre alone unless the corners already
  // lost (the same lower bound as below, with the centre counted visible).
  if (scene_->packs_sight_lines()) {
    const std::array<Eigen::Vector3d, kBodySamples> points =
        body_sample_points(scene_->scene().character().body_at(feet));
    const int corners_visible = std::popcount(scene_->lines_of_sight(
        camera, std::span<const Eigen::Vector3d>(points.data() + 1, kBodySamples - 1)));
    const int hidden = kBodySamples - 1 - corners_visible;
    if (hidden > 0) {
      const double at_least = 1.0 - static_cast<double>(kBodySamples - hidden) / kBodySamples;
      if ((cost_before + weight() * at_least) + cost_after >= bound) return at_least;
    }
    const int visible = corners_visible + (scene_->line_of_sight(camera, points[0]) ? 1 : 0);
    return 1.0 - static_cast<double>(visible) / kBodySamples;
  }
  // violation() is 1 - visible / kBodySamples; with the samples not yet tested counted as
  // visible, the same expression is a lower bound of it (rounding is monotone).
  int hidden = 0;
  for (const Eigen::Vector3d& p : body_sample_points(scene_->scene().character().body_at(feet))) {
    if (scene_->line_of_sight(camera, p)) continue;
    ++hidden;
    const double at_least = 1.0 - static_cast<double>(kBodySamples - hidden) / kBodySamples;
    if ((cost_before + weight() * at_least) + cost_after >= bound) return at_least;
  }
  return 1.0 - static_cast<double>(kBodySamples - hidden) / kBodySamples;
}

double BodyVisibilityConstraint::violation_and_gradient(std::span<const double> values,
                                                        std::span<double> gradient) const {
  std::fill(gradient.begin(), gradient.end(), 0.0);
  return violation(values);
}

}  // namespace sightline::camera
