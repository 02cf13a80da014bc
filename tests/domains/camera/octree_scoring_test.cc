// How the octree solvers score a candidate cheaply without scoring it differently:
//   - violation_until (body visibility, future visibility): violation_until returns exactly
//     violation() unless the candidate has lost, and then a lower bound that proves it lost
//     (with a cost known to come after it in the sum, too);
//   - OctreeSearch::evaluate (soft sight-line counts stopped early, the expensive constraints
//     asked out of the problem's order) decides valid and cost exactly as the plain loop
//     over the view's constraints in order, written here, does: the same candidates
//     survive, with bit-identical costs.
// On a shipped scene with movers crossing the sight line (people-crossing), with the
// anticipating profile and variants with a soft look-at and a soft clearance, and on a level
// walk (oa_thor, where the sight lines go to Embree as ray packets).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/control/camera_problem_view.h"
#include "sightline/domains/camera/control/octree_search.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"

namespace sightline::camera {
namespace {

Scene people_crossing() {
  return read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) +
                         "/experiments/scenes/anticipation/people-crossing.yaml");
}

// The largest shipped level walk's map (66,906 triangles), loaded once for the whole program.
const Scene& oa_thor() {
  static const Scene scene = read_scene_file(std::string(SIGHTLINE_SOURCE_DIR) +
                                             "/experiments/scenes/levels/oa_thor-walk2.yaml");
  return scene;
}

// A camera position around the character: within `around` horizontally, at 0.1-5 m up.
Eigen::Vector3d near(const CharacterState& s, std::mt19937_64& rng, double around) {
  std::uniform_real_distribution<double> u(-around, around), up(0.1, 5);
  return {s.position.x() + u(rng), s.position.y() + up(rng), s.position.z() + u(rng)};
}

const Scene& people_crossing_once() {
  static const Scene scene = people_crossing();
  return scene;
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

class Bounded : public ::testing::TestWithParam<bool> {};

TEST_P(Bounded, IsTheViolationUnlessTheCandidateLostAndThenALowerBoundThatProvesIt) {
  const bool level = GetParam();
  const Scene& scene = level ? oa_thor() : people_crossing_once();
  const CameraProfile profile = preset_profile("anticipating");
  CameraProblem cp(scene, profile);
  const csp::Problem& problem = cp.problem();
  ASSERT_TRUE(cp.ids().visible_fraction && cp.ids().future_visible);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int exact = 0, stopped_early = 0, lost_at_the_end = 0;
  for (int trial = 0; trial < (level ? 1500 : 3000); ++trial) {
    const double t = scene.trajectory().start_time() + u(rng) * scene.trajectory().duration();
    const CharacterState s = scene.character_at(t);
    cp.set_frame(s, s.position + Eigen::Vector3d(0, 2.5, -4), 1.0 / 60);
    const Eigen::Vector3d p = near(s, rng, 5);
    const double values[3] = {p.x(), p.y(), p.z()};
    for (csp::ConstraintId id : {*cp.ids().visible_fraction, *cp.ids().future_visible}) {
      const csp::Constraint& c = problem.constraint(id);
      const double full = c.violation(values);
      const double before = 3 * u(rng);
      // Half the time a term known to come after it in the sum (a search asking out of order).
      const double after = u(rng) < 0.5 ? 0.0 : 2 * u(rng);
      const double bound = u(rng) < 0.1 ? std::numeric_limits<double>::infinity()
                                        : before + after + c.weight() * u(rng) * 1.2;
      const double got = c.violation_until(values, before, bound, after);
      if ((before + c.weight() * full) + after < bound) {
        ASSERT_EQ(got, full) << c.kind() << " trial " << trial;  // bit for bit
        ++exact;
      } else {
        ASSERT_LE(got, full) << c.kind() << " trial " << trial;
        ASSERT_GE((before + c.weight() * got) + after, bound) << c.kind() << " trial " << trial;
        stopped_early += got < full;
        lost_at_the_end += got == full;
      }
    }
  }
  // Every case is met: the test would notice a bound that never stops or always does. On a
  // level the sight lines go to Embree as packets: only the body's centre ray is left out
  // when its 8 corners already lost, so fewer counts stop early.
  EXPECT_GT(exact, 500);
  EXPECT_GT(stopped_early, level ? 50 : 100);
  EXPECT_GT(lost_at_the_end, 10);
}

INSTANTIATE_TEST_SUITE_P(BoxesAndLevel, Bounded, ::testing::Bool());

class OctreeScoring : public ::testing::TestWithParam<int> {};

TEST_P(OctreeScoring, DropsAndCostsEveryCandidateAsThePlainLoopInOrderDoes) {
  const Scene& scene = GetParam() == 4 ? oa_thor() : people_crossing_once();
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
  std::uniform_real_distribution<double> u(0, 1), around(-4, 4);
  int valid = 0, dropped = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const double t = scene.trajectory().start_time() + u(rng) * scene.trajectory().duration();
    const CharacterState s = scene.character_at(t);
    cp.set_frame(s, s.position + Eigen::Vector3d(around(rng), 2.5, around(rng)), 1.0 / 60);
    OctreeSearch search(problem, *view);
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 60; ++i) {
      const Eigen::Vector3d p = near(s, rng, 4);
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

// 0-3: people-crossing (anticipating, soft look-at, soft clearance, thesis-default); 4: oa_thor.
INSTANTIATE_TEST_SUITE_P(Profiles, OctreeScoring, ::testing::Values(0, 1, 2, 3, 4));

}  // namespace
}  // namespace sightline::camera
