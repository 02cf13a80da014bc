// How the octree solvers score a candidate cheaply without scoring it differently:
//   - BoundedViolation (body visibility, future visibility): violation_until returns exactly
//     violation() unless the candidate has lost, and then a lower bound that proves it lost;
//   - OctreeSearch::evaluate (soft sight-line counts stopped early) decides valid and cost
//     exactly as the plain loop over the view's constraints in order, written here, does:
//     the same candidates survive, with bit-identical costs.
// On a shipped scene with movers crossing the sight line (people-crossing), with the
// anticipating profile and variants with a soft look-at and a soft clearance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "domains/camera/camera_problem.h"
#include "domains/camera/constraints/bounded_violation.h"
#include "domains/camera/control/camera_problem_view.h"
#include "domains/camera/control/octree_search.h"
#include "domains/camera/profile_file.h"
#include "domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

Scene people_crossing() {
  return read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) +
                         "/experiments/scenes/anticipation/people-crossing.yaml");
}

// The plain scoring loop (as OctreeSearch::evaluate was first written): every constraint in
// the view's order, cheap then expensive, plain violation(); a candidate is dropped by a
// hidden look-at point, a broken hard constraint or a soft sum reaching the bound.
Candidate reference_evaluate(const csp::Problem& problem, const CameraProblemView& view,
                             const Eigen::Vector3d& p, double bound) {
  const double values[3] = {p.x(), p.y(), p.z()};
  const std::span<const double> x(values, 3);
  Candidate out{p, 0, false};
  for (csp::ConstraintId id : view.cheap()) {
    const csp::Constraint& c = problem.constraint(id);
    const double v = c.violation(x);
    if (c.is_hard()) {
      if (v > 0) return out;
      continue;
    }
    out.cost += c.weight() * v;
  }
  if (out.cost >= bound) return out;
  for (csp::ConstraintId id : view.expensive()) {
    const csp::Constraint& c = problem.constraint(id);
    const double v = c.violation(x);
    if (v > 0 && (id == view.look_at_id() || c.is_hard())) return out;
    if (c.is_hard()) continue;
    out.cost += c.weight() * v;
    if (out.cost >= bound) return out;
  }
  out.valid = true;
  return out;
}

TEST(BoundedViolation, IsTheViolationUnlessTheCandidateLostAndThenALowerBoundThatProvesIt) {
  const Scene scene = people_crossing();
  const CameraProfile profile = preset_profile("anticipating");
  CameraProblem cp(scene, profile);
  const csp::Problem& problem = cp.problem();
  ASSERT_TRUE(cp.ids().visible_fraction && cp.ids().future_visible);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1), around(-5, 5), up(0.3, 5);
  int exact = 0, stopped_early = 0, lost_at_the_end = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const double t = scene.trajectory().start_time() + u(rng) * scene.trajectory().duration();
    const CharacterState s = scene.character_at(t);
    cp.set_frame(s, s.position + Eigen::Vector3d(0, 2.5, -4), 1.0 / 60);
    const double values[3] = {s.position.x() + around(rng), up(rng), s.position.z() + around(rng)};
    for (csp::ConstraintId id : {*cp.ids().visible_fraction, *cp.ids().future_visible}) {
      const csp::Constraint& c = problem.constraint(id);
      const auto* bounded = dynamic_cast<const BoundedViolation*>(&c);
      ASSERT_NE(bounded, nullptr) << c.kind();
      const double full = c.violation(values);
      const double before = 3 * u(rng);
      const double bound = u(rng) < 0.1 ? std::numeric_limits<double>::infinity()
                                        : before + c.weight() * u(rng) * 1.2;
      const double got = bounded->violation_until(values, before, bound, 0.0);
      if (before + c.weight() * full < bound) {
        ASSERT_EQ(got, full) << c.kind() << " trial " << trial;  // bit for bit
        ++exact;
      } else {
        ASSERT_LE(got, full) << c.kind() << " trial " << trial;
        ASSERT_GE(before + c.weight() * got, bound) << c.kind() << " trial " << trial;
        stopped_early += got < full;
        lost_at_the_end += got == full;
      }
    }
  }
  // Every case is met: the test would notice a bound that never stops or always does.
  EXPECT_GT(exact, 500);
  EXPECT_GT(stopped_early, 100);
  EXPECT_GT(lost_at_the_end, 10);
}

class OctreeScoring : public ::testing::TestWithParam<int> {};

TEST_P(OctreeScoring, DropsAndCostsEveryCandidateAsThePlainLoopInOrderDoes) {
  const Scene scene = people_crossing();
  CameraProfile profile = preset_profile("anticipating");
  if (GetParam() == 1) profile.look_at_hard = false;
  if (GetParam() == 2) profile.clearance_hard = false;
  if (GetParam() == 3) profile = preset_profile("thesis-default");
  CameraProblem cp(scene, profile);
  const csp::Problem& problem = cp.problem();
  std::string why;
  const auto view = CameraProblemView::find(problem, &why);
  ASSERT_TRUE(view) << why;
  std::mt19937_64 rng(17 + GetParam());
  std::uniform_real_distribution<double> u(0, 1), around(-4, 4), up(0.1, 5);
  int valid = 0, dropped = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const double t = scene.trajectory().start_time() + u(rng) * scene.trajectory().duration();
    const CharacterState s = scene.character_at(t);
    cp.set_frame(s, s.position + Eigen::Vector3d(around(rng), 2.5, around(rng)), 1.0 / 60);
    OctreeSearch search(problem, *view);
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 60; ++i) {
      const Eigen::Vector3d p(s.position.x() + around(rng), up(rng), s.position.z() + around(rng));
      // The running best of a search, and sometimes an arbitrary bound.
      const double bound = u(rng) < 0.3 ? 4 * u(rng) : best;
      const Candidate want = reference_evaluate(problem, *view, p, bound);
      const Candidate got = search.evaluate(p, true, bound);
      ASSERT_EQ(got.valid, want.valid) << "frame " << frame << " candidate " << i;
      if (want.valid) {
        ASSERT_EQ(got.cost, want.cost) << "frame " << frame << " candidate " << i;
        best = std::min(best, want.cost);
        ++valid;
      } else {
        ++dropped;
      }
    }
  }
  EXPECT_GT(valid, 200);
  EXPECT_GT(dropped, 200);
}

INSTANTIATE_TEST_SUITE_P(Profiles, OctreeScoring, ::testing::Values(0, 1, 2, 3));

}  // namespace
}  // namespace sightline::camera
