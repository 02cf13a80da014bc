// The search's view of one composition problem (shot_search.h's steps 1 and 2): a point of
// the search (position, aim offsets from the direction to the targets' centre, fov, roll)
// and its assignment; where a candidate aims (Newton steps putting `screen_position`
// targets at their points); the view turned to take someone the shot keeps out off an edge;
// and where each person's properties ask the camera to stand (Vantage). Kept apart from the
// search itself (shot_search.cc), which only walks these points.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/domains/camera/composition/composition_problem.h"

namespace sightline::camera::shot_search_detail {

inline constexpr double kDegrees = 180.0 / 3.14159265358979323846;
inline constexpr double kRadians = 3.14159265358979323846 / 180.0;
inline constexpr int kDims = 7;  // x, y, z, yaw offset, pitch offset, fov, roll
using Point = std::array<double, kDims>;

// Where the properties of person `t` ask the camera to stand: (distance, bearings, elevations).
struct Vantage {
  double distance = 4;
  std::vector<double> bearings;    // degrees, world yaw of (camera - aim)
  std::vector<double> elevations;  // degrees
};

// What a Framing works in, kept between solves so that a tracking camera's frames allocate
// nothing once the vectors have grown.
struct FramingStorage {
  std::vector<int> targets;   // the people the shot wants in the image
  std::vector<int> excluded;  // people the shot keeps out who are not also wanted
  std::vector<std::size_t> placed;  // the shot's screen_position properties
  std::vector<std::size_t> framed;  // the shot's framed properties
  csp::Assignment values;
  // Per constraint of the problem: the shot property it is (nullptr for the others), whether
  // it reads the camera's position only, and its score at the last position scored.
  std::vector<const ShotPropertyConstraint*> properties;
  std::vector<char> position_only;
  std::vector<csp::Score> at_position;
  // Per constraint: whether it asks the scene (sight lines, clearance: query_cost() > 0),
  // and its term at the point being scored.
  std::vector<char> queries;
  std::vector<csp::Score> terms;
};

// The search's view of one problem: the targets' centre, and the point -> assignment map.
class Framing {
 public:
  // `storage` is kept between solves; one Framing per solve (a solve's problem may have
  // moved its people since the last).
  Framing(const csp::Problem& problem, const CompositionProblem& owner, FramingStorage& storage);
  const Eigen::Vector3d& centre() const { return centre_; }
  const std::vector<int>& targets() const { return storage_.targets; }
  // The shot's screen_position properties (their indices), in order.
  const std::vector<std::size_t>& placed() const { return storage_.placed; }

  // The assignment of a point: the aim offsets are relative to the direction to the centre.
  const csp::Assignment& values(const Point& x);
  // The problem's score of x's assignment, the same value as problem.score(values(x)) (the
  // same terms, added in the same order). Faster: the shot's properties share one view of
  // the pose instead of making one each, and the terms that read the camera's position
  // only (the `visible` properties' sight lines, clearance) are kept from the last point
  // scored when x has not moved, only turned or zoomed (most of a compass search's steps).
  csp::Score score(const Point& x);
  // score(x), with `complete` set, whenever it may be below `bound` (fewer hard, or as many
  // and less soft: the order the search sorts in); else possibly a score at least `bound`
  // that is no more than score(x) (the terms that ask the scene left out: the others
  // already cost as much), with `complete` cleared. The same decisions as comparing score(x) with `bound`,
  // without the sight lines and clearance of most rejected points (a compass search's
  // steps, the candidates that cannot enter the best few). Terms that cannot be negative
  // added in the same order with some left out sum to no more (rounding is monotone).
  csp::Score score_below(const Point& x, const csp::Score& bound, bool& complete);

  // How far x's view is from the next count of each framed property that is partly met
  // (scoring above 0 and below 1): the screen distance (units) the samples it lacks must
  // still travel, the nearest first (into its rect when it wants more of the person in,
  // out of it when it wants fewer), weighted as the property. A count is flat between
  // its steps, so a search comparing scores alone cannot tell which way the next sample
  // is (26 of 27 framed from every pose round the best it found): this says, for poses
  // that score the same. 0 when no framed property is partly met; +inf for an invalid view.
  double framed_gap(const Point& x);
  bool counts_framed() const { return !storage_.framed.empty(); }

  // How far (screen units, > 0) the view at x must turn to take the people the shot keeps
  // out who are on screen there off each edge of the image (0 left, 1 right, 2 bottom,
  // 3 top), their bodies' corners `beyond` screen units past it: a group's shot with someone
  // standing among them may do best giving up a wanted person on that side. False when no
  // one kept out is on screen, or when a corner of theirs is behind the camera.
  bool shifts_away(const Point& x, double beyond, std::array<double, 4>& shift);

  // x's aim turned by `shift` screen units toward `side` (see shifts_away). Screen units to
  // degrees, roughly: one unit is the angle the image spans on that axis. A larger yaw turns
  // the view left (points move right); a larger pitch looks up (points move down). With a
  // roll the axes turn too: the candidate is only a guess, and the problem's score decides
  // whether it is kept.
  void turn(Point& x, int side, double shift) const;

  // Aim offsets that put the screen_position targets at their points (a few Newton steps
  // on their mean screen error), from (0, 0): the centre at the image's centre.
  void aim(Point& x);

  // The screen point of the target of `property` (a screen_position property) seen from x;
  // false when it is behind the camera.
  bool screen_point(const Point& x, std::size_t property, Eigen::Vector2d& out);
  // x's aim offsets moved (a few Newton steps) so that the target of `property` is at
  // `wanted` on screen again: a move of the camera that keeps one person where they are in
  // the image. False when it cannot (behind the camera, a singular step).
  bool hold_on_screen(Point& x, std::size_t property, const Eigen::Vector2d& wanted);

 private:
  // Mean of (screen point - wanted point) over the screen_position properties.
  bool error(const Point& x, Eigen::Vector2d& out);
  // Up to `steps` Newton steps on x's aim offsets driving `residual` (a screen-space error,
  // bool residual(const Point&, Eigen::Vector2d&), false when it has none) to 0, with a
  // finite-difference Jacobian of step `h`, each step at most `largest` degrees per offset.
  // True when done (below `tolerance`, or all steps taken), false when a residual or the
  // Jacobian failed.
  template <class Residual>
  bool newton_on_aim(Point& x, int steps, double h, double tolerance, double largest,
                     Residual residual);

  const csp::Problem* problem_;
  const CompositionProblem* owner_;
  Eigen::Vector3d centre_;
  FramingStorage& storage_;
  // Where storage_.at_position was scored (valid once has_position_ is set).
  Eigen::Vector3d scored_position_ = Eigen::Vector3d::Zero();
  bool has_position_ = false;
};

// Where person t's own properties (distance, size, angles) ask the camera to stand, with
// the lens at `fov` degrees.
void vantage_into(const CompositionProblem& owner, int t, double fov, Vantage& v);
// The unit direction at world yaw `bearing` and `elevation` (degrees).
Eigen::Vector3d from_bearing(double bearing, double elevation);

}  // namespace sightline::camera::shot_search_detail
