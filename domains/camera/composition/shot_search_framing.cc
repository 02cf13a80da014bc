#include "sightline/domains/camera/composition/shot_search_framing.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace sightline::camera::shot_search_detail {

namespace {

double mid(const ValueRange& r, double fallback) {
  if (std::isfinite(r.lo) && std::isfinite(r.hi)) return (r.lo + r.hi) / 2;
  if (std::isfinite(r.lo)) return r.lo > 0 ? r.lo * 1.25 : r.lo + fallback;
  if (std::isfinite(r.hi)) return r.hi * 0.8;
  return fallback;
}

}  // namespace

Framing::Framing(const csp::Problem& problem, const CompositionProblem& owner,
                 FramingStorage& storage)
    : problem_(&problem),
      owner_(&owner),
      storage_(storage) {
  const auto& people = owner.world().people();
  storage_.targets = owner.wanted();
  storage_.excluded.clear();
  for (const std::vector<int>& ts : owner.targets()) {
    for (int t : ts) {
      if (std::find(storage_.targets.begin(), storage_.targets.end(), t) == storage_.targets.end() &&
          std::find(storage_.excluded.begin(), storage_.excluded.end(), t) == storage_.excluded.end()) {
        storage_.excluded.push_back(t);
      }
    }
  }
  storage_.placed.clear();
  storage_.framed.clear();
  const Shot& shot = owner.shot();
  for (std::size_t i = 0; i < shot.properties.size(); ++i) {
    if (shot.properties[i].kind == "screen_position") storage_.placed.push_back(i);
    if (shot.properties[i].kind == "framed") storage_.framed.push_back(i);
  }
  centre_.setZero();
  for (int t : storage_.targets) centre_ += people[static_cast<std::size_t>(t)].aim;
  centre_ /= static_cast<double>(std::max<std::size_t>(1, storage_.targets.size()));
  storage_.values.resize(kDims);
  const std::size_t n = problem.num_constraints();
  storage_.properties.assign(n, nullptr);
  storage_.position_only.assign(n, 0);
  storage_.at_position.assign(n, csp::Score{});
  storage_.queries.assign(n, 0);
  storage_.terms.assign(n, csp::Score{});
  for (csp::ConstraintId id = 0; id < n; ++id) {
    const csp::Constraint& c = problem.constraint(id);
    const auto* property = dynamic_cast<const ShotPropertyConstraint*>(&c);
    storage_.properties[id] = property;
    const auto scope = c.scope();
    const bool on_position = std::all_of(scope.begin(), scope.end(),
                                         [](csp::VariableId v) { return v < 3; });
    storage_.position_only[id] = property ? property->position_only() : on_position;
    storage_.queries[id] = c.query_cost() > 0;
  }
}

csp::Score Framing::score(const Point& x) {
  // Nothing is below an infinite bound's reach: every term asked.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  bool complete = true;
  return score_below(x, csp::Score{kInf, kInf}, complete);
}

csp::Score Framing::score_below(const Point& x, const csp::Score& bound, bool& complete) {
  complete = true;
  const csp::Assignment& v = values(x);
  const std::optional<View> view = View::of(owner_->pose(v));
  // An invalid view scores every property 0 (their violation() without a view): nothing to
  // share, and nothing kept (a position's terms are kept only as scored with a valid view).
  if (!view) return problem_->score(v);
  const bool same_position = has_position_ && view->position() == scored_position_;
  auto term_of = [&](csp::ConstraintId id) {
    if (const ShotPropertyConstraint* property = storage_.properties[id]) {
      return property->score_of(1 - property->score(*view));  // its violation, view shared
    }
    return problem_->constraint_score(id, v);
  };
  // First the terms that ask nothing of the scene, or are kept from the last position.
  const std::size_t n = storage_.properties.size();
  csp::Score partial;
  bool left_out = false;
  for (csp::ConstraintId id = 0; id < n; ++id) {
    if (storage_.position_only[id] && same_position) {
      storage_.terms[id] = storage_.at_position[id];
    } else if (storage_.queries[id]) {
      left_out = true;
      continue;
    } else {
      storage_.terms[id] = term_of(id);
    }
    partial += storage_.terms[id];
  }
  if (left_out && !partial.before(bound)) {
    complete = false;
    return partial;
  }
  // Then the rest, and the sum in the problem's order (score()'s value to the bit).
  csp::Score total;
  for (csp::ConstraintId id = 0; id < n; ++id) {
    if (storage_.queries[id] && !(storage_.position_only[id] && same_position)) {
      storage_.terms[id] = term_of(id);
    }
    if (storage_.position_only[id]) storage_.at_position[id] = storage_.terms[id];
    total += storage_.terms[id];
  }
  scored_position_ = view->position();
  has_position_ = true;
  return total;
}

