// shot-search's view of a problem (shot_search_framing.h) and the move it makes along the rim
// of a screen_position's flat zone: hold_on_screen keeps one person where they are in the
// image (checked by this test's own pinhole, FORMATS.md's definition) while the camera moves.
// What the move buys shot-search: composition_solvers_test.cc (problem 11). And the search's
// own scoring (a view shared by the properties, position-only terms kept while the camera
// only turns) against the problem's full evaluation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/shot_search_framing.h"
#include "sightline/domains/camera/scene_file.h"
#include "tests/csp/bounded_score_check.h"

namespace sightline::camera {
namespace {

// FORMATS.md's pinhole with roll 0, worked here: the screen point of `q` from `pose`.
Eigen::Vector2d on_screen(const CameraPose& pose, const Eigen::Vector3d& q) {
  const Eigen::Vector3d f = (pose.look_at - pose.position).normalized();
  const Eigen::Vector3d r = f.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d u = r.cross(f);
  const double t = std::tan(pose.fov * 3.14159265358979323846 / 360);
  const Eigen::Vector3d d = q - pose.position;
  const double z = d.dot(f);
  return {(1 + d.dot(r) / (z * t * pose.aspect)) / 2, (1 + d.dot(u) / (z * t)) / 2};
}

// A scene's shot at t = 0 and the search's view of it.
struct FramedShot {
  FramedShot(const std::string& yaml, const std::string& file)
      : scene(parse_scene(csp::parse_yaml(yaml, file))),
        owner(scene, *scene.shot(), 0),
        framing(owner.problem(), owner, storage) {}
  const Scene scene;
  const CompositionProblem owner;
  shot_search_detail::FramingStorage storage;
  shot_search_detail::Framing framing;
};

TEST(ShotSearchFraming, HoldOnScreenKeepsOnePersonWhereTheyAreAsTheCameraMoves) {
  FramedShot shot(
      "name: two\n"
      "actors:\n"
      "  - {name: alice, trajectory: [{t: 0, position: [-1, 0, 0], yaw: 0}]}\n"
      "  - {name: bob, trajectory: [{t: 0, position: [1, 0, 0], yaw: 180}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-4, 0.5, 2], max: [4, 4, 8]}\n"
      "  properties:\n"
      "    - {kind: screen_position, target: alice, at: [0.35, 0.6]}\n"
      "    - {kind: screen_position, target: bob, at: [0.7, 0.5]}\n",
      "two.yaml");
  const CompositionProblem& owner = shot.owner;
  shot_search_detail::Framing& framing = shot.framing;
  const auto& people = owner.world().people();
  const Eigen::Vector3d alice = people[*owner.world().find("alice")].aim;
  const Eigen::Vector3d bob = people[*owner.world().find("bob")].aim;

  shot_search_detail::Point x{-0.5, 1.8, 5, 0, 0, 50, 0};
  framing.aim(x);
  const CameraPose start = owner.pose(framing.values(x));
  const Eigen::Vector2d alice_at = on_screen(start, alice);
  const Eigen::Vector2d bob_at = on_screen(start, bob);
  Eigen::Vector2d held;
  ASSERT_TRUE(framing.screen_point(x, 0, held));
  EXPECT_LT((held - alice_at).norm(), 1e-9);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  int bob_moved = 0;
  for (int trial = 0; trial < 50; ++trial) {
    shot_search_detail::Point y = x;
    for (int k = 0; k < 3; ++k) y[static_cast<std::size_t>(k)] += 0.3 * unit(rng);
    y[3] += 3 * unit(rng);
    y[4] += 3 * unit(rng);
    ASSERT_TRUE(framing.hold_on_screen(y, 0, held)) << trial;
    const CameraPose moved = owner.pose(framing.values(y));
    EXPECT_LT((on_screen(moved, alice) - alice_at).norm(), 1e-6) << trial;
    bob_moved += (on_screen(moved, bob) - bob_at).norm() > 1e-3;
  }
  // The move is a real one: the other person's place on screen changes.
  EXPECT_GT(bob_moved, 40);
}

// Framing::framed_gap against this test's own count: the 27 samples of FORMATS.md projected
// by the test's pinhole; for each framed property partly met, the distances the samples it
// lacks are from its rect (wanted in) or from the rect's nearest edge (kept out), the
// nearest first, as many as take the count to its range, times the weight. From poses
// turned at random about one that frames both people, so that the counts fall anywhere.
TEST(ShotSearchFraming, FramedGapIsTheDistanceTheMissingSamplesHaveToTravel) {
  FramedShot shot(
      "name: gap\n"
      "actors:\n"
      "  - {name: alice, trajectory: [{t: 0, position: [-0.6, 0, 0], yaw: 0}]}\n"
      "  - {name: bob, trajectory: [{t: 0, position: [0.6, 0, 0], yaw: 180}]}\n"
      "shot:\n"
      "  fov: 50\n"
      "  region: {min: [-4, 0.5, 2], max: [4, 4, 8]}\n"
      "  properties:\n"
      "    - {kind: framed, target: alice, rect: [0.1, 0.1, 0.9, 0.9], range: [0.7, 1], weight: 2}\n"
      "    - {kind: framed, target: bob, rect: [0.5, 0, 1, 1], range: [0, 0.2], softness: 2}\n",
      "gap.yaml");
  const CompositionProblem& owner = shot.owner;
  const auto& people = owner.world().people();
  struct Wanted {
    const char* name;
    Eigen::Vector4d rect;
    double lo, hi, softness, weight;
  };
  const Wanted wanted[] = {{"alice", {0.1, 0.1, 0.9, 0.9}, 0.7, 1, 1, 2},
                           {"bob", {0.5, 0, 1, 1}, 0, 0.2, 2, 1}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  int partly = 0, nothing = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const shot_search_detail::Point x{0.5 * unit(rng), 1.6 + 0.3 * unit(rng), 4 + unit(rng),
                                      25 * unit(rng), 15 * unit(rng), 50, 0};
    const CameraPose pose = owner.pose(shot.framing.values(x));
    double expected = 0;
    for (const Wanted& w : wanted) {
      const Aabb& body = people[*owner.world().find(w.name)].body;
      std::vector<double> out, in;
      for (double i : {0.1, 0.5, 0.9}) {
        for (double j : {0.1, 0.5, 0.9}) {
          for (double k : {0.1, 0.5, 0.9}) {
            const Eigen::Vector3d q = body.min + Eigen::Vector3d(i, j, k).cwiseProduct(body.max - body.min);
            ASSERT_GT((q - pose.position).dot((pose.look_at - pose.position).normalized()), 0.05);
            const Eigen::Vector2d s = on_screen(pose, q);
            const double dx = std::max(w.rect[0] - s.x(), s.x() - w.rect[2]);
            const double dy = std::max(w.rect[1] - s.y(), s.y() - w.rect[3]);
            if (dx <= 0 && dy <= 0) {
              in.push_back(std::min({s.x() - w.rect[0], w.rect[2] - s.x(), s.y() - w.rect[1], w.rect[3] - s.y()}));
            } else {
              out.push_back(std::sqrt(std::pow(std::max(dx, 0.0), 2) + std::pow(std::max(dy, 0.0), 2)));
            }
          }
        }
      }
      const double fraction = static_cast<double>(in.size()) / 27;
      const double gap = fraction < w.lo ? w.lo - fraction : fraction > w.hi ? fraction - w.hi : 0;
      if (gap == 0 || gap >= w.softness) continue;  // met, or scoring 0: no gap
      ++partly;
      std::vector<double>& moving = fraction < w.lo ? out : in;
      // Samples to move: alice needs 19 of 27 in (0.7), bob at most 5 (0.2).
      const std::size_t need = fraction < w.lo ? 19 - in.size() : in.size() - 5;
      std::sort(moving.begin(), moving.end());
      for (std::size_t k = 0; k < need; ++k) expected += w.weight * moving[k];
    }
    nothing += expected == 0;
    EXPECT_NEAR(shot.framing.framed_gap(x), expected, 1e-9) << trial;
  }
  // The poses cover the cases: properties partly met, and poses where none is.
  EXPECT_GT(partly, 100);
  EXPECT_GT(nothing, 10);
}

// A framed range beyond what a fraction can reach (FORMATS.md allows any lo <= hi): below 0,
// every sample inside must leave the rect, so the gap is the sum of all their depths; above
// 1, every sample outside must enter it, the sum of all their distances.
TEST(ShotSearchFraming, FramedGapOfARangeNoFractionReachesCountsEverySample) {
  for (const bool below : {true, false}) {
    FramedShot shot(std::string("name: beyond\n"
                                "actors:\n"
                                "  - {name: alice, trajectory: [{t: 0, position: [0, 0, 0], yaw: 0}]}\n"
                                "shot:\n"
                                "  fov: 50\n"
                                "  region: {min: [-4, 0.5, 2], max: [4, 4, 8]}\n"
                                "  properties:\n"
                                "    - {kind: framed, target: alice, rect: [0.5, 0, 1, 1], softness: 3, range: ") +
                        (below ? "[-1, -0.5]" : "[1.5, 2]") + "}\n",
                    "beyond.yaml");
    const auto& body = shot.owner.world().people()[0].body;
    const shot_search_detail::Point x{0.4, 1.5, 4, 0, 0, 50, 0};  // alice across the rect's edge
    const CameraPose pose = shot.owner.pose(shot.framing.values(x));
    double in_depths = 0, out_distances = 0;
    int in = 0;
    for (double i : {0.1, 0.5, 0.9}) {
      for (double j : {0.1, 0.5, 0.9}) {
        for (double k : {0.1, 0.5, 0.9}) {
          const Eigen::Vector2d s = on_screen(pose, body.min + Eigen::Vector3d(i, j, k).cwiseProduct(body.max - body.min));
          ASSERT_TRUE(s.y() > 0 && s.y() < 1);
          if (s.x() >= 0.5 && s.x() <= 1) {
            ++in;
            in_depths += std::min({s.x() - 0.5, 1 - s.x(), s.y(), 1 - s.y()});
          } else {
            out_distances += std::max(0.5 - s.x(), s.x() - 1);
          }
        }
      }
    }
    ASSERT_GT(in, 0);
    ASSERT_LT(in, 27);
    EXPECT_NEAR(shot.framing.framed_gap(x), below ? in_depths : out_distances, 1e-9) << below;
  }
}

// Three people among pillars, with every kind of property, one of them hard.
constexpr const char* kThreeAmongPillars =
    "name: three among pillars\n"
    "boxes:\n"
    "  - {min: [-0.3, 0, 1.5], max: [0.3, 3, 2.1]}\n"
    "  - {min: [1.5, 0, 2.5], max: [2.2, 1.2, 3.2]}\n"
    "actors:\n"
    "  - {name: ann, trajectory: [{t: 0, position: [-1, 0, 0], yaw: 0}]}\n"
    "  - {name: ben, trajectory: [{t: 0, position: [1, 0, 0.5], yaw: 180}]}\n"
    "  - {name: cal, trajectory: [{t: 0, position: [0, 0, -1.5], yaw: 90}]}\n"
    "shot:\n"
    "  fov: [30, 70]\n"
    "  roll: [-20, 20]\n"
    "  region: {min: [-5, 0.3, 1], max: [5, 4, 7]}\n"
    "  clearance: 0.3\n"
    "  properties:\n"
    "    - {kind: framed, target: ann}\n"
    "    - {kind: visible, target: ann, range: [0.6, 1]}\n"
    "    - {kind: visible, target: ben, hard: true}\n"
    "    - {kind: framed, target: cal, range: [0, 0], weight: 2}\n"
    "    - {kind: screen_position, target: ben, at: [0.6, 0.5]}\n"
    "    - {kind: angle_horizontal, target: ann, range: [-40, 40]}\n"
    "    - {kind: distance, target: ben, range: [3, 5]}\n"
    "    - {kind: size, target: ann, range: [0.3, 0.5]}\n"
    "    - {kind: order, targets: [ann, ben]}\n";

// Framing::score keeps the terms that read the camera's position only (visible, distance,
// the vantage angles, clearance) while the camera turns or zooms without moving; it must
// give exactly the problem's own score, whatever the sequence of points: moves, turns,
// zooms, rolls, a point whose view is invalid (a field of view of 0) and back. And
// Framing::score_below, asked first at each point with a bound just above, at or below its
// score or far from it, must decide as the problem's score does (bounded_score_check.h),
// and a point it left in part (its position's terms not asked) must not spoil the terms
// kept for the next.
TEST(ShotSearchFraming, ScoreIsTheProblemsScoreWhetherTheCameraMovesOrOnlyTurns) {
  FramedShot shot(kThreeAmongPillars, "three.yaml");
  const csp::Problem& problem = shot.owner.problem();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  shot_search_detail::Point x{0, 1.7, 4, 0, 0, 50, 0};
  int moves = 0, turns = 0, differing_visible = 0, complete = 0, in_part = 0;
  double last_visible = -1;
  for (int trial = 0; trial < 400; ++trial) {
    const double kind = unit(rng);
    if (kind < 0.3) {  // a move: a new position anywhere in the region
      x[0] = -5 + 10 * unit(rng);
      x[1] = 0.3 + 3.7 * unit(rng);
      x[2] = 1 + 6 * unit(rng);
      ++moves;
    } else if (kind < 0.95) {  // a turn, a zoom or a roll where it stands
      x[3] += 20 * (unit(rng) - 0.5);
      x[4] += 20 * (unit(rng) - 0.5);
      x[5] = 30 + 40 * unit(rng);
      x[6] = -20 + 40 * unit(rng);
      ++turns;
    } else {  // no view: every property scores 0
      x[5] = 0;
    }
    const csp::Score full = problem.score(shot.framing.values(x));
    csp::Score bound = full;
    const int pick = trial % 7;
    if (pick < 5) {
      bound.soft += std::array<double, 5>{-1, -1e-9, 0, 1e-9, 1}[static_cast<std::size_t>(pick)];
    } else {
      bound.hard += pick == 5 ? 1 : -1;
    }
    bool whole = false;
    const csp::Score got = shot.framing.score_below(x, bound, whole);
    csp::expect_bounded_score(got, whole, full, bound, trial);
    ++(whole ? complete : in_part);
    const csp::Score fast = shot.framing.score(x);
    ASSERT_EQ(fast.hard, full.hard) << trial;
    ASSERT_EQ(fast.soft, full.soft) << trial;
    if (kind >= 0.95) {
      EXPECT_FALSE(View::of(shot.owner.pose(shot.framing.values(x)))) << trial;
      x[5] = 50;
    }
    // The sequence is a real test of the kept terms: ann's sight lines change between moves.
    const double visible = problem.constraint_score(1, shot.framing.values(x)).soft;
    differing_visible += kind < 0.3 && visible != last_visible;
    last_visible = visible;
  }
  EXPECT_GT(moves, 80);
  EXPECT_GT(turns, 200);
  EXPECT_GT(differing_visible, 10);
  EXPECT_GT(complete, 100);
  EXPECT_GT(in_part, 30);
}

}  // namespace
}  // namespace sightline::camera
