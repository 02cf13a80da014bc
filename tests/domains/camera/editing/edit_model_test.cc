// Editing costs on footage made by hand (a cut across the line, a jump cut, a clean cut, a
// too-short shot), and the chain solver's optimum of small real edits against bnb and
// brute force (grid).
#include "sightline/domains/camera/editing/edit_model.h"

#include <gtest/gtest.h>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/editing/editor.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/solvers/registry.h"

namespace sightline::camera {
namespace {

Scene scene_of(const std::string& name, const char* text) {
  return parse_scene(csp::parse_yaml(text, name));
}

// ann and bob face each other on the x axis; ann speaks to bob for 10 s.
const char* kTwoPeople = R"(name: two
actors:
  - name: ann
    trajectory:
      - {t: 0, position: [-1, 0, 0], yaw: 90}
      - {t: 10, position: [-1, 0, 0], yaw: 90}
  - name: bob
    trajectory:
      - {t: 0, position: [1, 0, 0], yaw: 270}
      - {t: 10, position: [1, 0, 0], yaw: 270}
script:
  - {t: [0, 10], speaker: ann, to: bob}
)";

CameraPose looking(Eigen::Vector3d from, Eigen::Vector3d at) {
  CameraPose p;
  p.position = from;
  p.look_at = at;
  return p;
}

// Footage of four shots of ann, each take the same at every slot: A in front of the line
// (z > 0), B behind it (across the line from A), C 9 degrees from A (a jump cut from A),
// D 45 degrees from A on A's side (a clean cut).
Footage hand_footage(std::size_t slots) {
  Footage f;
  f.start = 0;
  f.slot_seconds = 0.25;
  f.end = 0.25 * static_cast<double>(slots - 1);
  f.people = {"ann", "bob"};
  const Eigen::Vector3d ann(-1, 1.5, 0);
  const std::vector<CameraPose> poses = {looking(ann + Eigen::Vector3d(0, 0, 3), ann),
                                         looking(ann + Eigen::Vector3d(0, 0, -3), ann),
                                         looking(ann + Eigen::Vector3d(0.5, 0, 3.2), ann),
                                         looking(ann + Eigen::Vector3d(3, 0, 3), ann)};
  for (const char* name : {"A", "B", "C", "D"}) {
    CandidateShot c;
    c.name = name;
    c.idiom = Idiom::kMedium;
    c.subject = "ann";
    f.candidates.push_back(c);
  }
  for (std::size_t i = 0; i < slots; ++i) {
    f.slot_times.push_back(0.25 * static_cast<double>(i));
    std::vector<Take> takes;
    for (const CameraPose& pose : poses) {
      Take t;
      t.pose = pose;
      t.feasible = true;
      t.satisfaction = 1;
      t.people = {{true, true, 0.5}, {true, true, 0.5}};
      t.subject_size = 0.5;
      takes.push_back(t);
    }
    f.takes.push_back(takes);
  }
  return f;
}

TEST(EditCosts, CutsAcrossTheLineJumpCutsAndCleanCutsCostWhatTheRulesSay) {
  const Scene scene = scene_of("edit_costs_two.yaml", kTwoPeople);
  const Footage f = hand_footage(9);
  EditWeights w;
  w.min_shot_seconds = 1;
  const EditCosts c = edit_costs(scene, f, w, ContinuityRules{});
  ASSERT_EQ(c.min_slots, 4u);
  const std::size_t A = 0, B = 1, C = 2, D = 3, K = 4;
  for (std::size_t i = 1; i < 9; ++i) {
    EXPECT_DOUBLE_EQ(c.change[i][A * K + A], 0);               // holding a shot
    EXPECT_DOUBLE_EQ(c.change[i][A * K + B], w.cut + w.crossing);  // across the line
    EXPECT_DOUBLE_EQ(c.change[i][A * K + C], w.cut + w.jump_cut);  // 9 degrees, same size
    EXPECT_DOUBLE_EQ(c.change[i][A * K + D], w.cut);               // 45 degrees, same side
    EXPECT_DOUBLE_EQ(c.change[i][B * K + D], w.cut + w.crossing);
    EXPECT_FALSE(c.jumps[i][A]);
  }
  // Everyone shown from the front and large: no script cost; the first second is the
  // opening, where a shot that is not an establishing one misfits by 0.3.
  EXPECT_DOUBLE_EQ(c.unary[0][A].script, 0);
  EXPECT_DOUBLE_EQ(c.unary[0][A].relevance, 0.3);
  EXPECT_DOUBLE_EQ(c.unary[5][A].relevance, 0);
}

TEST(EditCosts, AShotShorterThanTheMinimumCostsItsShortfall) {
  const Scene scene = scene_of("edit_costs_short.yaml", kTwoPeople);
  const Footage f = hand_footage(9);
  EditWeights w;
  w.min_shot_seconds = 1;  // 4 slots
  const EditCosts c = edit_costs(scene, f, w, ContinuityRules{});
  const auto problem = edit_problem(c, w, "short");
  // A for 4 slots, D for 1, A for 4: two clean cuts and one shot of 1 slot out of 4.
  const std::vector<double> one_slot = {0, 0, 0, 0, 3, 0, 0, 0, 0};
  const double opening = 4 * 0.3;
  EXPECT_NEAR(problem->score(one_slot).soft, opening + 2 * w.cut + w.short_shot * 3.0 / 4, 1e-12);
  const std::vector<double> long_enough = {0, 0, 0, 0, 3, 3, 3, 3, 3};
  EXPECT_NEAR(problem->score(long_enough).soft, opening + w.cut, 1e-12);
  // The exact solver holds one shot (no cut at all is cheapest here).
  auto chain = solvers::SolverRegistry::global().create("chain");
  const auto r = chain->solve(*problem, one_slot);
  EXPECT_NEAR(r.cost(), opening, 1e-12);
}

// A short conversation, three lines, edited on one-second slots among its first few
// candidate shots: small enough for bnb and brute force.
const char* kShort = R"(name: short
actors:
  - name: ann
    trajectory:
      - {t: 0, position: [-1, 0, 0], yaw: 90}
      - {t: 7, position: [-1, 0, 0], yaw: 90}
  - name: bob
    trajectory:
      - {t: 0, position: [1, 0, 0], yaw: 270}
      - {t: 7, position: [1, 0, 0], yaw: 270}
boxes:
  - {name: post, min: [2, 0, 1.5], max: [2.3, 3, 1.8]}
script:
  - {t: [0, 2.5], speaker: ann, to: bob}
  - {t: [2.5, 5], speaker: bob, to: ann}
  - {t: [5, 7], speaker: ann, to: bob}
)";

