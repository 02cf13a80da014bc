// The anticipation pieces on their own: MotionPrediction (never inside a wall, the turn
// rate, the path lookahead, movers forecast or read), FutureVisibleConstraint against a
// brute-force weighted count written here (own slab test, own mover boxes), the profile's
// `anticipation:` and `cuts:` blocks and their errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/camera_problem.h"
#include "sightline/domains/camera/constraints/future_visibility.h"
#include "sightline/domains/camera/motion_prediction.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/experiments/runs/independent_check.h"

namespace sightline::camera {
namespace {

using Eigen::Vector3d;

// The test's sight-line judge, independent of the camera domain's queries
// (experiments/runs/independent_check.h), for one box.
bool slab_meets(const Vector3d& a, const Vector3d& b, const Vector3d& lo, const Vector3d& hi) {
  return experiments::segment_blocked({{lo, hi}}, a, b);
}

bool inside(const Vector3d& p, const Vector3d& lo, const Vector3d& hi) {
  return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
}

// A corridor along +z (walls at x = +-2), a wall across it at z = 10, and one mover, a
// 1 x 2 x 1 cart crossing along x at 2 m/s, at z = 4, from x = -6 (t = 0) to x = 6 (t = 6).
Scene corridor(const std::vector<Keyframe>& keys) {
  std::vector<SolidBox> solids = {{"west", {{-2.2, 0, -5}, {-2, 3, 12}}, {}},
                                  {"east", {{2, 0, -5}, {2.2, 3, 12}}, {}},
                                  {"end", {{-2, 0, 10}, {2, 3, 10.3}}, {}}};
  Scene scene("corridor", std::move(solids), {}, {}, Trajectory(keys));
  scene.set_movers({Mover("cart", {1, 2, 1}, {{0, {-6, 0, 4}}, {6, {6, 0, 4}}})});
  return scene;
}

CharacterState state(double t, Vector3d at, double yaw, Vector3d v) {
  CharacterState s;
  s.t = t;
  s.position = at;
  s.yaw = yaw;
  s.velocity = v;
  return s;
}

TEST(MotionPrediction, WalksOnAtTheCurrentVelocityAndStopsShortOfTheWallAhead) {
  const Scene scene = corridor({{0, {0, 0, 0}, 0}, {10, {0, 0, 9.5}, 0}});
  Anticipation a;
  a.lookahead = Lookahead::kMotion;
  a.horizon = 2.0;
  a.samples = 4;
  MotionPrediction p(scene, a);
  p.update(state(0, {0, 0, 8}, 0, {0, 0, 1.5}));  // 2 m from the end wall, 1.5 m/s
  ASSERT_EQ(p.size(), 4);
  EXPECT_NEAR(p.sample(0).look_at.z(), 8.75, 1e-9);  // 0.5 s: 0.75 m on
  EXPECT_NEAR(p.sample(1).look_at.z(), 9.5, 1e-9);
  // 1.5 s would be 10.25, through the wall at z = 10: it stops kWallMargin short.
  // (From the last step that was clear, so at most one step's length, 0.05 m, nearer.)
  EXPECT_LE(p.sample(2).look_at.z(), 10 - MotionPrediction::kWallMargin + 0.05 + 1e-9);
  EXPECT_GE(p.sample(2).look_at.z(), 10 - MotionPrediction::kWallMargin - 1e-9);
  EXPECT_EQ(p.sample(3).look_at, p.sample(2).look_at);  // stopped there
  for (int k = 0; k < p.size(); ++k) {
    EXPECT_NEAR(p.sample(k).look_at.y(), 1.5, 1e-12);
    EXPECT_NEAR(p.sample(k).weight, std::exp(-p.sample(k).ahead / a.decay), 1e-12);
  }
}

TEST(MotionPrediction, FollowsTheTurnRateAndIsNeverInsideGeometry) {
  const Scene scene = corridor({{0, {0, 0, 0}, 0}, {10, {0, 0, 9.5}, 0}});
  Anticipation a;
  a.lookahead = Lookahead::kMotion;
  a.horizon = 1.0;
  a.samples = 8;
  MotionPrediction p(scene, a);
  std::mt19937_64 rng(3);
  // Moving: a character standing still while turning sets off instead (the next test).
  std::uniform_real_distribution<double> x(-1.8, 1.8), z(-4, 9.8), yaw(0, 360),
      speed(MotionPrediction::kStillSpeed, 6);
  for (int trial = 0; trial < 300; ++trial) {
    const double y0 = yaw(rng), turn = std::uniform_real_distribution<double>(-90, 90)(rng);
    const Vector3d at(x(rng), 0, z(rng));
    const Vector3d v = speed(rng) * facing_from_yaw(y0);
    p.update(state(2 * trial, at, y0, v));
    p.update(state(2 * trial + 0.1, at, y0 + 0.1 * turn, v));  // turning at `turn` deg/s
    EXPECT_NEAR(p.turn_rate(), std::clamp(turn, -MotionPrediction::kMaxTurnRate,
                                          MotionPrediction::kMaxTurnRate), 1e-6);
    Vector3d previous = scene.character().look_at(at);
    for (int k = 0; k < p.size(); ++k) {
      const Vector3d& q = p.sample(k).look_at;
      for (const SolidBox& s : scene.solids()) {
        ASSERT_FALSE(inside(q, s.box.min, s.box.max)) << "trial " << trial << " sample " << k;
      }
      // Moving no faster than the character does.
      EXPECT_LE((q - previous).norm(), v.norm() * a.horizon / a.samples + 1e-9);
      previous = q;
    }
  }
  // A known answer in the open: at 1 m/s turning 90 deg/s, after 1 s the point is on the
  // circle of radius 1/(pi/2) m: (r, 0, r) from the start for a walk along +z turning to +x.
  const Scene open("open", {}, {}, {}, Trajectory({{0, {0, 0, 0}, 0}}));
  MotionPrediction q(open, a);
  q.update(state(0, {0, 0, 0}, 0, {0, 0, 1}));
  q.update(state(0.1, {0, 0, 0}, 9, {0, 0, 1}));
  const double r = 2 / 3.14159265358979;
  const Vector3d end = q.sample(q.size() - 1).look_at - Vector3d(0, 1.5, 0);
  EXPECT_NEAR(end.x(), r, 0.03);  // Euler steps of 1/30 s: close, not exact
  EXPECT_NEAR(end.z(), r, 0.03);
}

// Standing and turning on the spot after walking: she sets off at her last pace, along her
// facing turned kSetOffLead seconds further at her turn rate (at most 90 degrees), straight
// on. Worked out by hand here: 1.5 m/s, yaw 0 -> 30 in 0.1 s (300 deg/s): heading 60.
TEST(MotionPrediction, SetsOffTheWaySheFacesWhenSheTurnsOnTheSpotAfterWalking) {
  const Scene open("open", {}, {}, {}, Trajectory({{0, {0, 0, 0}, 0}}));
  Anticipation a;
  a.lookahead = Lookahead::kMotion;
  a.horizon = 1.0;
  a.samples = 4;
  const Vector3d at(0, 0, 3), look = at + Vector3d(0, 1.5, 0);
  const double lead = MotionPrediction::kSetOffLead;
  ASSERT_NEAR(lead, 0.1, 1e-12);  // the worked answers below assume it
  {
    MotionPrediction p(open, a);
    p.update(state(0, {0, 0, 0}, 0, {0, 0, 1.5}));  // walking along +z
    p.update(state(1.9, at, 0, Vector3d::Zero()));  // stopped
    p.update(state(2.0, at, 30, Vector3d::Zero()));  // turning at 300 deg/s
    const Vector3d heading = facing_from_yaw(60);
    for (int k = 0; k < p.size(); ++k) {
      EXPECT_LT((p.sample(k).look_at - (look + 1.5 * p.sample(k).ahead * heading)).norm(), 1e-9)
          << "sample " << k;
    }
  }
  {
    MotionPrediction p(open, a);  // 20 degrees in 1/60 s: 1200 deg/s, a lead of 90 at most
    p.update(state(0, {0, 0, 0}, 0, {0, 0, 2}));
    p.update(state(1.0, at, 100, Vector3d::Zero()));
    p.update(state(1.0 + 1.0 / 60, at, 80, Vector3d::Zero()));
    const Vector3d end = look + 2 * a.horizon * facing_from_yaw(350);
    EXPECT_LT((p.sample(p.size() - 1).look_at - end).norm(), 1e-9);
  }
  {
    MotionPrediction p(open, a);  // a snap: 60 degrees in one frame, set off as she now faces
    p.update(state(0, {0, 0, 0}, 0, {0, 0, 2}));
    p.update(state(1.0, at, 200, Vector3d::Zero()));
    p.update(state(1.0 + 1.0 / 60, at, 140, Vector3d::Zero()));
    const Vector3d end = look + 2 * a.horizon * facing_from_yaw(140);
    EXPECT_LT((p.sample(p.size() - 1).look_at - end).norm(), 1e-9);
  }
  {
    MotionPrediction p(open, a);  // standing without turning: she stays
    p.update(state(0, {0, 0, 0}, 0, {0, 0, 1.5}));
    p.update(state(1.9, at, 10, Vector3d::Zero()));
    p.update(state(2.0, at, 10 + 0.1 * (MotionPrediction::kSetOffTurnRate - 1), Vector3d::Zero()));
    for (int k = 0; k < p.size(); ++k) EXPECT_EQ(p.sample(k).look_at, look);
  }
  {
    MotionPrediction p(open, a);  // last moved longer ago than kPaceMemory: she stays
    p.update(state(0, {0, 0, 0}, 0, {0, 0, 1.5}));
    const double later = MotionPrediction::kPaceMemory + 0.5;
    p.update(state(later, at, 0, Vector3d::Zero()));
    p.update(state(later + 0.1, at, 30, Vector3d::Zero()));
    for (int k = 0; k < p.size(); ++k) EXPECT_EQ(p.sample(k).look_at, look);
  }
  {
    // In the corridor, turning toward a wall: never inside it.
    const Scene scene = corridor({{0, {0, 0, 0}, 0}, {10, {0, 0, 9.5}, 0}});
    MotionPrediction p(scene, a);
    p.update(state(0, {0, 0, 0}, 0, {0, 0, 5}));
    p.update(state(1.0, {1.5, 0, 8}, 60, Vector3d::Zero()));
    p.update(state(1.1, {1.5, 0, 8}, 90, Vector3d::Zero()));
    for (int k = 0; k < p.size(); ++k) {
      for (const SolidBox& b : scene.solids()) {
        EXPECT_FALSE(inside(p.sample(k).look_at, b.box.min, b.box.max)) << "sample " << k;
      }
      EXPECT_LT(p.sample(k).look_at.x(), 2.0);  // short of the east wall's face
    }
    EXPECT_GT(p.sample(0).look_at.x(), 1.5);  // it did set off, toward +x
  }
}

TEST(MotionPrediction, PathLookaheadReadsTheTrajectoryAndTheMoversKeyframes) {
  const Scene scene = corridor({{0, {0, 0, 0}, 0}, {2, {0, 0, 2}, 0}, {4, {1, 0, 2}, 90}});
  Anticipation a;
  a.lookahead = Lookahead::kPath;
  a.horizon = 2.0;
  a.samples = 4;
  MotionPrediction p(scene, a);
  p.update(scene.character_at(1.5));
  for (int k = 0; k < p.size(); ++k) {
    const double t = 1.5 + p.sample(k).ahead;
    EXPECT_EQ(p.sample(k).look_at,
              scene.character().look_at(scene.trajectory().state_at(t).position));
    EXPECT_NEAR(p.geometry(k).time(), t, 1e-12);
    EXPECT_NEAR(p.geometry(k).mover_boxes()[0].centre().x(), -6 + 2 * t, 1e-9);
  }
  // Motion: the cart goes on at its current velocity (2 m/s along x) from where it is.
  a.lookahead = Lookahead::kMotion;
  MotionPrediction m(scene, a);
  m.update(scene.character_at(1.5));
  for (int k = 0; k < m.size(); ++k) {
    EXPECT_NEAR(m.geometry(k).mover_boxes()[0].centre().x(), -3 + 2 * m.sample(k).ahead, 1e-9);
  }
  a.lookahead = Lookahead::kNone;
  MotionPrediction none(scene, a);
  none.update(scene.character_at(1.5));
  EXPECT_EQ(none.size(), 0);
}

TEST(FutureVisibleConstraint, IsTheWeightedFractionOfPredictedPointsHiddenAtTheirTimes) {
  const Scene scene = corridor({{0, {0, 0, 0}, 0}, {8, {0, 0, 9}, 0}});
  for (Lookahead mode : {Lookahead::kMotion, Lookahead::kPath}) {
    Anticipation a;
    a.lookahead = mode;
    a.horizon = 1.5;
    a.samples = 6;
    MotionPrediction p(scene, a);
    const FutureVisibleConstraint c(0, 1, 2, p, 2.5);
    EXPECT_EQ(c.kind(), "camera.future_visible");
    EXPECT_FALSE(c.is_hard());
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> x(-1.9, 1.9), y(0.2, 4), z(-4, 11.9), t(0, 7.5);
    int some_hidden = 0, some_partly = 0;
    for (int trial = 0; trial < 400; ++trial) {
      const double now = t(rng);
      const CharacterState s = scene.character_at(now);
      p.update(s);
      const double cam[3] = {x(rng), y(rng), z(rng)};
      const Vector3d camera(cam[0], cam[1], cam[2]);
      // Brute force: each predicted point, every static box and the cart where the test
      // puts it at that sample's time.
      double hidden = 0, total = 0;
      for (int k = 0; k < p.size(); ++k) {
        const double ahead = p.sample(k).ahead;
        const double w = std::exp(-ahead / a.decay);
        total += w;
        bool blocked = false;
        for (const SolidBox& b : scene.solids()) {
          blocked = blocked || slab_meets(camera, p.sample(k).look_at, b.box.min, b.box.max);
        }
        // The cart: read ahead (path) or carried on at its velocity at `now` (motion).
        const double cart_x = mode == Lookahead::kPath
                                  ? std::clamp(-6 + 2 * (now + ahead), -6.0, 6.0)
                                  : std::clamp(-6 + 2 * now, -6.0, 6.0) +
                                        (now < 6 ? 2 * ahead : 0.0);
        blocked = blocked || slab_meets(camera, p.sample(k).look_at, {cart_x - 0.5, 0, 3.5},
                                        {cart_x + 0.5, 2, 4.5});
        if (blocked) hidden += w;
      }
      const double expected = hidden / total;
      ASSERT_NEAR(c.violation(cam), expected, 1e-12) << "trial " << trial;
      double gradient[3] = {7, 7, 7};
      EXPECT_EQ(c.violation_and_gradient(cam, gradient), c.violation(cam));
      EXPECT_EQ(gradient[0], 0);
      EXPECT_EQ(gradient[2], 0);
      some_hidden += expected == 1;
      some_partly += expected > 0 && expected < 1;
    }
    EXPECT_GT(some_hidden, 0);  // the test covers all three cases
    EXPECT_GT(some_partly, 0);
  }
}

TEST(CameraProblem, AddsFutureVisibilityOnlyWhenTheProfileLooksAhead) {
  const Scene scene = corridor({{0, {0, 0, 0}, 0}, {8, {0, 0, 9}, 0}});
  CameraProfile reactive;
  EXPECT_FALSE(CameraProblem(scene, reactive).ids().future_visible.has_value());
  const CameraProfile anticipating = preset_profile("anticipating");
  EXPECT_EQ(anticipating.anticipation.lookahead, Lookahead::kMotion);
  EXPECT_FALSE(anticipating.cuts.leave_enclosed);
  EXPECT_FALSE(anticipating.cuts.backing_up);
  EXPECT_TRUE(anticipating.cuts.smooth_escape);
  EXPECT_GT(anticipating.anticipation.plan_seconds, 0);  // motion planned over the horizon
  EXPECT_GT(anticipating.anticipation.max_jerk, 0);      // its changes of acceleration bounded
  EXPECT_TRUE(anticipating.cuts.cut_ahead);  // shut out by a mover: one forced cut, no escapes
  EXPECT_TRUE(preset_profile("anticipating-path").cuts.cut_ahead);
  // A stuck cut only with no other cut in the last minute: room for a forced one, so
  // never more than 2 cuts a minute for being late.
  EXPECT_EQ(anticipating.cuts.stuck_per_minute, 1);
  EXPECT_EQ(preset_profile("thesis").cuts.stuck_per_minute, 0);  // the thesis: no limit
  CameraProblem cp(scene, anticipating);
  ASSERT_TRUE(cp.ids().future_visible.has_value());
  const csp::Constraint& c = cp.problem().constraint(*cp.ids().future_visible);
  EXPECT_EQ(c.kind(), "camera.future_visible");
  EXPECT_EQ(c.weight(), anticipating.anticipation.weight);
  cp.set_frame(scene.character_at(2), {0, 2.5, -2}, 1.0 / 60);
  EXPECT_EQ(cp.prediction().size(), anticipating.anticipation.samples);
  EXPECT_DOUBLE_EQ(cp.scene_at_time().time(), 2);
  // The thesis profiles keep their cuts and look no further than now.
  const CameraProfile thesis = preset_profile("thesis-default");
  EXPECT_EQ(thesis.anticipation.lookahead, Lookahead::kNone);
  EXPECT_EQ(thesis.anticipation.plan_seconds, 0);
  EXPECT_EQ(thesis.anticipation.max_jerk, 0);
  EXPECT_EQ(thesis.cuts, CutPolicy{});
}

// SceneAtTime's grouped movers answer as every mover tested one by one would: many movers
// spread over a wide area, random segments and points, at times set and extrapolated.
TEST(SceneAtTime, GroupedMoversAnswerLikeTestingEveryMover) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-40, 40), s(0.3, 3), t(0, 10);
  std::vector<SolidBox> solids = {{"wall", {{-5, 0, -5}, {5, 3, -4.8}}, {}}};
  std::vector<Mover> movers;
  for (int i = 0; i < 23; ++i) {
    const Vector3d from(u(rng), 0, u(rng)), to(u(rng), 0, u(rng));
    movers.emplace_back("m", Vector3d(s(rng), s(rng), s(rng)),
                        std::vector<MoverKeyframe>{{0, from}, {10, to}});
  }
  Scene scene("many", std::move(solids), {}, {}, Trajectory({{0, {0, 0, 0}, 0}}));
  scene.set_movers(movers);
  SceneAtTime at(scene);
  for (int trial = 0; trial < 300; ++trial) {
    const double now = t(rng), ahead = 0.5 * (trial % 3);
    if (ahead == 0) {
      at.set_time(now);
    } else {
      at.set_time_extrapolated(now, ahead);
    }
    std::vector<std::pair<Vector3d, Vector3d>> boxes;  // the test's own mover boxes
    for (const Mover& m : movers) {
      const auto& k = m.path();
      const Vector3d v = (k[1].position - k[0].position) / 10;
      const Vector3d base = k[0].position + (now + ahead) * v;
      boxes.push_back({base - Vector3d(m.size().x() / 2, 0, m.size().z() / 2),
                       base + Vector3d(m.size().x() / 2, m.size().y(), m.size().z() / 2)});
    }
    for (int q = 0; q < 20; ++q) {
      const Vector3d a(u(rng), std::abs(u(rng)) / 10, u(rng)), b(u(rng), std::abs(u(rng)) / 10, u(rng));
      bool blocked = slab_meets(a, b, {-5, 0, -5}, {5, 3, -4.8});
      double nearest = INFINITY;
      bool in_mover = false;
      for (const auto& [lo, hi] : boxes) {
        blocked = blocked || slab_meets(a, b, lo, hi);
        nearest = std::min(nearest, Aabb{lo, hi}.signed_distance(a));
        in_mover = in_mover || inside(a, lo, hi);
      }
      ASSERT_EQ(at.line_of_sight(a, b), !blocked) << trial;
      ASSERT_EQ(at.first_hit(a, b).has_value(), blocked) << trial;
      const double static_d = scene.clearance(a, 2.0);
      EXPECT_NEAR(at.clearance(a, 2.0), std::min({static_d, nearest, 2.0}), 1e-12);
      EXPECT_EQ(at.open_at(a), scene.open_at(a) && !in_mover);
      const auto n = at.nearest_surface(a, 2.0);
      const double expected = std::min(static_d, nearest);
      ASSERT_EQ(n.has_value(), expected < 2.0);
      if (n) {
        EXPECT_NEAR(n->signed_distance, expected, 1e-12);
      }
    }
  }
}

