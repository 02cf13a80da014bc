// Every registered solver that takes a composition problem, against a fine `grid` on tiny
// shots: the dedicated shot-search never ends above the grid's lattice optimum, and every
// solver's answer is scored by the independent evaluate() exactly as the problem scores it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/control/camera_solvers.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

// alice at (-1, 0, 0) facing +z, bob at (1, 0, 0) facing -z; a pillar; a small region in
// front of alice, so a 9-point grid over position, yaw and pitch is fine.
Scene tiny_shot(const std::string& properties) {
  return parse_scene(csp::parse_yaml(
      "name: tiny\n"
      "boxes: [{min: [0.2, 0, 2], max: [0.6, 3, 2.4]}]\n"
      "actors:\n"
      "  - {name: alice, trajectory: [{t: 0, position: [-1, 0, 0], yaw: 0}]}\n"
      "  - {name: bob, trajectory: [{t: 0, position: [1, 0, 0], yaw: 180}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-2, 1, 3], max: [1, 2.5, 5]}\n"
      "  properties:\n" + properties,
      "tiny.yaml"));
}

const char* kShots[] = {
    "    - {kind: screen_position, target: alice, at: [0.4, 0.6]}\n"
    "    - {kind: size, target: alice, range: [0.3, 0.4]}\n"
    "    - {kind: angle_horizontal, target: alice, range: [-10, 10]}\n",
    "    - {kind: framed, target: alice, rect: [0, 0, 0.5, 1]}\n"
    "    - {kind: framed, target: bob, rect: [0.5, 0, 1, 1]}\n"
    "    - {kind: visible, target: bob, range: [0.9, 1]}\n"
    "    - {kind: order, targets: [alice, bob]}\n",
    // Not all can be met: alice 1-2 m away, seen from 30-40 degrees above, at (0.7, 0.5).
    "    - {kind: distance, target: alice, range: [1, 2], softness: 5}\n"
    "    - {kind: angle_vertical, target: alice, range: [30, 40]}\n"
    "    - {kind: screen_position, target: alice, at: [0.7, 0.5]}\n"
    "    - {kind: visible, target: alice, hard: true}\n",
};

TEST(CompositionSolvers, EverySolverAgainstAFineGridOnTinyShots) {
  solvers::SolverRegistry& registry = solver_registry();
  register_composition_solvers(registry);
  for (const char* properties : kShots) {
    const Scene scene = tiny_shot(properties);
    const CompositionProblem problem(scene, *scene.shot(), 0);
    solvers::SolveContext context;
    const solvers::SolverResult grid =
        registry.create("grid", {{"points", "9"}})->solve(problem.problem(), csp::Assignment{}, context);
    ASSERT_TRUE(grid.feasible());
    for (const std::string& name : registry.names()) {
      auto solver = registry.create(name);
      if (!solver->unsuitable_reason(problem.problem()).empty() || name == "grid") continue;
      solvers::SolveContext limited;
      limited.limits.time_limit_seconds = 0.05;
      // Local methods start from the middle of the region looking at alice.
      CameraPose middle;
      middle.position = scene.shot()->region.centre();
      middle.look_at = Eigen::Vector3d(-1, 1.5, 0);
      middle.fov = 50;
      middle.aspect = scene.shot()->aspect;
      const solvers::SolverResult r =
          solver->solve(problem.problem(), problem.assignment(middle), limited);
      const ShotEvaluation e = problem.evaluate(problem.pose(r.best));
      // The problem's cost is FORMATS.md's cost of the pose.
      EXPECT_NEAR(r.cost(), e.cost, 1e-9) << name;
      EXPECT_EQ(r.feasible(), e.feasible) << name << ": " << e.why_infeasible;
      std::printf("%-28s cost %.4f (grid %.4f)\n", name.c_str(), r.cost(), grid.cost());
      if (name == "shot-search") {
        EXPECT_TRUE(r.feasible());
        EXPECT_LE(r.cost(), grid.cost() + 1e-9) << properties;
      }
    }
  }
}

TEST(CompositionSolvers, ShotSearchIsDeterministic) {
  register_composition_solvers(solvers::SolverRegistry::global());
  const Scene scene = tiny_shot(kShots[1]);
  const CompositionProblem problem(scene, *scene.shot(), 0);
  auto a = solvers::SolverRegistry::global().create("shot-search")->solve(problem.problem(), {});
  auto b = solvers::SolverRegistry::global().create("shot-search")->solve(problem.problem(), {});
  EXPECT_EQ(a.best, b.best);
}

