#include "sightline/domains/camera/editing/edit_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sightline/csp/kinds/stretch.h"
#include "sightline/domains/camera/composition/shot_world.h"

namespace sightline::camera {
namespace {

bool names(const CandidateShot& c, const std::string& who) { return c.subject == who || c.other == who; }

// How ill the candidate fits what happens at the slot (0 best).
double misfit(const CandidateShot& c, const std::vector<std::string>& speakers,
              const std::vector<std::string>& actors, bool opening) {
  double m = 0;
  const bool single = c.idiom == Idiom::kCloseUp || c.idiom == Idiom::kMedium ||
                      c.idiom == Idiom::kOverShoulder;
  auto about = [&](const std::vector<std::string>& who) {
    return std::any_of(who.begin(), who.end(), [&](const std::string& w) { return c.subject == w; });
  };
  auto mentions = [&](const std::vector<std::string>& who) {
    return std::any_of(who.begin(), who.end(), [&](const std::string& w) { return names(c, w); });
  };
  if (!speakers.empty()) {
    if (single && about(speakers)) {
      m = c.idiom == Idiom::kMedium ? 0 : c.idiom == Idiom::kOverShoulder ? 0.05 : 0.1;
    } else if (c.idiom == Idiom::kTwoShot && mentions(speakers)) {
      m = 0.25;
    } else if (c.idiom == Idiom::kEstablishing) {
      m = 0.5;
    } else if (c.idiom == Idiom::kNamed) {
      m = 0.15;
    } else {
      m = 0.4;
    }
  } else if (!actors.empty()) {
    if (single && about(actors)) {
      m = 0;
    } else if (c.idiom == Idiom::kTwoShot && mentions(actors)) {
      m = 0.15;
    } else if (c.idiom == Idiom::kEstablishing) {
      m = 0.3;
    } else {
      m = c.idiom == Idiom::kNamed ? 0.15 : 0.4;
    }
  } else {
    m = c.idiom == Idiom::kTwoShot || c.idiom == Idiom::kEstablishing ? 0
        : c.idiom == Idiom::kNamed                                    ? 0.1
                                                                      : 0.2;
  }
  if (opening) m = c.idiom == Idiom::kEstablishing ? 0 : m + 0.3;
  return m;
}

// Unary and binary costs as explicit tables, so bnb's soft arc consistency and the .wcsp
// writer see them as the tables they are.
class SlotShotConstraint : public csp::Constraint, public csp::TableCosts {
 public:
  SlotShotConstraint(csp::VariableId slot, const std::vector<double>* costs)
      : Constraint({slot}, 1.0, false), costs_(costs) {}
  std::string_view kind() const override { return "edit.shot"; }
  const csp::TableCosts* table_costs() const override { return this; }
  double violation(std::span<const double> values) const override {
    return (*costs_)[static_cast<std::size_t>(values[scope()[0]])];
  }
  double default_cost() const override { return 0; }
  std::size_t num_tuples() const override { return costs_->size(); }
  double tuple_value(std::size_t i, std::size_t) const override { return static_cast<double>(i); }
  double tuple_cost(std::size_t i) const override { return (*costs_)[i]; }

 private:
  const std::vector<double>* costs_;
};

class CutConstraint : public csp::Constraint, public csp::TableCosts {
 public:
  CutConstraint(csp::VariableId before, csp::VariableId after, std::size_t shots,
                const std::vector<double>* costs)
      : Constraint({before, after}, 1.0, false), shots_(shots), costs_(costs) {}
  std::string_view kind() const override { return "edit.cut"; }
  const csp::TableCosts* table_costs() const override { return this; }
  double violation(std::span<const double> values) const override {
    const auto a = static_cast<std::size_t>(values[scope()[0]]);
    const auto b = static_cast<std::size_t>(values[scope()[1]]);
    return (*costs_)[a * shots_ + b];
  }
  double default_cost() const override { return 0; }
  std::size_t num_tuples() const override { return costs_->size(); }
  double tuple_value(std::size_t i, std::size_t position) const override {
    return static_cast<double>(position == 0 ? i / shots_ : i % shots_);
  }
  double tuple_cost(std::size_t i) const override { return (*costs_)[i]; }

