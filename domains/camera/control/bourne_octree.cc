#include "sightline/domains/camera/control/bourne_octree.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sightline/domains/camera/control/octree_search.h"

namespace sightline::camera {

const solvers::OptionSchema<BourneOctreeSolver::Options>& BourneOctreeSolver::Options::schema() {
  static const auto* schema = [] {
    auto* s = new solvers::OptionSchema<Options>;
    s->integer("passes", &Options::passes, "octree passes", 1, 64)
        .real("initial_size", &Options::initial_size,
              "half-size of the first cube in metres (0 = the problem's search box)", 0, 1e6)
        .real("scale", &Options::scale, "cube shrink factor per pass, in (0, 1)", 0.01, 0.99);
    return s;
  }();
  return *schema;
}

std::string BourneOctreeSolver::unsuitable_reason(const csp::Problem& problem) const {
  std::string why;
  return CameraProblemView::find(problem, &why) ? "" : why;
}

void BourneOctreeSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                    const solvers::SolveContext& context,
                                    solvers::SolverResult& result) {
  solvers::Budget budget(context.limits, 1);
  const CameraProblemView& view = views_.get(problem, name_);
  OctreeSearch search(problem, view);
  const Eigen::Vector3d p0 = search.clamp(Eigen::Vector3d(start[0], start[1], start[2]));

  const double half = search.first_half_size(options_.initial_size);
  // "calculate camera facing and right vectors": facing = horizontal camera -> look-at.
  const Eigen::Vector3d look = view.look_at(problem);
  Eigen::Vector3d facing(look.x() - p0.x(), 0, look.z() - p0.z());
  if (facing.norm() < 1e-9) facing = Eigen::Vector3d::UnitZ();
  facing.normalize();
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d right = facing.cross(up).normalized();
  // The four rays, character -> sides, top and bottom of the initial search cube.
  const SceneAtTime& scene = view.scene();
  const bool top_blocked = !scene.line_of_sight(look, p0 + half * up);
  int blocked = top_blocked ? 1 : 0;
  const Eigen::Vector3d others[3] = {p0 + half * right, p0 - half * right, p0 - half * up};
  for (const Eigen::Vector3d& side : others) {
    if (!scene.line_of_sight(look, side)) ++blocked;
  }
  if (top_blocked) {
    search.set_height_override(view.height().term().desired + half);
  }
  OctreeSettings settings;
  settings.passes = static_cast<int>(options_.passes);
  settings.initial_half_size = half;
  settings.scale = options_.scale;
  settings.require_visible = false;
  const Candidate best = search.run(p0, settings);

  result.best.assign({p0.x(), p0.y(), p0.z()});
  if (best.valid) result.best.assign({best.position.x(), best.position.y(), best.position.z()});
  result.message.clear();
  if (blocked > 0) {
    result.message = std::to_string(blocked) + " of 4 rays blocked" +
                     (top_blocked ? "; top blocked: desired height raised" : "");
  }
  result.evaluations = search.evaluations() + 4;
  result.iterations = static_cast<std::uint64_t>(settings.passes);
  result.solutions_at_best = 0;
  result.stop = solvers::StopReason::kCompleted;
  solvers::finish_result(problem, context, budget, result);
}

}  // namespace sightline::camera