// The screen points (FORMATS.md's pinhole, worked here from the definition, not by View) of
// a box's eight corners; false when one is not in front of the camera.
bool corners_on_screen(const CameraPose& pose, const Aabb& box, std::vector<Eigen::Vector2d>& out) {
  const Eigen::Vector3d f = (pose.look_at - pose.position).normalized();
  const Eigen::Vector3d r = f.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d u = r.cross(f);  // roll 0
  const double t = std::tan(pose.fov * 3.14159265358979323846 / 360);
  out.clear();
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d q((c & 1) ? box.max.x() : box.min.x(), (c & 2) ? box.max.y() : box.min.y(),
                            (c & 4) ? box.max.z() : box.min.z());
    const Eigen::Vector3d d = q - pose.position;
    const double z = d.dot(f);
    if (z <= 0.05) return false;
    out.emplace_back((1 + d.dot(r) / (z * t * pose.aspect)) / 2, (1 + d.dot(u) / (z * t)) / 2);
  }
  return true;
}

// Screen points all beyond one edge of the image (left, right, below or above it).
bool beyond_one_edge(const std::vector<Eigen::Vector2d>& points) {
  bool left = true, right = true, below = true, above = true;
  for (const auto& c : points) {
    left = left && c.x() < 0;
    right = right && c.x() > 1;
    below = below && c.y() < 0;
    above = above && c.y() > 1;
  }
  return left || right || below || above;
}

// shot-search's answer within `evaluations` (a budget that is the same on any machine).
csp::Assignment shot_search(const CompositionProblem& problem, std::uint64_t evaluations) {
  register_composition_solvers(solvers::SolverRegistry::global());
  solvers::SolveContext context;
  context.limits.max_evaluations = evaluations;
  auto solver = solvers::SolverRegistry::global().create("shot-search");
  return solver->solve(problem.problem(), {}, context).best;
}

// A group shot of ann, ben and cal with dee, whom the shot keeps out (weight 2), standing in
// the row between ann and ben: no pose frames the three without dee, so the best gives up
// ann (satisfaction 4/5 = 0.8), dee off one edge of the image. shot-search's candidates
// include the view turned just enough to take dee off each edge; without them its compass
// steps, from views that hold all four, found no way out.
TEST(CompositionSolvers, ShotSearchGivesUpOnePersonToKeepOutSomeoneAmongThem) {
  const Scene scene = parse_scene(csp::parse_yaml(
      "name: row\n"
      "actors:\n"
      "  - {name: ann, trajectory: [{t: 0, position: [-2, 0, 0], yaw: 0}]}\n"
      "  - {name: dee, trajectory: [{t: 0, position: [0, 0, 0], yaw: 0}]}\n"
      "  - {name: ben, trajectory: [{t: 0, position: [2, 0, 0], yaw: 0}]}\n"
      "  - {name: cal, trajectory: [{t: 0, position: [3, 0, 0], yaw: 0}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-6, 1, 3], max: [6, 3, 9]}\n"
      "  properties:\n"
      "    - {kind: framed, target: ann}\n"
      "    - {kind: framed, target: ben}\n"
      "    - {kind: framed, target: cal}\n"
      "    - {kind: framed, target: dee, range: [0, 0], weight: 2}\n",
      "row.yaml"));
  const CompositionProblem problem(scene, *scene.shot(), 0);
  for (int n : {500, 800, 1000, 1500, 2000, 3000, 4000, 6000, 8000, 12000}) std::printf("EVAL %d %.5f\n", n, problem.evaluate(problem.pose(shot_search(problem, n))).satisfaction);
  const CameraPose pose = problem.pose(shot_search(problem, 1500));
  const ShotEvaluation e = problem.evaluate(pose);
  EXPECT_NEAR(e.satisfaction, 0.8, 1e-9);
  // Independently: dee wholly off screen, ben and cal wholly on it.
  std::vector<Eigen::Vector2d> corners;
  auto person = [&](const char* name) { return *problem.world().find(name); };
  const auto& people = problem.world().people();
  ASSERT_TRUE(corners_on_screen(pose, people[person("ben")].body, corners));
  for (const auto& c : corners) EXPECT_TRUE(c.minCoeff() >= 0 && c.maxCoeff() <= 1);
  ASSERT_TRUE(corners_on_screen(pose, people[person("cal")].body, corners));
  for (const auto& c : corners) EXPECT_TRUE(c.minCoeff() >= 0 && c.maxCoeff() <= 1);
  if (corners_on_screen(pose, people[person("dee")].body, corners)) {
    EXPECT_TRUE(beyond_one_edge(corners));
  }
}

