#include "sightline/domains/camera/composition/shot_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sightline/domains/camera/composition/composition_problem.h"
#include "sightline/domains/camera/composition/shot_search_framing.h"
#include "sightline/domains/camera/composition/toric_framing.h"

namespace sightline::camera {

// What a solve works in, kept between solves so a tracking camera's frames allocate nothing
// once the vectors have grown.
struct ShotSearchScratch {
  struct Candidate {
    csp::Score score;
    shot_search_detail::Point x;
    bool partial = false;  // scored without the scene's terms: score is a lower bound
  };
  std::vector<Candidate> candidates;
  std::vector<Candidate> sorted;  // candidates, best first
  std::vector<csp::Score> best_few;           // the best full scores, up to `keep`
  std::vector<std::uint32_t> order;
  std::vector<std::pair<int, shot_search_detail::Vantage>> vantages;
  shot_search_detail::Vantage group;
  std::vector<double> bearings;
  shot_search_detail::FramingStorage framing;
};

namespace {

using shot_search_detail::Framing;
using shot_search_detail::from_bearing;
using shot_search_detail::kDegrees;
using shot_search_detail::kDims;
using shot_search_detail::kRadians;
using shot_search_detail::Point;
using shot_search_detail::Vantage;
using shot_search_detail::vantage_into;

double halton(std::uint64_t index, std::uint64_t base) {
  double f = 1, r = 0;
  while (index > 0) {
    f /= static_cast<double>(base);
    r += f * static_cast<double>(index % base);
    index /= base;
  }
  return r;
}

}  // namespace

const solvers::OptionSchema<ShotSearch::Options>& ShotSearch::Options::schema() {
  static const solvers::OptionSchema<Options> schema = [] {
    solvers::OptionSchema<Options> s;
    s.integer("samples", &Options::samples, "Halton positions sampled in the region (>= 0)", 0);
    s.integer("keep", &Options::keep, "candidates refined by the compass search (>= 1)", 1);
    s.real("min_step", &Options::min_step,
           "step (metres, degrees) below which the refinement stops (> 0)", 1e-9);
    s.boolean("global", &Options::global,
              "search the whole region (false: refine the start only, for tracking)");
    s.boolean("hold_position", &Options::hold_position,
              "with global false: refine the start's aim, fov and roll only, its position held");
    return s;
  }();
  return schema;
}

std::string ShotSearch::Options::validate() const {
  return hold_position && global ? "hold_position needs global=false (it refines a start's view)" : "";
}

ShotSearch::ShotSearch(std::string name, Options options) : name_(std::move(name)), options_(options) {}
ShotSearch::~ShotSearch() = default;

std::string ShotSearch::unsuitable_reason(const csp::Problem& problem) const {
  return composition_of(problem) ? "" : "needs a composition problem (a scene's shot: block)";
}

void ShotSearch::solve_into(const csp::Problem& problem, std::span<const double> start,
                            const solvers::SolveContext& context, solvers::SolverResult& result) {
  const CompositionProblem* owner = composition_of(problem);
  if (!owner) throw std::invalid_argument(name_ + ": " + unsuitable_reason(problem));
  solvers::Budget budget(context.limits, 1);
  if (!scratch_) {
    // Room for the most candidates and angles a global solve makes with several people, so
    // the vectors stop growing after the first solves.
    scratch_ = std::make_unique<ShotSearchScratch>();
    scratch_->candidates.reserve(2048);
    scratch_->sorted.reserve(2048);
    scratch_->order.reserve(2048);
    scratch_->best_few.reserve(static_cast<std::size_t>(options_.keep) + 1);
    scratch_->bearings.reserve(64);
    scratch_->group.bearings.reserve(64);
    scratch_->group.elevations.reserve(64);
    scratch_->framing.placed.reserve(16);
  }
  ShotSearchScratch& scratch = *scratch_;
  Framing framing(problem, *owner, scratch.framing);
  const Shot& shot = owner->shot();
  auto clamp = [&](Point& x) {
    for (int k : {0, 1, 2, 5, 6}) x[k] = problem.domain(static_cast<csp::VariableId>(k)).clamp(x[k]);
  };
  const double fov = (shot.fov.lo + shot.fov.hi) / 2;
  const double roll = std::clamp(0.0, shot.roll.lo, shot.roll.hi);
  std::uint64_t evaluations = 0, iterations = 0;

  // 1-2. Candidates, each aimed and scored.
  auto& candidates = scratch.candidates;
  candidates.clear();
  // Only the best `keep` candidates are refined first: once that many are scored, one that
  // cannot be below the keep-th best is scored without its sight lines and clearance
  // (Framing::score_below), marked, and sorted after every fully scored one (its score a
  // lower bound: rescored before an anytime run refines it).
  const std::size_t keep = static_cast<std::size_t>(options_.keep);
  auto& best_few = scratch.best_few;  // the best `keep` full scores, best first
  best_few.clear();
  auto score_candidate = [&](const Point& x) {
    bool complete = true;
    const csp::Score s = best_few.size() < keep ? framing.score(x) : framing.score_below(x, best_few.back(), complete);
    ++evaluations;
    candidates.push_back({s, x, !complete});
    if (!complete) return;
    const auto at = std::upper_bound(best_few.begin(), best_few.end(), s,
                                     [](const csp::Score& a, const csp::Score& b) { return a.before(b); });
    if (best_few.size() < keep) {
      best_few.insert(at, s);
    } else if (at != best_few.end()) {
      best_few.insert(at, s);
      best_few.pop_back();
    }
  };
  // A candidate at p aimed at the targets (and, when several are wanted, a second one aimed
  // at `subject` alone: a shot that cannot hold them all may do best on one).
  // With a time limit, the candidates take at most 40% of it, so that the best of them
  // are refined: with several people there are more candidates than a 2 ms budget scores.
  const double candidate_seconds = 0.4 * context.limits.time_limit_seconds;
  auto candidates_done = [&] {
    return budget.exhausted(evaluations, iterations) ||
           (candidate_seconds > 0 && budget.elapsed_seconds() > candidate_seconds);
  };
  auto add = [&](const Eigen::Vector3d& p, const Eigen::Vector3d* subject = nullptr) {
    if (!candidates.empty() && candidates_done()) return;
    Point x{p.x(), p.y(), p.z(), 0, 0, fov, roll};
    clamp(x);
    framing.aim(x);
    score_candidate(x);
    // Someone the shot keeps out on screen: the view turned to each side to take them off it.
    std::array<double, 4> shift{};
    if (framing.shifts_away(x, 0.02, shift)) {
      for (int side = 0; side < 4 && !candidates_done(); ++side) {
        Point y = x;
        framing.turn(y, side, shift[static_cast<std::size_t>(side)]);
        score_candidate(y);
      }
    }
    if (subject == nullptr || framing.targets().size() < 2) return;
    const csp::Assignment& to_centre = framing.values(x);
    const double centre_yaw = to_centre[3], centre_pitch = to_centre[4] - x[4];
    const Eigen::Vector3d d = *subject - Eigen::Vector3d(x[0], x[1], x[2]);
    x[3] = signed_degrees(std::atan2(d.x(), d.z()) * kDegrees - (centre_yaw - x[3]));
    x[4] = std::atan2(d.y(), std::hypot(d.x(), d.z())) * kDegrees - centre_pitch;
    score_candidate(x);
  };
  if (start.size() == kDims) {
    // The start's own aim, as offsets from the direction to the centre.
    Point x{start[0], start[1], start[2], 0, 0, start[5], start[6]};
    clamp(x);
    const csp::Assignment& base = framing.values(x);
    x[3] = signed_degrees(start[3] - base[3]);
    x[4] = start[4] - base[4];
    score_candidate(x);
  }
  // Two subjects at screen points: the exact two-subject poses (toric_framing.h), coarsely.
  if (options_.global && !toric_) toric_ = std::make_unique<ToricFraming>("toric", ToricFraming::Options{32, 16});
  if (options_.global && toric_checked_ != &problem) {  // its reason is a string: asked once a problem
    toric_checked_ = &problem;
    toric_suits_ = toric_->unsuitable_reason(problem).empty();
  }
  if (options_.global && toric_suits_) {
    ToricFraming& toric = *toric_;
    solvers::SolveContext coarse;
    coarse.want_breakdown = false;
    if (context.limits.time_limit_seconds > 0) {
      coarse.limits.time_limit_seconds = context.limits.time_limit_seconds / 4;
    }
    toric.solve_into(problem, {}, coarse, toric_result_);
    evaluations += toric_result_.evaluations;
    if (toric_result_.message.empty()) {
      Point x{};
      std::copy(toric_result_.best.begin(), toric_result_.best.end(), x.begin());
      const csp::Assignment& base = framing.values(x);  // offsets from the centre's direction
      x[3] = signed_degrees(toric_result_.best[3] - (base[3] - x[3]));
      x[4] = toric_result_.best[4] - (base[4] - x[4]);
      score_candidate(x);
    }
  }
  // Around an aim point at `scale` times the vantage's distance, bearings (each with its
  // neighbours 15 degrees off) and elevations: all the bearings at one elevation before the
  // next, so that candidates a time limit stops early have looked all round (problems 140
  // and 164 of the benchmark, group shots).
  auto around = [&](const Eigen::Vector3d& aim, const Vantage& v, const Eigen::Vector3d* subject, double scale) {
    static constexpr double kAllBearings[] = {0, 45, 90, 135, 180, 225, 270, 315};
    static constexpr double kTwoElevations[] = {5, 20};
    std::vector<double>& bearings = scratch.bearings;
    bearings.clear();
    if (v.bearings.empty()) {
      bearings.assign(std::begin(kAllBearings), std::end(kAllBearings));
    } else {
      for (double b : v.bearings) bearings.insert(bearings.end(), {b, b - 15, b + 15});
    }
    const std::span<const double> elevations =
        v.elevations.empty() ? std::span<const double>(kTwoElevations) : std::span<const double>(v.elevations);
    for (double e : elevations) {
      for (double b : bearings) add(aim + scale * v.distance * from_bearing(b, e), subject);
    }
  };
  if (options_.global) {
    auto& vantages = scratch.vantages;
    vantages.resize(framing.targets().size());
    for (std::size_t i = 0; i < vantages.size(); ++i) {
      vantages[i].first = framing.targets()[i];
      vantage_into(*owner, vantages[i].first, fov, vantages[i].second);
    }
    // The group: centred on the targets' centre, far enough to hold them all.
    Vantage& group = scratch.group;
    group.bearings.clear();
    group.elevations.clear();
    double radius = 0;
    for (int t : framing.targets()) {
      const PersonAtTime& person = owner->world().people()[static_cast<std::size_t>(t)];
      radius = std::max(radius, (person.aim - framing.centre()).norm() + person.body.size().y() / 2);
    }
    group.distance = radius / std::tan(fov * kRadians / 2) * 1.2 + 1;
    for (const auto& [t, v] : vantages) {
      group.bearings.insert(group.bearings.end(), v.bearings.begin(), v.bearings.end());
      group.elevations.insert(group.elevations.end(), v.elevations.begin(), v.elevations.end());
    }
    // At the vantages' distances first, then 15% nearer, then 20% farther; at each, the
    // group's vantages and then each person's. With a short budget the candidates stop
    // early: every ring at one distance before any at the next reached the people's own
    // vantages of a group of four (2 ms: 3 more of problems 181-300 of the benchmark at
    // least as good as the particle swarm with 20 ms, 2 more of 61-180; before, only the
    // group's three distances were scored).
    for (double scale : {1.0, 0.85, 1.2}) {
      if (framing.targets().size() > 1) around(framing.centre(), group, nullptr, scale);
      for (const auto& [t, v] : vantages) {
        const Eigen::Vector3d& aim = owner->world().people()[static_cast<std::size_t>(t)].aim;
        around(aim, v, &aim, scale);
      }
    }
  }
  const Aabb& region = shot.region;
  if (candidates.empty()) add(region.centre());  // neither a start nor a global search
  for (std::int64_t i = 1; options_.global && i <= options_.samples; ++i) {
    const auto k = static_cast<std::uint64_t>(i);
    add(region.min + Eigen::Vector3d(halton(k, 2), halton(k, 3), halton(k, 5))
                         .cwiseProduct(region.max - region.min));
  }
  // Best first (fewer hard, then soft costs; those scored in part after all the others),
  // ties in the order added. Their indices are
  // sorted, in the scratch (std::stable_sort takes a buffer from the heap): a group's shot
  // makes well over a thousand candidates, which an insertion sort took a millisecond to
  // order.
  auto& order = scratch.order;
  order.resize(candidates.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (candidates[a].partial != candidates[b].partial) return candidates[b].partial;
    const csp::Score& sa = candidates[a].score;
    const csp::Score& sb = candidates[b].score;
    if (sa.before(sb)) return true;
    if (sb.before(sa)) return false;
    return a < b;
  });
  auto& sorted = scratch.sorted;
  sorted.clear();
  for (std::uint32_t i : order) sorted.push_back(candidates[i]);
  candidates.swap(sorted);

