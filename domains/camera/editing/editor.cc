#include "sightline/domains/camera/editing/editor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sightline/solvers/registry.h"

namespace sightline::camera {
namespace {

Eigen::Vector3d catmull_rom(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                            const Eigen::Vector3d& p2, const Eigen::Vector3d& p3, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return 0.5 * (2 * p1 + (p2 - p0) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u2 +
                (3 * p1 - p0 - 3 * p2 + p3) * u3);
}

double catmull_rom(double p0, double p1, double p2, double p3, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return 0.5 * (2 * p1 + (p2 - p0) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u2 +
                (3 * p1 - p0 - 3 * p2 + p3) * u3);
}

std::string number(double x) {
  std::ostringstream out;
  out.precision(3);
  out << x;
  return out.str();
}

std::string parts(const ShotCostParts& p) {
  return "composition " + number(p.composition) + ", script " + number(p.script) + ", relevance " +
         number(p.relevance);
}

// Why the film cuts from `from` to `to` at slot i.
std::string why_cut(const Edit& edit, std::size_t i, std::size_t from, std::size_t to) {
  const EditCosts& c = edit.costs;
  const auto& names = edit.footage.candidates;
  std::string text;
  if (from == to) {
    text = "its camera jumped (a cut keeping the shot): cut " + number(c.change[i][from * c.shots + to]);
  } else {
    text = "'" + names[to].name + "' (" + parts(c.unary[i][to]) + ") against staying on '" +
           names[from].name + "' (" + parts(c.unary[i][from]) + "); cut " +
           number(c.change[i][from * c.shots + to]);
  }
  return text;
}

}  // namespace

std::vector<double> film_frame_times(const Scene& scene) {
  const auto [start, end] = people_time_span(scene);
  const double rate = scene.frame_rate();
  const double frames = (end - start) * rate;
  const auto whole = static_cast<std::size_t>(std::floor(frames + 1e-6));
  std::vector<double> times;
  for (std::size_t f = 0; f <= whole; ++f) times.push_back(std::min(start + static_cast<double>(f) / rate, end));
  if (frames - static_cast<double>(whole) > 1e-6) times.push_back(end);
  return times;
}

Edit edit_scene(const Scene& scene, const EditorOptions& options) {
  return edit_footage(scene, film_footage(scene, candidate_shots(scene), options.footage), options);
}

Edit edit_footage(const Scene& scene, Footage footage, const EditorOptions& options) {
  Edit edit;
  edit.footage = std::move(footage);
  edit.costs = edit_costs(scene, edit.footage, options.weights, options.rules);
  edit.solver = options.solver;
  const EditCosts& costs = edit.costs;
  auto problem = edit_problem(costs, options.weights, scene.name() + " edit");
  edit.model_constraints = problem->num_constraints();
  const auto began = std::chrono::steady_clock::now();
  if (options.solver == kGreedyEditor) {
    edit.choice = greedy_edit(costs, options.weights);
    edit.solver_message = "greedy editor with hysteresis " + number(options.weights.hysteresis);
  } else {
    auto solver = solvers::SolverRegistry::global().create(options.solver);
    if (std::string why = solver->unsuitable_reason(*problem); !why.empty()) {
      throw std::invalid_argument("solver '" + options.solver + "' cannot edit: " + why);
    }
    solvers::SolveContext context;
    context.seed = options.seed;
    context.want_breakdown = false;
    context.limits.time_limit_seconds = options.time_limit_seconds;
    // Local searches start from the greedy edit, as an editor would start from a rough cut.
    std::vector<std::size_t> rough = greedy_edit(costs, options.weights);
    csp::Assignment start(rough.begin(), rough.end());
    const solvers::SolverResult result = solver->solve(*problem, start, context);
    edit.solver_message = result.brief_report(options.solver);
    for (double v : result.best) edit.choice.push_back(static_cast<std::size_t>(v));
  }
  edit.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  csp::Assignment chosen(edit.choice.begin(), edit.choice.end());
  edit.score = problem->score(chosen);

  // The shots: where the choice changes, or a shot's camera jumps.
  const std::size_t n = edit.choice.size();
  const Footage& f = edit.footage;
  auto starts_shot = [&](std::size_t i) {
    return i == 0 || edit.choice[i] != edit.choice[i - 1] || costs.jumps[i][edit.choice[i]];
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!starts_shot(i)) continue;
    if (!edit.shots.empty()) edit.shots.back().end = f.slot_times[i];
    FilmShot shot;
    shot.shot = edit.choice[i];
    shot.start = i == 0 ? f.start : f.slot_times[i];
    shot.first_slot = i;
    shot.why = i == 0 ? "opening shot (" + parts(costs.unary[0][shot.shot]) + ")"
                      : why_cut(edit, i, edit.choice[i - 1], edit.choice[i]);
    edit.shots.push_back(std::move(shot));
  }
  if (!edit.shots.empty()) edit.shots.back().end = f.end;

  // The frames.
  std::size_t last_slot = 0;
  bool first = true;
  for (const double t : film_frame_times(scene)) {
    const std::size_t i = std::min(
        n - 1, static_cast<std::size_t>(std::floor((t - f.start) / f.slot_seconds + 1e-9)));
    const std::size_t k = edit.choice[i];
    EditedFrame frame;
    frame.t = t;
    frame.shot = k;
    frame.cost = costs.totals[i][k];
    frame.cut = !first && i != last_slot && starts_shot(i);
    // The takes around: the shot's own, not across a jump of its camera.
    const bool next = i + 1 < n && !costs.jumps[i + 1][k];
    const bool prev = i > 0 && !costs.jumps[i][k];
    const Take& t1 = f.takes[i][k];
    const Take& t2 = next ? f.takes[i + 1][k] : t1;
    const Take& t0 = prev ? f.takes[i - 1][k] : t1;
    const Take& t3 = next && i + 2 < n && !costs.jumps[i + 2][k] ? f.takes[i + 2][k] : t2;
    const double u = std::clamp((t - f.slot_times[i]) / f.slot_seconds, 0.0, 1.0);
    auto dir = [](const Take& take) { return Eigen::Vector3d((take.pose.look_at - take.pose.position).normalized()); };
    frame.pose = t1.pose;
    frame.pose.position = catmull_rom(t0.pose.position, t1.pose.position, t2.pose.position, t3.pose.position, u);
    Eigen::Vector3d d = catmull_rom(dir(t0), dir(t1), dir(t2), dir(t3), u);
    if (d.norm() < 1e-6) d = dir(t1);
    frame.pose.look_at = frame.pose.position + d.normalized();
    frame.pose.fov = catmull_rom(t0.pose.fov, t1.pose.fov, t2.pose.fov, t3.pose.fov, u);
    frame.pose.roll = catmull_rom(t0.pose.roll, t1.pose.roll, t2.pose.roll, t3.pose.roll, u);
    edit.frames.push_back(frame);
    last_slot = i;
    first = false;
  }
  return edit;
}

}  // namespace sightline::camera