// Problem 11 of the benchmark of shot problems (experiments/sources/shot_problems.h, seed
// 11), written out: ann and ben placed on screen, ann seen from behind, ben 90% visible
// (hard). Its optimum, 0.95814 (particle-swarm with 1 s), has ann's and ben's screen
// distances both at the 0.02 rim of their flat zones; without the polls that hold one
// person on screen, shot-search stopped at 0.9575 whatever its budget.
TEST(CompositionSolvers, ShotSearchFollowsTheRimOfAScreenPositionToTheOptimum) {
  const Scene scene = parse_scene(csp::parse_yaml(
      "name: shot-problem-11\n"
      "boxes:\n"
      "  - {min: [-0.842, 0.000, 3.196], max: [0.069, 0.904, 3.946]}\n"
      "  - {min: [-1.489, 0.000, 5.454], max: [-0.690, 1.056, 6.253]}\n"
      "  - {min: [-5.335, 0.000, 2.019], max: [-4.624, 0.577, 2.686]}\n"
      "  - {min: [3.328, 0.000, -0.143], max: [3.728, 3.000, 0.257]}\n"
      "actors:\n"
      "  - {name: ann, trajectory: [{t: 0, position: [0.175, 0, -1.460], yaw: -36.407}]}\n"
      "  - {name: ben, trajectory: [{t: 0, position: [-1.771, 0, 1.934], yaw: 142.604}]}\n"
      "  - {name: cal, trajectory: [{t: 0, position: [-0.202, 0, 0.606], yaw: -105.934}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-9, 0.3, -9], max: [9, 5, 9]}\n"
      "  clearance: 0.3\n"
      "  properties:\n"
      "    - {kind: angle_horizontal, target: ben, range: [-35, 35], weight: 2}\n"
      "    - {kind: angle_horizontal, target: ann, range: [140, -140]}\n"
      "    - {kind: screen_position, target: ann, at: [0.25, 0.5]}\n"
      "    - {kind: screen_position, target: ben, at: [0.667, 0.55]}\n"
      "    - {kind: framed, target: ann, range: [0.3, 1]}\n"
      "    - {kind: visible, target: ben, range: [0.9, 1], hard: true}\n",
      "shot-problem-11.yaml"));
  const CompositionProblem problem(scene, *scene.shot(), 0);
  const ShotEvaluation e = problem.evaluate(problem.pose(shot_search(problem, 4000)));
  ASSERT_TRUE(e.feasible) << e.why_infeasible;
  EXPECT_GT(e.satisfaction, 0.9581) << "ann " << e.measures[2] << ", ben " << e.measures[3];
  // With 1,500 evaluations (what 2 ms gives on the 2-core VM): stepping an axis up and down,
  // each re-hold of a person on screen scoring 5e-8 to 1e-7 better, took 750 of them and
  // left it at 0.95799 (held axis moves may not go straight back).
  const ShotEvaluation quick = problem.evaluate(problem.pose(shot_search(problem, 1500)));
  EXPECT_GT(quick.satisfaction, 0.9581);
}

// Problem 596 of the benchmark, written out: ann, ben and cal framed in a rect 0.05 inside
// the image's edges and 60% visible, dee near them kept out (weight 2), ann seen from 5-30
// degrees up and left of ben; all of it can be met (satisfaction 1). Within 2,500
// evaluations shot-search stopped with ben 26 of 27 samples framed (0.9963) from every
// pose its steps tried round its best: a count is flat between its steps. Walking the
// plateau toward the missing sample (poses that score the same and are nearer the next
// count: Framing::framed_gap) reaches 27.
TEST(CompositionSolvers, ShotSearchWalksTheFlatOfACountToItsNextStep) {
  const Scene scene = parse_scene(csp::parse_yaml(
      "name: shot-problem-596\n"
      "boxes:\n"
      "  - {min: [-5.170, 0.000, -3.529], max: [-3.800, 1.063, -2.267]}\n"
      "  - {min: [1.646, 0.000, -4.362], max: [2.546, 0.701, -3.030]}\n"
      "  - {min: [-5.230, 0.000, 2.045], max: [-4.830, 3.000, 2.445]}\n"
      "  - {min: [3.180, 0.000, 2.839], max: [3.580, 3.000, 3.239]}\n"
      "  - {min: [1.061, 0.000, 2.942], max: [9.000, 2.800, 3.142]}\n"
      "actors:\n"
      "  - {name: ann, trajectory: [{t: 0, position: [2.478, 0, 1.412], yaw: -87.627}]}\n"
      "  - {name: ben, trajectory: [{t: 0, position: [-1.731, 0, -0.396], yaw: 59.494}]}\n"
      "  - {name: cal, trajectory: [{t: 0, position: [-1.780, 0, 2.401], yaw: 159.231}]}\n"
      "  - {name: dee, trajectory: [{t: 0, position: [-0.637, 0, -1.262], yaw: 12.625}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-9, 0.3, -9], max: [9, 5, 9]}\n"
      "  clearance: 0.3\n"
      "  properties:\n"
      "    - {kind: framed, target: ann, rect: [0.05, 0.05, 0.95, 0.95]}\n"
      "    - {kind: visible, target: ann, range: [0.6, 1]}\n"
      "    - {kind: framed, target: ben, rect: [0.05, 0.05, 0.95, 0.95]}\n"
      "    - {kind: visible, target: ben, range: [0.6, 1]}\n"
      "    - {kind: framed, target: cal, rect: [0.05, 0.05, 0.95, 0.95]}\n"
      "    - {kind: visible, target: cal, range: [0.6, 1]}\n"
      "    - {kind: framed, target: dee, range: [0, 0], weight: 2}\n"
      "    - {kind: angle_vertical, target: ann, range: [5, 30]}\n"
      "    - {kind: order, targets: [ann, ben]}\n",
      "shot-problem-596.yaml"));
  const CompositionProblem problem(scene, *scene.shot(), 0);
  const CameraPose pose = problem.pose(shot_search(problem, 2500));
  const ShotEvaluation e = problem.evaluate(pose);
  ASSERT_TRUE(e.feasible) << e.why_infeasible;
  EXPECT_NEAR(e.satisfaction, 1, 1e-9);
  // Independently: the corners of each wanted person's sample box (every sample a mix of
  // them) inside the rect, so all 27 samples are; dee's wholly beyond one edge of the image.
  const auto& people = problem.world().people();
  auto sample_box = [&](const char* name) {
    const Aabb& body = people[*problem.world().find(name)].body;
    return Aabb{body.min + 0.1 * (body.max - body.min), body.min + 0.9 * (body.max - body.min)};
  };
  std::vector<Eigen::Vector2d> corners;
  for (const char* name : {"ann", "ben", "cal"}) {
    ASSERT_TRUE(corners_on_screen(pose, sample_box(name), corners)) << name;
    for (const auto& c : corners) {
      EXPECT_TRUE(c.minCoeff() >= 0.05 && c.maxCoeff() <= 0.95) << name << " " << c.transpose();
    }
  }
  if (corners_on_screen(pose, sample_box("dee"), corners)) {
    EXPECT_TRUE(beyond_one_edge(corners));
  }
}