double Framing::framed_gap(const Point& x) {
  if (storage_.framed.empty()) return 0;
  const std::optional<View> view = View::of(owner_->pose(values(x)));
  if (!view) return std::numeric_limits<double>::infinity();
  // A sample not in front is farther from any rect than one on screen can be.
  constexpr double kNotInFront = 10;
  const Shot& shot = owner_->shot();
  double gap = 0;
  for (std::size_t i : storage_.framed) {
    const ShotProperty& p = shot.properties[i];
    const PersonAtTime& person = owner_->world().people()[static_cast<std::size_t>(owner_->targets()[i][0])];
    std::array<double, kPersonSamples> outside{}, inside{};  // distance out, depth in
    std::size_t n_out = 0, n_in = 0;
    for (const Eigen::Vector3d& q : person_samples(person.body)) {
      const std::optional<Eigen::Vector2d> s = view->project(q);
      if (!s) {
        outside[n_out++] = kNotInFront;
        continue;
      }
      const double dx = std::max(p.rect[0] - s->x(), s->x() - p.rect[2]);
      const double dy = std::max(p.rect[1] - s->y(), s->y() - p.rect[3]);
      if (dx <= 0 && dy <= 0) {
        inside[n_in++] = -std::max(dx, dy);
      } else {
        outside[n_out++] = std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
      }
    }
    const double fraction = static_cast<double>(n_in) / kPersonSamples;
    const double s = satisfaction(fraction, p.range, p.softness, false);
    if (!(s > 0 && s < 1)) continue;
    // The samples to move: as many as take the count to the range's nearer end (a count
    // within [0, 27], whatever the range says).
    const bool wants_more = fraction < p.range.lo;
    const double end = wants_more ? std::ceil(p.range.lo * kPersonSamples - 1e-9)
                                  : std::floor(p.range.hi * kPersonSamples + 1e-9);
    const auto wanted = static_cast<long>(std::clamp(end, 0.0, static_cast<double>(kPersonSamples)));
    const auto in = static_cast<long>(n_in);
    double* distances = wants_more ? outside.data() : inside.data();
    const std::size_t count = wants_more ? n_out : n_in;
    const std::size_t need =
        std::min(count, static_cast<std::size_t>(std::max(0L, wants_more ? wanted - in : in - wanted)));
    std::partial_sort(distances, distances + need, distances + count);
    double sum = 0;
    for (std::size_t k = 0; k < need; ++k) sum += distances[k];
    gap += (p.hard ? 1.0 : p.weight) * sum;
  }
  return gap;
}

const csp::Assignment& Framing::values(const Point& x) {
  const Eigen::Vector3d d = centre_ - Eigen::Vector3d(x[0], x[1], x[2]);
  const double yaw = std::atan2(d.x(), d.z()) * kDegrees;
  const double pitch = std::atan2(d.y(), std::hypot(d.x(), d.z())) * kDegrees;
  storage_.values[0] = x[0];
  storage_.values[1] = x[1];
  storage_.values[2] = x[2];
  storage_.values[3] = signed_degrees(yaw + x[3]);
  storage_.values[4] = std::clamp(pitch + x[4], -89.0, 89.0);
  storage_.values[5] = x[5];
  storage_.values[6] = x[6];
  return storage_.values;
}

bool Framing::shifts_away(const Point& x, double beyond, std::array<double, 4>& shift) {
  const std::optional<View> view = View::of(owner_->pose(values(x)));
  if (!view) return false;
  const auto& people = owner_->world().people();
  shift.fill(0);
  bool any = false;
  for (int e : storage_.excluded) {
    const PersonAtTime& person = people[static_cast<std::size_t>(e)];
    const std::optional<Eigen::Vector2d> s = view->project(person.aim);
    if (!s || s->minCoeff() <= 0 || s->maxCoeff() >= 1) continue;
    any = true;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d corner((c & 1) ? person.body.max.x() : person.body.min.x(),
                                   (c & 2) ? person.body.max.y() : person.body.min.y(),
                                   (c & 4) ? person.body.max.z() : person.body.min.z());
      const std::optional<Eigen::Vector2d> q = view->project(corner);
      if (!q) return false;
      for (int side = 0; side < 4; ++side) {
        const double at = (*q)[side / 2];
        shift[static_cast<std::size_t>(side)] = std::max(
            shift[static_cast<std::size_t>(side)], side % 2 == 0 ? at + beyond : 1 + beyond - at);
      }
    }
  }
  return any;
}

void Framing::turn(Point& x, int side, double shift) const {
  const int axis = side / 2;
  const double tan_half = std::tan(x[5] * kRadians / 2) * (axis == 0 ? owner_->shot().aspect : 1.0);
  const double degrees = 2 * std::atan(tan_half) * kDegrees * shift;
  if (axis == 0) {
    x[3] += side == 0 ? -degrees : degrees;
  } else {
    x[4] += side == 2 ? degrees : -degrees;
  }
}