  csp::Score best = candidates.front().score;
  Point best_x = candidates.front().x;
  budget.note_best(evaluations);

  // 3. Compass search from a candidate, in place.
  const Eigen::Vector3d extent = region.max - region.min;
  const double position_step = std::max(0.05, 0.1 * extent.minCoeff());
  // Random poll directions (seeded: a solve is repeatable).
  std::mt19937_64 poll_rng(context.seed ^ 0x5d0bu);
  std::uniform_real_distribution<double> poll_unit(-1.0, 1.0);
  auto keep_best = [&](const csp::Score& score, const Point& x) {
    if (!score.better_than(best)) return;
    best = score;
    best_x = x;
    budget.note_best(evaluations);
  };
  // `polls`: random directions tried when no axis step pays, before the steps halve.
  auto refine = [&](csp::Score& score, Point& x, double scale, double min_step, int polls = 0) {
    const double move = options_.hold_position ? 0.0 : position_step * scale;
    std::array<double, kDims> step{move, move, move, 4 * scale, 4 * scale,
                                   shot.fov.fixed() ? 0.0 : 4.0 * scale,
                                   shot.roll.fixed() ? 0.0 : 4.0 * scale};
    // Plateaus are walked in the fine refinements only (those that poll): a coarse one is a
    // first look at a candidate, and walking its plateaus spends the budget on poses that
    // may not be kept.
    const bool on_plateaus = polls > 0 && framing.counts_framed();
    // x's framed_gap, once asked (kUnknown: not yet, or x has moved since).
    constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
    double x_gap = kUnknown;
    // x becomes y, scoring s, with y's framed_gap (kUnknown when not asked).
    auto take = [&](const csp::Score& s, const Point& y, double y_gap) {
      score = s;
      x = y;
      x_gap = y_gap;
      return true;
    };
    // Moves x to y (clamped into the domains) when y scores better, or the same (to the
    // tolerance of Score::better_than) with a smaller framed_gap: on the plateau of a count,
    // toward its next step.
    auto moved_to = [&](Point y) {
      clamp(y);
      if (y == x) return false;
      bool complete = false;
      csp::Score s = framing.score_below(y, score, complete);
      ++evaluations;
      if (complete && s.better_than(score)) return take(s, y, kUnknown);
      // A partial score is no more than the full one: when it is already worse, so is y.
      if (!on_plateaus || score.better_than(s)) return false;
      // Nothing partly framed at x (a shot met, or its counts at 0): no plateau to walk.
      if (std::isnan(x_gap)) x_gap = framing.framed_gap(x);
      if (!(x_gap > 0)) return false;
      if (!complete) {
        s = framing.score(y);
        ++evaluations;
        // Better only within Score::better_than's tolerance of a partial score that was not.
        if (s.better_than(score)) return take(s, y, kUnknown);
        if (score.better_than(s)) return false;
      }
      const double y_gap = framing.framed_gap(y);
      if (!(y_gap < x_gap - 1e-9)) return false;
      return take(s, y, y_gap);
    };
    // The last held axis move that paid (see below), as person x 6 + axis move; -1 when the
    // last move that paid was another.
    int last_held = -1;
    while (!budget.exhausted(evaluations, iterations)) {
      ++iterations;
      bool improved = false;
      const Point base = x;
      for (int k = 0; k < kDims; ++k) {
        if (step[static_cast<std::size_t>(k)] == 0) continue;
        for (double sign : {1.0, -1.0}) {
          Point y = x;
          y[static_cast<std::size_t>(k)] += sign * step[static_cast<std::size_t>(k)];
          if (moved_to(y)) {
            improved = true;
            break;
          }
        }
      }
      // Hooke and Jeeves' pattern move: the sweep's whole move once more, while it pays (a
      // narrow valley across the axes, as screen positions traded against an angle, is
      // followed in long strides instead of axis steps). Global searches only: a tracking
      // camera's frame refinement keeps to axis steps (with the pattern move, the camera
      // filming circling-dialogue lost the person circling in 2% of frames instead of 0).
      for (Point from = base; options_.global && improved && !budget.exhausted(evaluations, iterations);) {
        Point y;
        for (std::size_t k = 0; k < y.size(); ++k) y[k] = x[k] + (x[k] - from[k]);
        const Point was = x;
        if (!moved_to(y)) break;
        from = was;
      }
      keep_best(score, x);
      if (improved) {
        last_held = -1;
        continue;
      }
      // No axis step pays: a few random directions of the same size before the steps halve
      // (on a ridge between two properties' kinks only a diagonal move gains).
      // Every other poll then turns the view back so that one person placed on screen stays
      // where they are (their distance from their point unchanged): with two people placed,
      // the optimum often lies on the rim of one's flat zone while the other's point is
      // approached, a move that neither an axis step nor a random direction makes (problem
      // 11 of the benchmark: 0.9575 with any budget without it, 0.9581 with it).
      Eigen::Vector2d held;
      for (int d = 0; d < polls && !improved && !budget.exhausted(evaluations, iterations); ++d) {
        Point y = x, z = x;
        for (std::size_t k = 0; k < y.size(); ++k) {
          const double u = step[k] * poll_unit(poll_rng);
          y[k] += u;
          z[k] -= u;
        }
        const std::vector<std::size_t>& placed = framing.placed();
        if (d % 2 == 1 && !placed.empty()) {
          const std::size_t kept = placed[static_cast<std::size_t>(d / 2) % placed.size()];
          if (framing.screen_point(x, kept, held)) {
            for (Point* w : {&y, &z}) {
              clamp(*w);
              if (!framing.hold_on_screen(*w, kept, held)) *w = x;
            }
          }
        }
        improved = moved_to(y) || moved_to(z);
        if (improved) last_held = -1;
      }
      // And each position axis, both ways, turned back to hold each placed person: the
      // rim moves in a fixed set of directions (the random ones above may miss the one).
      const std::vector<std::size_t>& placed = framing.placed();
      for (std::size_t p = 0; polls > 0 && p < placed.size() && !improved; ++p) {
        if (!framing.screen_point(x, placed[p], held)) continue;
        for (int k = 0; k < 6 && !improved && !budget.exhausted(evaluations, iterations); ++k) {
          // Not straight back along the last one that paid: a re-hold is exact only to the
          // Newton steps' tolerance, and stepping an axis up and down, each re-hold scoring
          // 5e-8 to 1e-7 better, took 750 of problem 11's 2 ms evaluations.
          const int move = static_cast<int>(p) * 6 + k;
          if (last_held >= 0 && move == (last_held ^ 1)) continue;
          Point w = x;
          w[static_cast<std::size_t>(k / 2)] += (k % 2 == 0 ? 1 : -1) * step[static_cast<std::size_t>(k / 2)];
          clamp(w);
          improved = framing.hold_on_screen(w, placed[p], held) && moved_to(w);
          if (improved) last_held = move;
        }
      }
      keep_best(score, x);
      if (improved) continue;
      double largest = 0;
      for (double& s : step) {
        s /= 2;
        largest = std::max(largest, s);
      }
      if (largest < min_step) break;
    }
  };
  // Coarsely (to 5 cm and 0.05 degrees) from each of the best few, then finely from the best.
  const std::size_t refined = std::min(candidates.size(), keep);
  const double coarse = std::max(options_.min_step, 0.05);
  auto refine_finely = [&] {
    csp::Score score = best;
    Point x = best_x;
    refine(score, x, coarse / position_step * 2, options_.min_step, options_.global ? 12 : 0);
  };
  // A clear leader (feasible, costing at most kClearLead of the runner-up) is refined finely
  // as soon as coarsely, before the others: with a short budget the others' coarse rounds
  // left its fine one unfinished (problem 11 at 2 ms). The fine round runs again at the end
  // only if another candidate has overtaken it.
  constexpr double kClearLead = 0.75;
  // A candidate scored in part gets its full score before it is compared or refined.
  auto score_fully = [&](ShotSearchScratch::Candidate& c) {
    if (!c.partial) return;
    c.score = framing.score(c.x);
    c.partial = false;
    ++evaluations;
  };
  if (candidates.size() > 1) score_fully(candidates[1]);  // keep 1: the runner-up, for the test
  const bool leader_first =
      options_.global && coarse > options_.min_step && candidates.size() > 1 &&
      candidates[0].score.feasible() &&
      candidates[0].score.soft <= kClearLead * candidates[1].score.soft;
  std::optional<csp::Score> after_leader;
  // With a time limit, the coarse refinements stop at 70% of it, leaving the best's fine one
  // the rest.
  const double coarse_seconds = 0.7 * context.limits.time_limit_seconds;
  for (std::size_t i = 0; i < refined && !budget.exhausted(evaluations, iterations); ++i) {
    if (i > 0 && coarse_seconds > 0 && budget.elapsed_seconds() > coarse_seconds) break;
    refine(candidates[i].score, candidates[i].x, options_.global || options_.hold_position ? 1.0 : 0.25, coarse);
    if (i == 0 && leader_first && !budget.exhausted(evaluations, iterations)) {
      refine_finely();
      after_leader = best;
    }
  }
  if (!budget.exhausted(evaluations, iterations) && coarse > options_.min_step &&
      (!after_leader || best.better_than(*after_leader))) {
    refine_finely();
  }
  // 4. With a budget to use (an anytime run): the other candidates in order (coarsely), then
  // restarts that alternate between the best pose shaken (position by up to a metre, aim by
  // up to 10 degrees) and a new point of the region's Halton sequence aimed at the targets,
  // so the search keeps exploring other basins as well as polishing its best.
  if (context.runs_to_the_limit() && options_.global) {
    std::mt19937_64 rng(context.seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::size_t next = refined;
    std::uint64_t halton_index = static_cast<std::uint64_t>(options_.samples);
    for (std::uint64_t restart = 0; !budget.exhausted(evaluations, iterations); ++restart) {
      if (next < candidates.size()) {
        score_fully(candidates[next]);
        refine(candidates[next].score, candidates[next].x, 1.0, coarse);
        ++next;
        continue;
      }
      Point x = best_x;
      double scale = 0.5;
      if (restart % 2 == 0) {
        for (int k = 0; k < 3; ++k) x[static_cast<std::size_t>(k)] += unit(rng);
        x[3] += 10 * unit(rng);
        x[4] += 10 * unit(rng);
        if (!shot.fov.fixed()) x[5] += 5 * unit(rng);
      } else {
        ++halton_index;
        const Eigen::Vector3d p =
            region.min + Eigen::Vector3d(halton(halton_index, 2), halton(halton_index, 3),
                                         halton(halton_index, 5))
                             .cwiseProduct(region.max - region.min);
        x = Point{p.x(), p.y(), p.z(), 0, 0, fov, roll};
        framing.aim(x);
        scale = 1.0;
      }
      clamp(x);
      csp::Score score = framing.score(x);
      ++evaluations;
      refine(score, x, scale, restart % 2 == 0 ? options_.min_step : coarse, restart % 2 == 0 ? 6 : 0);
    }
  }
  result.best = framing.values(best_x);
  result.evaluations = evaluations;
  result.iterations = iterations;
  result.stop = budget.exhausted(evaluations, iterations) ? budget.reason()
                                                          : solvers::StopReason::kCompleted;
  result.message.clear();
  solvers::finish_result(problem, context, budget, result);
}

}  // namespace sightline::camera
