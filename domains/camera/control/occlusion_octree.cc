#include "sightline/domains/camera/control/occlusion_octree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sightline/domains/camera/control/octree_search.h"

namespace sightline::camera {

const solvers::OptionSchema<OcclusionOctreeSolver::Options>&
OcclusionOctreeSolver::Options::schema() {
  static const auto* schema = [] {
    auto* s = new solvers::OptionSchema<Options>;
    s->integer("passes", &Options::passes, "octree passes per orientation", 1, 64)
        .real("initial_size", &Options::initial_size,
              "half-size of the first cube in metres (0 = the problem's search box)", 0, 1e6)
        .real("scale", &Options::scale, "cube shrink factor per pass, in (0, 1)", 0.01, 0.99)
        .real("sweep_step", &Options::sweep_step, "orientation sweep step, degrees", 1, 180)
        .real("probe_distance", &Options::probe_distance,
              "front/back probe distance, metres (0 = no probes)", 0, 100)
        .boolean("include_start", &Options::include_start,
                 "also score the current camera position");
    return s;
  }();
  return *schema;
}

std::string OcclusionOctreeSolver::Options::validate() const { return ""; }

std::string OcclusionOctreeSolver::unsuitable_reason(const csp::Problem& problem) const {
  std::string why;
  return CameraProblemView::find(problem, &why) ? "" : why;
}

void OcclusionOctreeSolver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                       const solvers::SolveContext& context,
                                       solvers::SolverResult& result) {
  solvers::Budget budget(context.limits, 1);
  const CameraProblemView& view = views_.get(problem, name_);
  OctreeSearch search(problem, view);
  const Eigen::Vector3d p0(start[0], start[1], start[2]);
  OctreeSettings settings;
  settings.passes = static_cast<int>(options_.passes);
  settings.initial_half_size = options_.initial_size;
  settings.scale = options_.scale;
  settings.require_visible = true;

  const double base = view.orientation().term().desired_degrees;
  Candidate best;
  best.cost = std::numeric_limits<double>::infinity();
  std::uint64_t passes_run = 0;
  double used_orientation = base;
  result.stop = solvers::StopReason::kCompleted;
  // Orientation values in sweep order: base, base + s, base - s, base + 2s, ... within
  // [0, 180].
  for (int k = 0;; ++k) {
    const int step = (k + 1) / 2;
    const double sign = (k % 2 == 1) ? 1.0 : -1.0;
    const double desired = base + sign * step * options_.sweep_step;
    if (step * options_.sweep_step > 180 + 1e-9) break;
    if (k > 0 && (desired < -1e-9 || desired > 180 + 1e-9)) continue;
    search.set_orientation_override(k == 0 ? std::nullopt : std::optional<double>(desired));
    if (k == 0 && options_.include_start) {
      const Candidate here = search.evaluate(search.clamp(p0), true, best.cost);
      if (here.valid) best = here;
    }
    const Candidate found = search.run(p0, settings);
    passes_run += static_cast<std::uint64_t>(settings.passes);
    if (found.valid && found.cost < best.cost) best = found;
    if (best.valid) {
      used_orientation = k == 0 ? base : desired;
      break;
    }
    if (budget.exhausted(search.evaluations(), passes_run)) {
      result.stop = budget.reason();
      break;
    }
  }
  if (best.valid && options_.probe_distance > 0) {
    // Table 9: "if front or back points at unit distance away from the calculated best
    // solution has less cost then choose it". Front = toward the character.
    const Eigen::Vector3d character = view.character(problem);
    Eigen::Vector3d toward(character.x() - best.position.x(), 0,
                           character.z() - best.position.z());
    if (toward.norm() > 1e-9) {
      toward.normalize();
      for (double s : {1.0, -1.0}) {
        const Candidate probe = search.evaluate(
            search.clamp(best.position + s * options_.probe_distance * toward), true, best.cost);
        if (probe.valid && probe.cost < best.cost) best = probe;
      }
    }
  }
  // Alternatives, only when asked (see the header): the search again from each octant of
  // the first cube, under the orientation the main search settled on. The best stays the
  // cheapest of all, so asking never makes it worse.
  explored_.clear();
  const double first_half = search.first_half_size(options_.initial_size);
  if (context.alternatives_wanted > 0 && best.valid) {
    explored_.push_back(best);
    OctreeSettings octant = settings;
    octant.initial_half_size = 0.5 * first_half;
    const double q = 0.5 * first_half;
    for (int child = 0; child < 8; ++child) {
      if (budget.exhausted(search.evaluations(), passes_run)) {
        result.stop = budget.reason();
        break;
      }
      const Eigen::Vector3d offset((child & 1) ? q : -q, (child & 2) ? q : -q,
                                   (child & 4) ? q : -q);
      const Candidate found = search.run(p0 + offset, octant);
      passes_run += static_cast<std::uint64_t>(octant.passes);
      if (found.valid) explored_.push_back(found);
    }
    std::stable_sort(explored_.begin(), explored_.end(),
                     [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
    best = explored_.front();
  }
  result.best.assign({p0.x(), p0.y(), p0.z()});
  result.message.clear();
  if (best.valid) {
    result.best.assign({best.position.x(), best.position.y(), best.position.z()});
    if (used_orientation != base) {
      result.message = "orientation swept to " + std::to_string(static_cast<int>(used_orientation)) +
                       " deg";
    }
  } else {
    result.message = "no visible candidate in the search box";
  }
  // The alternatives: the next cheapest runs' bests, each in another region than the best
  // and than those already chosen.
  result.alternatives.clear();
  const double separation = 0.25 * first_half;
  for (std::size_t i = 1; i < explored_.size() &&
                          result.alternatives.size() < context.alternatives_wanted; ++i) {
    const Eigen::Vector3d& p = explored_[i].position;
    bool distinct = (p - best.position).norm() >= separation;
    for (const csp::Assignment& a : result.alternatives) {
      distinct = distinct && (p - Eigen::Vector3d(a[0], a[1], a[2])).norm() >= separation;
    }
    if (distinct) result.alternatives.push_back({p.x(), p.y(), p.z()});
  }
  result.evaluations = search.evaluations();
  result.iterations = passes_run;
  result.solutions_at_best = 0;
  solvers::finish_result(problem, context, budget, result);
}

}  // namespace sightline::camera
