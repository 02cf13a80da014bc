// A researcher's program against the installed package: solves 8-queens with two registered
// solvers (checked by counting attacking pairs) and films a scene file with the chase camera
// (checked by the run metrics' independent visibility check). Exit 0 when both hold.
//   usage: research_check SCENE.yaml
#include <iostream>

#include "sightline/domains/nqueens/nqueens.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/solvers/registry.h"

int main(int argc, char** argv) {
  namespace sl = sightline;
  if (argc != 2) {
    std::cerr << "usage: research_check SCENE.yaml\n";
    return 2;
  }
  const auto problem = sl::nqueens::build_nqueens(8);
  for (const char* name : {"bnb", "sls"}) {
    const auto solver = sl::solvers::SolverRegistry::global().create(name);
    const sl::solvers::SolverResult result = solver->solve(*problem, problem->default_assignment());
    const std::size_t pairs = sl::nqueens::attacking_pairs(result.best);
    std::cout << "8-queens, " << name << ": " << pairs << " attacking pairs\n";
    if (pairs != 0) return 1;
  }
  const sl::camera::Scene scene = sl::camera::read_scene_file(argv[1]);
  sl::camera::ChaseCameraOptions options;
  const sl::experiments::CameraRun run = sl::experiments::run_camera(scene, scene.profile(), options);
  std::cout << sl::experiments::summary_paragraph(scene, run) << "\n";
  return run.metrics.visible_percent == 100.0 ? 0 : 1;
}