CameraProfile parse(const std::string& text) {
  return parse_profile(csp::parse_yaml(text, "profile.yaml"));
}

TEST(CameraProfile, ReadsTheAnticipationAndCutsBlocks) {
  const CameraProfile p = parse(
      "anticipation: {lookahead: path, horizon: 1.5, samples: 6, weight: 4, decay: 0.8,\n"
      "               plan_seconds: 0.6, max_jerk: 40}\n"
      "cuts: {leave_enclosed: false, backing_up: true, stuck: false, smooth_escape: true,\n"
      "       cut_ahead: true}\n");
  EXPECT_EQ(p.anticipation.lookahead, Lookahead::kPath);
  EXPECT_EQ(p.anticipation.horizon, 1.5);
  EXPECT_EQ(p.anticipation.samples, 6);
  EXPECT_EQ(p.anticipation.weight, 4);
  EXPECT_EQ(p.anticipation.decay, 0.8);
  EXPECT_EQ(p.anticipation.plan_seconds, 0.6);
  EXPECT_EQ(p.anticipation.max_jerk, 40);
  EXPECT_FALSE(p.cuts.leave_enclosed);
  EXPECT_TRUE(p.cuts.backing_up);
  EXPECT_FALSE(p.cuts.stuck);
  EXPECT_TRUE(p.cuts.smooth_escape);
  EXPECT_TRUE(p.cuts.cut_ahead);
}