template <class Residual>
bool Framing::newton_on_aim(Point& x, int steps, double h, double tolerance, double largest,
                            Residual residual) {
  for (int step = 0; step < steps; ++step) {
    Eigen::Vector2d r0;
    if (!residual(x, r0)) return false;
    if (r0.norm() < tolerance) return true;
    Eigen::Matrix2d j;
    for (int k = 0; k < 2; ++k) {
      Point y = x;
      y[static_cast<std::size_t>(3 + k)] += h;
      Eigen::Vector2d r1;
      if (!residual(y, r1)) return false;
      j.col(k) = (r1 - r0) / h;
    }
    if (std::abs(j.determinant()) < 1e-12) return false;
    const Eigen::Vector2d delta = j.inverse() * r0;
    x[3] -= std::clamp(delta.x(), -largest, largest);
    x[4] -= std::clamp(delta.y(), -largest, largest);
  }
  return true;
}

void Framing::aim(Point& x) {
  x[3] = x[4] = 0;
  if (storage_.placed.empty()) return;
  newton_on_aim(x, 6, 0.25, 1e-4, 30.0,
                [this](const Point& y, Eigen::Vector2d& out) { return error(y, out); });
}

bool Framing::screen_point(const Point& x, std::size_t property, Eigen::Vector2d& out) {
  const std::optional<View> view = View::of(owner_->pose(values(x)));
  if (!view) return false;
  const int target = owner_->targets()[property][0];
  const auto& person = owner_->world().people()[static_cast<std::size_t>(target)];
  const std::optional<Eigen::Vector2d> s = view->project(person.aim);
  if (!s) return false;
  out = *s;
  return true;
}

bool Framing::hold_on_screen(Point& x, std::size_t property, const Eigen::Vector2d& wanted) {
  return newton_on_aim(x, 3, 0.01, 1e-6, 5.0, [&](const Point& y, Eigen::Vector2d& out) {
    if (!screen_point(y, property, out)) return false;
    out -= wanted;
    return true;
  });
}

bool Framing::error(const Point& x, Eigen::Vector2d& out) {
  const std::optional<View> view = View::of(owner_->pose(values(x)));
  if (!view) return false;
  out.setZero();
  int n = 0;
  const Shot& shot = owner_->shot();
  for (std::size_t i : storage_.placed) {
    const ShotProperty& p = shot.properties[i];
    const auto& person = owner_->world().people()[static_cast<std::size_t>(owner_->targets()[i][0])];
    const std::optional<Eigen::Vector2d> s = view->project(person.aim);
    if (!s) return false;
    out += *s - p.at;
    ++n;
  }
  out /= std::max(1, n);
  return true;
}

void vantage_into(const CompositionProblem& owner, int t, double fov, Vantage& v) {
  const Shot& shot = owner.shot();
  const PersonAtTime& person = owner.world().people()[static_cast<std::size_t>(t)];
  v.distance = 4;
  v.bearings.clear();
  v.elevations.clear();
  const double tan_half = std::tan(fov * kRadians / 2);
  for (std::size_t i = 0; i < shot.properties.size(); ++i) {
    const ShotProperty& p = shot.properties[i];
    if (owner.targets()[i].size() != 1 || owner.targets()[i][0] != t) continue;
    if (p.kind == "distance") {
      v.distance = mid(p.range, 4);
    } else if (p.kind == "size") {
      const Eigen::Vector3d size = person.body.size();
      const double wanted = mid(p.range, 0.3);
      if (!(wanted > 0)) continue;
      double extent = size.y(), image = 2 * tan_half;  // height: image height at depth 1
      if (p.measure == "width") {
        extent = std::max(size.x(), size.z());
        image = 2 * tan_half * shot.aspect;
      } else if (p.measure == "area") {
        extent = std::sqrt(size.y() * std::max(size.x(), size.z()));
        image = 2 * tan_half * std::sqrt(shot.aspect);
      }
      const double fraction = p.measure == "area" ? std::sqrt(wanted) : wanted;
      v.distance = extent / (image * fraction);
    } else if (p.kind == "angle_horizontal") {
      v.bearings.push_back(person.yaw + arc_middle(p.range));
    } else if (p.kind == "angle_vertical") {
      // Its middle, and near both ends when they are finite (a group often fits at one end).
      const double m = mid(p.range, 10);
      v.elevations.push_back(m);
      if (std::isfinite(p.range.lo) && std::isfinite(p.range.hi) && p.range.hi > p.range.lo) {
        const double span = p.range.hi - p.range.lo;
        v.elevations.push_back(std::clamp(p.range.lo + 0.1 * span, -85.0, 85.0));
        v.elevations.push_back(std::clamp(p.range.hi - 0.1 * span, -85.0, 85.0));
      }
    }
  }
}

Eigen::Vector3d from_bearing(double bearing, double elevation) {
  return {std::cos(elevation * kRadians) * std::sin(bearing * kRadians),
          std::sin(elevation * kRadians),
          std::cos(elevation * kRadians) * std::cos(bearing * kRadians)};
}

}  // namespace sightline::camera::shot_search_detail