 private:
  std::size_t shots_;
  const std::vector<double>* costs_;
};

}  // namespace

EditCosts edit_costs(const Scene& scene, const Footage& footage, const EditWeights& w,
                     const ContinuityRules& rules) {
  EditCosts costs;
  costs.slots = footage.slot_times.size();
  costs.shots = footage.candidates.size();
  costs.min_slots = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::ceil(w.min_shot_seconds / footage.slot_seconds - 1e-9)));
  if (w.max_shot_seconds > 0) {
    costs.max_slots = std::max<std::size_t>(
        costs.min_slots, static_cast<std::size_t>(std::floor(w.max_shot_seconds / footage.slot_seconds + 1e-9)));
  }
  costs.unary.assign(costs.slots, std::vector<ShotCostParts>(costs.shots));
  costs.totals.assign(costs.slots, std::vector<double>(costs.shots, 0.0));
  costs.change.assign(costs.slots, std::vector<double>(costs.shots * costs.shots, 0.0));
  costs.jumps.assign(costs.slots, std::vector<bool>(costs.shots, false));
  static const std::vector<ScriptEntry> kNoScript;
  const std::vector<ScriptEntry>& script = scene.script() ? *scene.script() : kNoScript;
  ShotWorld world(scene, footage.start);
  auto index_of = [&](const std::string& who) -> int {
    const auto found = world.find(who);
    return found ? *found : -1;
  };
  // A shot's camera jumps when it moves faster than half the film's speed limit on average
  // between two takes: its path through the takes (a Catmull-Rom curve) peaks higher.
  const double max_move = 0.5 * w.max_speed * footage.slot_seconds;
  for (std::size_t i = 1; i < costs.slots; ++i) {
    for (std::size_t k = 0; k < costs.shots; ++k) {
      const Take& now = footage.takes[i][k];
      const Take& before = footage.takes[i - 1][k];
      costs.jumps[i][k] = (now.pose.position - before.pose.position).norm() > max_move ||
                          view_turn_degrees(before.pose, now.pose) > 90;
    }
  }
  for (std::size_t i = 0; i < costs.slots; ++i) {
    const double t = footage.slot_times[i];
    world.set_time(t);
    // Who speaks or acts during the slot, with the share of the slot they take.
    std::vector<std::string> speakers, actors;
    std::vector<double> speaking, acting;
    const double slot_end = t + footage.slot_seconds;
    for (const ScriptEntry& e : script) {
      const double share = (std::min(slot_end, e.t1) - std::max(t, e.t0)) / footage.slot_seconds;
      if (share <= 0) continue;
      (e.speaker.empty() ? actors : speakers).push_back(e.speaker.empty() ? e.action : e.speaker);
      (e.speaker.empty() ? acting : speaking).push_back(share);
    }
    const bool opening = t < footage.start + w.min_shot_seconds;
    for (std::size_t k = 0; k < costs.shots; ++k) {
      const Take& take = footage.takes[i][k];
      ShotCostParts& part = costs.unary[i][k];
      part.composition = w.composition * (1 - take.satisfaction) + (take.feasible ? 0 : w.infeasible);
      for (std::size_t s = 0; s < speakers.size(); ++s) {
        const int p = index_of(speakers[s]);
        if (p < 0) continue;
        const PersonInTake& seen = take.people[p];
        if (!seen.shown) {
          part.script += speaking[s] * (w.speaker_hidden + 2 * w.speaker_view);
        } else {
          if (!seen.front) part.script += speaking[s] * w.speaker_view;
          if (seen.size < w.readable_size) part.script += speaking[s] * w.speaker_view;
        }
      }
      for (std::size_t a = 0; a < actors.size(); ++a) {
        const int p = index_of(actors[a]);
        if (p >= 0 && !take.people[p].shown) part.script += acting[a] * w.action_hidden;
      }
      part.relevance = w.relevance * misfit(footage.candidates[k], speakers, actors, opening);
      costs.totals[i][k] = part.total();
    }
    if (i == 0) continue;
    // The lines of action at the cut: at the slot's start and at the frame the film cuts on
    // (the first frame at or after it), which may fall under the next line.
    const double rate = scene.frame_rate();
    const double cut_frame = footage.start + std::ceil((t - footage.start) * rate - 1e-9) / rate;
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> lines;
    for (const double when : {t, cut_frame}) {
      if (const auto entry = line_of_action_entry(script, when)) {
        const int a = index_of(script[*entry].speaker), b = index_of(script[*entry].to);
        if (a >= 0 && b >= 0) lines.emplace_back(world.people()[a].aim, world.people()[b].aim);
      }
    }
    // A cut's price. The film's frames around a cut pass between takes: the last frame
    // before it lies between the old shot's takes `from_before` and `from`, the cut frame
    // between the new shot's `to` and `to_after` (null: held), so the sides are checked
    // for each of them.
    auto cut_price = [&](const Take& from, const Take* from_before, const Take& to, const Take* to_after) {
      double price = w.cut;
      bool crossing = false, near = false;
      const Take* befores[] = {&from, from_before};
      const Take* afters[] = {&to, to_after};
      for (const auto& [a, b] : lines) {
        for (const Take* x : befores) {
          for (const Take* y : afters) {
            if (!x || !y) continue;
            // Stricter than the rule: opposite signs at all.
            const double s0 = side_of_line(x->pose.position, a, b), s1 = side_of_line(y->pose.position, a, b);
            crossing = crossing || s0 * s1 < 0 || crosses_line(x->pose.position, y->pose.position, a, b, rules);
            near = near || std::abs(s0) < 1.0 / 3 || std::abs(s1) < 1.0 / 3;
          }
        }
      }
      if (crossing) price += w.crossing;
      if (near) price += w.on_line;
      if (is_jump_cut(from.pose, from.subject_size, to.pose, to.subject_size, rules)) price += w.jump_cut;
      return price;
    };
    for (std::size_t a = 0; a < costs.shots; ++a) {
      // A shot whose camera jumped into this slot was last seen at its previous take.
      const bool jumped = costs.jumps[i][a];
      const Take& from = jumped ? footage.takes[i - 1][a] : footage.takes[i][a];
      const Take* from_before = jumped ? nullptr : &footage.takes[i - 1][a];
      for (std::size_t b = 0; b < costs.shots; ++b) {
        const Take* to_after = i + 1 < costs.slots && !costs.jumps[i + 1][b] ? &footage.takes[i + 1][b] : nullptr;
        double& price = costs.change[i][a * costs.shots + b];
        if (a == b) {
          // Holding a shot through its camera's jump is a cut the runs do not count: priced
          // as a cut and as a shot cut short, so the edit cuts to another shot instead.
          price = jumped ? cut_price(footage.takes[i - 1][a], nullptr, footage.takes[i][a], to_after) + w.short_shot
                         : 0;
        } else {
          price = cut_price(from, from_before, footage.takes[i][b], to_after);
        }
      }
    }
  }
  return costs;
}

