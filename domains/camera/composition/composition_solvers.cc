#include "sightline/domains/camera/composition/composition_solvers.h"

#include "sightline/domains/camera/composition/particle_swarm.h"
#include "sightline/domains/camera/composition/shot_search.h"
#include "sightline/domains/camera/composition/toric_framing.h"

namespace sightline::camera {

void register_composition_solvers(solvers::SolverRegistry& registry) {
  if (registry.contains("shot-search")) return;
  solvers::register_solver<ShotSearch>(
      registry, "shot-search",
      "composition: candidates where the shot's properties point, aimed at the targets, "
      "refined by a compass search (a scene's shot: block)");
  solvers::register_solver<ToricFraming>(
      registry, "toric",
      "composition: exact two-subject framing on Lino & Christie's torus (two screen_position "
      "targets), the other properties scored along it");
  solvers::register_solver<ParticleSwarm>(
      registry, "particle-swarm",
      "composition: particle swarm over the pose, the literature's baseline (Burelli et al. "
      "2008, Ranon & Urli 2014)");
}

}  // namespace sightline::camera
