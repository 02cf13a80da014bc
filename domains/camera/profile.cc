#include "sightline/domains/camera/profile.h"

#include <cmath>

namespace sightline::camera {

const char* to_string(AreaKind kind) {
  return kind == AreaKind::kEnclosed ? "enclosed" : "semi-enclosed";
}

std::optional<AreaKind> area_kind_from_string(const std::string& text) {
  if (text == "enclosed") return AreaKind::kEnclosed;
  if (text == "semi-enclosed") return AreaKind::kSemiEnclosed;
  return std::nullopt;
}

const char* to_string(Lookahead lookahead) {
  switch (lookahead) {
    case Lookahead::kNone: return "none";
    case Lookahead::kMotion: return "motion";
    case Lookahead::kPath: return "path";
  }
  return "none";
}

std::optional<Lookahead> lookahead_from_string(const std::string& text) {
  if (text == "none") return Lookahead::kNone;
  if (text == "motion") return Lookahead::kMotion;
  if (text == "path") return Lookahead::kPath;
  return std::nullopt;
}

namespace {

std::string check_adaptation(const AreaAdaptation& a, const std::string& where) {
  if (a.ceiling_margin && (!std::isfinite(*a.ceiling_margin) || *a.ceiling_margin < 0)) {
    return where + ".ceiling_margin must be a finite number >= 0";
  }
  if (a.distance_fraction &&
      (!std::isfinite(*a.distance_fraction) || *a.distance_fraction <= 0 ||
       *a.distance_fraction > 1)) {
    return where + ".distance_fraction must be in (0, 1]";
  }
  return "";
}

bool finite_non_negative(double x) { return std::isfinite(x) && x >= 0; }

}  // namespace

std::string CameraProfile::validate() const {
  if (!std::isfinite(height.desired)) return "height.desired must be a finite number";
  if (!finite_non_negative(distance.desired)) return "distance.desired must be >= 0";
  if (!std::isfinite(orientation.desired) || orientation.desired < 0 ||
      orientation.desired > 180) {
    return "orientation.desired must be in [0, 180] degrees";
  }
  if (!finite_non_negative(height.weight)) return "height.weight must be >= 0";
  if (!finite_non_negative(distance.weight)) return "distance.weight must be >= 0";
  if (!finite_non_negative(orientation.weight)) return "orientation.weight must be >= 0";
  if (!finite_non_negative(frame_coherence_weight)) return "frame_coherence.weight must be >= 0";
  if (!finite_non_negative(visible_fraction_weight)) {
    return "occlusion.visible_fraction_weight must be >= 0";
  }
  if (!finite_non_negative(look_at_weight)) return "occlusion.look_at_weight must be >= 0";
  if (!finite_non_negative(clearance_radius)) return "clearance.radius must be >= 0";
  if (!finite_non_negative(clearance_weight)) return "clearance.weight must be >= 0";
  if (!std::isfinite(search_half_size) || search_half_size <= 0) {
    return "search.half_size must be > 0";
  }
  if (auto e = check_adaptation(enclosed, "areas.enclosed"); !e.empty()) return e;
  if (auto e = check_adaptation(semi_enclosed, "areas.semi-enclosed"); !e.empty()) return e;
  auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  if (!positive(sensing.ceiling_probe)) return "sensing.ceiling_probe must be > 0";
  if (!positive(sensing.behind_probe)) return "sensing.behind_probe must be > 0";
  if (!finite_non_negative(sensing.wall_margin)) return "sensing.wall_margin must be >= 0";
  if (!finite_non_negative(sensing.min_distance)) return "sensing.min_distance must be >= 0";
  if (!finite_non_negative(sensing.smoothing)) return "sensing.smoothing must be >= 0";
  const Anticipation& a = anticipation;
  if (!std::isfinite(a.horizon) || a.horizon <= 0 || a.horizon > 5) {
    return "anticipation.horizon must be in (0, 5] seconds";
  }
  if (a.samples < 1 || a.samples > Anticipation::kMaxSamples) {
    return "anticipation.samples must be 1 to " + std::to_string(Anticipation::kMaxSamples);
  }
  if (!finite_non_negative(a.weight)) return "anticipation.weight must be >= 0";
  if (!positive(a.decay)) return "anticipation.decay must be > 0 seconds";
  if (!std::isfinite(a.plan_seconds) || a.plan_seconds < 0 || a.plan_seconds > 5) {
    return "anticipation.plan_seconds must be in [0, 5] seconds";
  }
  if (!std::isfinite(a.max_jerk) || a.max_jerk < 0 || a.max_jerk > 1e5) {
    return "anticipation.max_jerk must be in [0, 100000] m/s^3";
  }
  if (cuts.stuck_per_minute < 0 || cuts.stuck_per_minute > 16) {
    return "cuts.stuck_per_minute must be in [0, 16] (0: no limit)";
  }
  if (cuts.cut_ahead &&
      (!cuts.smooth_escape || a.lookahead == Lookahead::kNone || a.plan_seconds <= 0)) {
    return "cuts.cut_ahead needs cuts.smooth_escape: true, anticipation.lookahead motion or "
           "path and anticipation.plan_seconds > 0";
  }
  return "";
}

Eigen::Vector3d ideal_camera_position(const CharacterState& character, double height,
                                      double distance, double orientation_degrees) {
  // The camera -> character direction makes the desired angle with the facing, so the camera
  // sits at feet - distance x facing(yaw + angle), raised by the desired height.
  const Eigen::Vector3d direction = facing_from_yaw(character.yaw + orientation_degrees);
  return character.position - distance * direction + Eigen::Vector3d(0, height, 0);
}

}  // namespace sightline::camera