// shot-search holding the camera's position (a tracking camera's view turned from where it
// is, on its way to a far pose): from a view 6 degrees off in yaw and pitch, it ends where
// it started, lens and roll as given (both fixed by the shot), never worse than the start,
// and, on the shots whose measures vary smoothly with the view (screen position, size,
// angles), no worse than the best of a 0.25-degree brute-force scan of yaw and pitch from
// that position. (A `framed` measure is a share of a few samples, flat between steps: a
// compass search can stop on a step, so kShots[1] is held to the first three only.)
TEST(CompositionSolvers, ShotSearchHoldingItsPositionTurnsTheViewToTheBestFromThere) {
  register_composition_solvers(solvers::SolverRegistry::global());
  for (std::size_t shot = 0; shot < std::size(kShots); ++shot) {
    const Scene scene = tiny_shot(kShots[shot]);
    const CompositionProblem problem(scene, *scene.shot(), 0);
    CameraPose from_there;
    from_there.position = Eigen::Vector3d(-0.5, 1.75, 4);
    from_there.look_at = Eigen::Vector3d(-1, 1, 0);
    from_there.aspect = scene.shot()->aspect;
    csp::Assignment values = problem.assignment(from_there);
    csp::Score scanned = problem.problem().score(values);
    csp::Assignment best = values;
    for (double yaw = -180; yaw < 180; yaw += 0.25) {
      for (double pitch = -60; pitch <= 60; pitch += 0.25) {
        values[3] = yaw;
        values[4] = pitch;
        const csp::Score s = problem.problem().score(values);
        if (s.better_than(scanned)) {
          scanned = s;
          best = values;
        }
      }
    }
    csp::Assignment start = best;
    start[3] += 6;
    start[4] -= 6;
    solvers::SolveContext context;
    context.limits.max_evaluations = 400;
    auto solver = solvers::SolverRegistry::global().create(
        "shot-search", {{"global", "false"}, {"hold_position", "true"}});
    const solvers::SolverResult r = solver->solve(problem.problem(), start, context);
    for (std::size_t k : {0, 1, 2, 5, 6}) EXPECT_EQ(r.best[k], start[k]) << "shot " << shot << ", variable " << k;
    const csp::Score got = problem.problem().score(r.best);
    EXPECT_FALSE(problem.problem().score(start).better_than(got)) << "shot " << shot;
    if (shot != 1) {
      EXPECT_EQ(got.hard, scanned.hard) << "shot " << shot;
      EXPECT_LE(got.soft, scanned.soft + 1e-9) << "shot " << shot;
    }
    std::printf("shot %zu, position held: cost %.6f (start %.6f, scan %.6f)\n", shot, got.soft,
                problem.problem().score(start).soft, scanned.soft);
  }
  EXPECT_THROW(solvers::SolverRegistry::global().create("shot-search", {{"hold_position", "true"}}),
               std::exception);
}

}  // namespace
}  // namespace sightline::camera