std::unique_ptr<csp::Problem> edit_problem(const EditCosts& costs, const EditWeights& w,
                                           const std::string& name) {
  auto problem = std::make_unique<csp::Problem>(name);
  if (costs.slots == 0) return problem;
  problem->add_variables("slot", costs.slots,
                         csp::Domain::integer_range(0, static_cast<std::int64_t>(costs.shots) - 1));
  for (std::size_t i = 0; i < costs.slots; ++i) {
    problem->add_constraint(
        std::make_unique<SlotShotConstraint>(static_cast<csp::VariableId>(i), &costs.totals[i]));
    if (i > 0) {
      problem->add_constraint(std::make_unique<CutConstraint>(
          static_cast<csp::VariableId>(i - 1), static_cast<csp::VariableId>(i), costs.shots,
          &costs.change[i]));
    }
  }
  std::vector<csp::VariableId> all(costs.slots);
  for (std::size_t i = 0; i < costs.slots; ++i) all[i] = static_cast<csp::VariableId>(i);
  auto stretch = std::make_unique<csp::StretchConstraint>(all, costs.min_slots, w.short_shot);
  stretch->set_label("shots of at least " + std::to_string(costs.min_slots) + " slots");
  problem->add_constraint(std::move(stretch));
  if (costs.max_slots > 0 && w.long_shot > 0) {
    auto rhythm = std::make_unique<csp::StretchConstraint>(all, 1, w.long_shot, false, costs.max_slots);
    rhythm->set_label("shots of at most " + std::to_string(costs.max_slots) + " slots");
    problem->add_constraint(std::move(rhythm));
  }
  return problem;
}

std::vector<std::size_t> greedy_edit(const EditCosts& costs, const EditWeights& w) {
  std::vector<std::size_t> choice(costs.slots, 0);
  if (costs.slots == 0 || costs.shots == 0) return choice;
  std::size_t current = 0;
  for (std::size_t k = 1; k < costs.shots; ++k) {
    if (costs.totals[0][k] < costs.totals[0][current]) current = k;
  }
  choice[0] = current;
  std::size_t age = 1;
  for (std::size_t i = 1; i < costs.slots; ++i) {
    const auto& change = costs.change[i];
    // A shot whose camera jumps must be left (or cut within).
    const bool must = costs.jumps[i][current];
    if (age >= costs.min_slots || must) {
      // The cheapest shot now among those a plain cut reaches (no line crossed, no jump cut);
      // staying past the maximum length costs its share.
      const bool overdue = costs.max_slots > 0 && age >= costs.max_slots;
      std::size_t best = current;
      double best_cost = costs.totals[i][current] + (must ? w.cut : 0) +
                         (overdue ? w.long_shot / static_cast<double>(costs.max_slots) : 0);
      for (std::size_t k = 0; k < costs.shots; ++k) {
        if (k == current || change[current * costs.shots + k] > w.cut + w.on_line) continue;
        if (costs.totals[i][k] + w.hysteresis < best_cost) {
          best_cost = costs.totals[i][k] + w.hysteresis;
          best = k;
        }
      }
      if (best != current) {
        current = best;
        age = 0;
      }
    }
    choice[i] = current;
    ++age;
  }
  return choice;
}

}  // namespace sightline::camera
