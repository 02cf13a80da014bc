#include "sightline/domains/camera/composition/composition_solvers.h"

#include "sightline/domains/camera/composition/shot_search.h"

namespace sightline::camera {

void register_composition_solvers(solvers::SolverRegistry& registry) {
  if (registry.contains("shot-search")) return;
  solvers::register_solver<ShotSearch>(
      registry, "shot-search",
      "composition: candidates where the shot's properties point, aimed at the targets, "
      "refined by a compass search (a scene's shot: block)");
}

}  // namespace sightline::camera