TEST(EditModel, TheChainOptimumEqualsBnbAndBruteForceOnSmallEdits) {
  const Scene scene = scene_of("edit_short.yaml", kShort);
  std::vector<CandidateShot> all = candidate_shots(scene);
  for (const std::size_t count : {3u, 5u}) {
    for (const double min_shot : {0.0, 2.0}) {
      std::vector<CandidateShot> some;
      // Mirror forms of medium and two-shot, and the establishing shot: cuts across the
      // line are among the choices.
      for (const CandidateShot& c : all) {
        if (some.size() < count && (c.idiom == Idiom::kMedium || c.idiom == Idiom::kTwoShot ||
                                    c.idiom == Idiom::kEstablishing)) {
          some.push_back(c);
        }
      }
      FootageOptions options;
      options.slot_seconds = 1;
      const Footage f = film_footage(scene, some, options);
      EditWeights w;
      w.min_shot_seconds = min_shot;
      const EditCosts c = edit_costs(scene, f, w, ContinuityRules{});
      const auto problem = edit_problem(c, w, "short edit");
      ASSERT_EQ(problem->num_variables(), 7u);
      auto& registry = solvers::SolverRegistry::global();
      const auto start = problem->default_assignment();
      const auto chain = registry.create("chain")->solve(*problem, start);
      const auto bnb = registry.create("bnb")->solve(*problem, start);
      const auto grid = registry.create("grid")->solve(*problem, start);
      ASSERT_EQ(chain.stop, solvers::StopReason::kProvenOptimal);
      ASSERT_EQ(bnb.stop, solvers::StopReason::kProvenOptimal);
      EXPECT_NEAR(chain.cost(), bnb.cost(), 1e-9) << count << " shots, min " << min_shot;
      EXPECT_NEAR(chain.cost(), grid.cost(), 1e-9) << count << " shots, min " << min_shot;
      // The greedy editor is an edit of the same model: never better than the optimum.
      const std::vector<std::size_t> greedy = greedy_edit(c, w);
      const std::vector<double> g(greedy.begin(), greedy.end());
      EXPECT_GE(problem->score(g).soft, chain.cost() - 1e-9);
    }
  }
}

}  // namespace
}  // namespace sightline::camera
