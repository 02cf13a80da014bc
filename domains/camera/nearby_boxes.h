// NearbyBoxes: the scene's static boxes near the camera, in a short flat list, so the
// frame's many sight lines (the look-at point, 9 body samples and K predicted points per
// scored candidate, the escape moves) skip the walk down the whole BoxTree.
//
// Every sight line a camera frame asks starts in the search box and ends at the character or
// at a predicted look-at point, so all of them lie in one small region. cover(needed) gathers
// once (one BoxTree query) every static box that touches that region grown by kMargin; later
// frames whose region still fits reuse the list (static boxes never move), so it is rebuilt
// about once per kMargin metres the camera travels. A segment whose two ends lie in region()
// lies in it entirely (a box is convex), so any box it touches is in the list: the answer is
// exactly BoxTree::segment_blocked's, computed by the same exact slab test on the same boxes.
// Each box is first rejected against the segment's bounding box, with the box padded by
// kPad x (1 + |coordinate|) so that no rounding of the exact test can ever find a hit the
// reject skipped. Segments with an end outside region() go to the tree as before. Likewise
// the clearance of a point whose ball of the clearance radius lies in region().
//
// Capacity is fixed (kCapacity boxes, reserved once): cover() never allocates. When more
// boxes touch the region it retries without the margin, and past that covers nothing, so
// every query uses the tree. Time-independent: one list serves the frame's geometry and
// every predicted sample's (SceneAtTime::set_nearby). Queries are const and thread-safe.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "sightline/domains/camera/geometry/aabb.h"
#include "sightline/domains/camera/scene.h"

namespace sightline::camera {

class NearbyBoxes {
 public:
  static constexpr std::size_t kCapacity = 64;
  // Metres added around a region when the list is rebuilt.
  static constexpr double kMargin = 2.0;
  // Relative padding of the reject test (BoxTree pads its nodes the same way).
  static constexpr double kPad = 1e-6;

  // `scene` must outlive this. Covers nothing until cover().
  explicit NearbyBoxes(const Scene& scene);

  // Makes region() contain `needed` (a no-op when it already does).
  void cover(const Aabb& needed);
  // Where segments are answered from the list (empty when nothing is covered).
  const Aabb& region() const { return region_; }
  std::size_t size() const { return boxes_.size(); }
  // True when both ends are in region().
  bool covers(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return region_.contains(a) && region_.contains(b);
  }
  // scene.solid_tree().segment_blocked(a, b), for a segment covers() accepts.
  bool segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    return !boxes_.empty() && list_blocks(a, b);
  }
  // True when the ball of radius `limit` (finite, >= 0) around p lies in region().
  bool covers_ball(const Eigen::Vector3d& p, double limit) const {
    const Eigen::Vector3d r(limit, limit, limit);
    return region_.contains(p - r) && region_.contains(p + r);
  }
  // The boxes' part of Scene::clearance(p, limit): the smallest signed distance from p to a
  // box, or `limit` when none is nearer, for a ball covers_ball() accepts (any box nearer
  // than `limit` meets the ball, so it is in the list).
  double clearance(const Eigen::Vector3d& p, double limit) const;

 private:
  struct Entry {
    Aabb box;     // exact, as in the scene
    Aabb padded;  // for the reject test
  };
  bool list_blocks(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
  // Gathers the boxes touching `region` grown by `margin`; false if more than kCapacity.
  bool gather(const Aabb& region);

  const Scene* scene_;
  Aabb region_ = Aabb::empty();
  std::vector<Entry> boxes_;
};

}  // namespace sightline::camera
