// SceneAtTime: the scene's geometry at one moment: the static boxes and level, plus every
// mover placed where its keyframes put it at that time.
//
// Scene is shared, read-only, by every run of a suite (one per thread), so it cannot hold a
// "current time". Each run (each camera, each baseline, each horizon sample of the
// anticipating camera) owns a SceneAtTime, calls set_time() once per frame and asks its
// queries, which have Scene's meaning and answer for boxes, triangles and movers together.
// This is the one geometry interface of the camera: nothing that judges where the camera
// may go asks Scene's static-only queries.
//
// Movers are few (people, doors, vehicles) next to the static geometry, so they sit in a
// flat array beside the static index, tested after one reject against their common bounds,
// rather than in a BVH refit every frame: measured in docs/BENCHMARKS.md ("Movers"). Movers
// spread over a whole city make those common bounds useless, so set_time() also sorts them
// along the bounds' longest axis into groups of kGroupSize with their own bounds (one level
// of hierarchy, rebuilt per set_time in O(n log n) without allocating), and every query
// skips the groups it cannot touch.
// With NearbyBoxes (set_nearby), set_time() also lists the movers touching their region, and
// a sight line or clearance ball inside it tests only those, and the static boxes from the
// short list: the same answers, far fewer tests.
// set_time() and the queries do not allocate; the constructor sizes everything once.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "sightline/domains/camera/geometry/aabb.h"
#include "sightline/domains/camera/nearby_boxes.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

class SceneAtTime {
 public:
  // At the scene's first frame. `scene` must outlive this object.
  explicit SceneAtTime(const Scene& scene);

  const Scene& scene() const { return *scene_; }
  // Places every mover at time t (seconds). O(movers) for times that advance frame by frame.
  void set_time(double t);
  // Places every mover where its velocity at `now` carries it `ahead` seconds later (a
  // constant-velocity forecast from what a game knows at `now`, not its future keyframes);
  // time() becomes now + ahead. The anticipating camera's `lookahead: motion` uses this.
  void set_time_extrapolated(double now, double ahead);
  double time() const { return time_; }
  // The movers' boxes at time(), in the order of scene().movers().
  const std::vector<Aabb>& mover_boxes() const { return boxes_; }
  bool has_movers() const { return !boxes_.empty(); }

  // The static boxes near the camera (nearby_boxes.h), for sight lines inside their region;
  // null (the default) = always the scene's BoxTree. Must outlive this object; the answers
  // are the same either way.
  // Ignored in a scene without static boxes (a level: its triangles have their own index),
  // where the list could only cost a test per query.
  void set_nearby(const NearbyBoxes* nearby) {
    nearby_ = scene_->solids().empty() || world_ ? nullptr : nearby;
    find_near_movers();
  }

  // --- Scene's queries, with the movers at time() (see scene.h for their meaning) ---
  bool line_of_sight(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    if (world_) return world_line_of_sight(a, b) && !mover_blocks(a, b);
    return !boxes_block(a, b) && !scene_->triangle_index().segment_blocked(a, b) &&
           !mover_blocks(a, b);
  }
  // Sight lines from one point `a` to each of `ends` (at most TriangleIndex::kMaxFan): bit i
  // of the result is set when line_of_sight(a, ends[i]) holds. The level's triangles answer
  // all of them at once, as ray packets (triangle_index.h); boxes and movers line by line.
  std::uint32_t lines_of_sight(const Eigen::Vector3d& a,
                               std::span<const Eigen::Vector3d> ends) const;
  // The part of it that does not depend on time: bit i set when a static box or a level
  // triangle blocks a -> ends[i]. The same for every SceneAtTime of a scene, so the K
  // predicted samples of one candidate ask it once (and mover_blocks of each sample).
  std::uint32_t static_blocked(const Eigen::Vector3d& a,
                               std::span<const Eigen::Vector3d> ends) const;
  // True when the scene has a level's triangles, whose sight lines are cheaper asked together
  // (lines_of_sight) than one by one; box scenes gain nothing from it and lose the early stop
  // of a count.
  bool packs_sight_lines() const { return !scene_->triangle_index().empty(); }

  // A mover hit has source kMover and the mover's index.
  std::optional<SurfaceHit> first_hit(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  double clearance(const Eigen::Vector3d& p,
                   double limit = std::numeric_limits<double>::infinity()) const;
  // clearance(p, limit) < r, for 0 < r <= limit: is p inside clearance r of something?
  // On a level it asks only as far as the answer needs: the level's triangles within r
  // first, the map's solid volume only when none is (clearance() asks it first, for the
  // sign of its value, and then the depth inside solid matter).
  bool closer_than(const Eigen::Vector3d& p, double r, double limit) const;
  std::optional<NearestSurface> nearest_surface(
      const Eigen::Vector3d& p, double limit = std::numeric_limits<double>::infinity()) const;
  bool open_at(const Eigen::Vector3d& p) const;

  // True when the segment touches a mover's box at time().
  bool mover_blocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

 private:
  static constexpr std::size_t kGroupSize = 4;
  // Whether a static box blocks a -> b: the nearby list when it covers the segment (the
  // same answer), else the scene's BoxTree.
  bool boxes_block(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return nearby_ && nearby_->covers(a, b) ? nearby_->segment_blocked(a, b)
                                            : scene_->solid_tree().segment_blocked(a, b);
  }
  // The scene's world (Scene::world()) at time_: its answers, with NearestSurface's meaning
  // (first_hit asks Scene::surface_hit).
  bool world_line_of_sight(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  std::optional<NearestSurface> world_nearest_surface(const Eigen::Vector3d& p,
                                                      double limit) const;
  // Sorts the movers into groups and computes bounds_ and the groups' bounds.
  void regroup();
  // The movers touching the nearby boxes' region at time_ (near_movers_, near_region_).
  void find_near_movers();
  // min(d, every mover's signed distance to p, limit), through the movers' groups.
  double grouped_mover_clearance(const Eigen::Vector3d& p, double d, double limit) const;

  const Scene* scene_;
  const NearbyBoxes* nearby_ = nullptr;
  const sightline::World* world_ = nullptr;  // scene_->world()
  double time_ = 0;
  std::vector<Aabb> boxes_;
  std::vector<std::size_t> segments_;  // each mover's keyframe segment at time_
  Aabb bounds_ = Aabb::empty();        // of boxes_
  std::vector<std::uint32_t> order_;   // mover indices, grouped
  std::vector<Aabb> group_bounds_;     // of order_[g * kGroupSize ...]
  // The movers touching near_region_ (the nearby boxes' region when set_time ran): a
  // segment or ball inside it can only meet those (empty region = none known).
  Aabb near_region_ = Aabb::empty();
  std::vector<std::uint32_t> near_movers_;
};

}  // namespace sightline::camera