TEST(CameraProfile, BadAnticipationValuesNameTheLineAndWhatWasExpected) {
  const struct {
    const char* yaml;
    const char* message;
  } cases[] = {
      {"name: x\nanticipation: {lookahead: sideways}\n", "none, motion or path"},
      {"name: x\nanticipation:\n  samples: 0\n", "anticipation.samples"},
      {"name: x\nanticipation:\n  samples: 2.5\n", "whole number"},
      {"name: x\nanticipation:\n  samples: 9\n", "anticipation.samples"},
      {"name: x\nanticipation:\n  horizon: -1\n", "anticipation.horizon"},
      {"name: x\nanticipation:\n  decay: 0\n", "anticipation.decay"},
      {"name: x\nanticipation:\n  plan_seconds: -0.5\n", "profile.yaml:3"},
      {"name: x\nanticipation:\n  plan_seconds: 6\n", "anticipation.plan_seconds"},
      {"name: x\nanticipation:\n  plan_seconds: soon\n", "anticipation.plan_seconds"},
      {"name: x\nanticipation:\n  max_jerk: -1\n", "profile.yaml:3"},
      {"name: x\nanticipation:\n  max_jerk: 1e6\n", "anticipation.max_jerk"},
      {"name: x\nanticipation:\n  wieght: 1\n", "wieght"},
      {"name: x\ncuts:\n  stuck: maybe\n", ""},
      {"name: x\ncuts:\n  cut_ahead: soon\n", "profile.yaml:3"},
      {"name: x\ncuts:\n  stuck_per_minute: 17\n", "stuck_per_minute in [0, 16]"},
      {"name: x\ncuts:\n  stuck_per_minute: 1.5\n", "profile.yaml:3"},
      // cut_ahead acts only where the planner's escapes would: refused without them.
      {"name: x\ncuts: {smooth_escape: true, cut_ahead: true}\n", "cuts.cut_ahead needs"},
      {"name: x\nanticipation: {lookahead: motion}\ncuts: {cut_ahead: true}\n",
       "smooth_escape: true"},
      {"name: x\nanticipation: {lookahead: motion, plan_seconds: 0}\n"
       "cuts: {smooth_escape: true, cut_ahead: true}\n",
       "anticipation.plan_seconds > 0"},
  };
  for (const auto& c : cases) {
    try {
      parse(c.yaml);
      ADD_FAILURE() << "accepted: " << c.yaml;
    } catch (const csp::InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("profile.yaml:"), std::string::npos) << what;
      EXPECT_NE(what.find(c.message), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace sightline::camera
