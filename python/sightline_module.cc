// The Python module `sightline` (pybind11; its package is python/sightline/): the library's
// weighted-CSP layer, solvers, cameras and suites for researchers, as Python objects.
//
// Build problems (ProblemBuilder, or problem files: .yaml, .wcsp, .cfn, .col), list solvers
// and kinds, solve with options and limits (the GIL released while solving; Ctrl-C stops a
// solve or a suite and raises KeyboardInterrupt), read results
// (assignment by variable name, cost, breakdown, stop reason, time and evaluations to
// best); read a scene once (Scene) and film it (the trace as a numpy structured array),
// compose its shot or judge a pose or a whole trace by the shot's measures; run a suite and
// read its results. Errors become Python exceptions: sightline.InputError (a ValueError with file,
// line, column and detail) for bad input, sightline.OptionError for bad names and options.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "apps/problem_loader.h"
#include "apps/solver_registration.h"
#include "python/interruptible_call.h"
#include "python/trace_array.h"
#include "sightline/csp/input_error.h"
#include "sightline/csp/kinds/builder.h"
#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/domains/camera/composition/compose.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/composition/pose_reading.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/execution/interruption.h"
#include "sightline/experiments/execution/suite_runner.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/edit_metrics.h"
#include "sightline/experiments/suite/suite.h"
#include "sightline/solvers/registry.h"

namespace py = pybind11;
using namespace sightline;

namespace {

// Python values into a Spec for a kind's fields: numbers, strings, booleans, lists, dicts.
csp::Spec to_spec(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return csp::Spec::string(value.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) {
    return csp::Spec::number(value.cast<double>());
  }
  if (py::isinstance<py::str>(value)) return csp::Spec::string(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    std::vector<std::pair<std::string, csp::Spec>> fields;
    for (const auto& [k, v] : value.cast<py::dict>()) fields.emplace_back(py::str(k), to_spec(v));
    return csp::Spec::map(std::move(fields));
  }
  if (py::isinstance<py::sequence>(value)) {
    std::vector<csp::Spec> items;
    for (const py::handle& item : value.cast<py::sequence>()) items.push_back(to_spec(item));
    return csp::Spec::list(std::move(items));
  }
  throw py::type_error("a constraint field must be a number, string, bool, list or dict, got " +
                       std::string(py::str(value.get_type())));
}

// A constraint defined in Python: the function gets the scope's values (floats, in scope
// order) and returns the violation (a finite number >= 0; 0 when satisfied). Solvers call it
// with the GIL released around the solve, so each call takes the GIL; an exception it raises
// comes back out of the solve as itself.
class PythonConstraint : public csp::Constraint {
 public:
  PythonConstraint(std::vector<csp::VariableId> scope, py::function function, double weight,
                   bool hard)
      : Constraint(std::move(scope), weight, hard), function_(std::move(function)) {}
  ~PythonConstraint() override {
    py::gil_scoped_acquire gil;
    function_ = py::function();
  }
  std::string_view kind() const override { return "python"; }
  double violation(std::span<const double> values) const override {
    py::gil_scoped_acquire gil;
    const auto s = scope();
    py::tuple args(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) args[i] = py::float_(values[s[i]]);
    const py::object returned = function_(*args);
    double v = 0;
    try {
      v = returned.cast<double>();
    } catch (const py::cast_error&) {
      throw py::type_error("python constraint '" + name() + "' must return its violation (a number), got " +
                           std::string(py::str(returned.get_type())));
    }
    if (!std::isfinite(v) || v < 0) {
      throw py::value_error("python constraint '" + name() + "' returned " + std::string(py::str(returned)) +
                            ": a violation is a finite number >= 0 (0 when satisfied)");
    }
    return v;
  }

 private:
  std::string name() const { return label().empty() ? std::string(kind()) : label(); }
  py::function function_;
};

struct PyProblem {
  std::shared_ptr<csp::Problem> problem;
  std::vector<std::vector<std::string>> labels;  // per variable, from a problem file
  std::vector<std::string> variables() const {
    std::vector<std::string> out;
    for (csp::VariableId v = 0; v < problem->num_variables(); ++v) out.push_back(problem->variable_name(v));
    return out;
  }
};

struct PyBuilder {
  std::unique_ptr<csp::ProblemBuilder> builder;
  explicit PyBuilder(const std::string& name) : builder(std::make_unique<csp::ProblemBuilder>(name)) {}
  csp::ProblemBuilder& get() {
    if (!builder) throw std::invalid_argument("this builder has already built its problem");
    return *builder;
  }
};

struct PyResult {
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> labels;
  csp::Assignment values;
  double cost = 0, hard = 0;
  bool feasible = false;
  std::string solver, stop, message;
  double wall_seconds = 0, best_found_seconds = -1;
  std::uint64_t evaluations = 0, iterations = 0, evaluations_at_best = 0;
  std::vector<std::pair<std::string, double>> breakdown;
  // The anytime trajectory: (seconds, evaluations, cost, hard) at each improvement.
  std::vector<std::tuple<double, std::uint64_t, double, double>> trajectory;
  // By variable name; a value's label where the problem file gives labels.
  py::dict assignment() const {
    py::dict d;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (const std::string* label = csp::find_value_label(labels, static_cast<csp::VariableId>(i), values[i])) {
        d[py::str(names[i])] = *label;
      } else {
        d[py::str(names[i])] = values[i];
      }
    }
    return d;
  }
};

// A solver's options from a Python dict: values as text, booleans as true / false.
solvers::OptionValues option_values(const py::dict& options) {
  solvers::OptionValues values;
  for (const auto& [k, v] : options) {
    values[py::str(k)] = py::isinstance<py::bool_>(v) ? (v.cast<bool>() ? "true" : "false")
                                                      : std::string(py::str(v));
  }
  return values;
}

PyResult solve(const PyProblem& p, const std::string& solver_name, const py::dict& options,
               std::optional<double> time_limit, std::optional<std::uint64_t> max_evaluations,
               std::optional<std::uint64_t> max_iterations, std::uint64_t seed,
               std::optional<std::vector<double>> start) {
  std::unique_ptr<solvers::Solver> solver =
      solvers::SolverRegistry::global().create(solver_name, option_values(options));
  if (std::string why = solver->unsuitable_reason(*p.problem); !why.empty()) {
    throw std::invalid_argument(solver_name + " cannot solve '" + p.problem->name() + "': " + why);
  }
  solvers::SolveContext context;
  context.seed = seed;
  context.want_trajectory = true;
  if (time_limit) {
    if (!(*time_limit > 0)) throw std::invalid_argument("time_limit must be > 0 seconds");
    context.limits.time_limit_seconds = *time_limit;
  }
  if (max_evaluations) context.limits.max_evaluations = *max_evaluations;
  if (max_iterations) context.limits.max_iterations = *max_iterations;
  std::vector<double> from = start.value_or(p.problem->default_assignment());
  if (!from.empty() && from.size() != p.problem->num_variables()) {
    throw std::invalid_argument("start has " + std::to_string(from.size()) + " values for " +
                                std::to_string(p.problem->num_variables()) + " variables");
  }
  // Ctrl-C stops the solver at its next budget check and raises KeyboardInterrupt.
  std::atomic<bool> stop{false};
  context.limits.stop = &stop;
  const solvers::SolverResult r =
      python::call_interruptibly(stop, [&] { return solver->solve(*p.problem, from, context); });
  PyResult out;
  for (csp::VariableId v = 0; v < p.problem->num_variables(); ++v) out.names.push_back(p.problem->variable_name(v));
  out.values = r.best;
  out.labels = p.labels;
  out.cost = r.score.soft;
  out.hard = r.score.hard;
  out.feasible = r.feasible();
  out.solver = solver_name;
  out.stop = solvers::to_string(r.stop);
  out.message = r.message;
  out.wall_seconds = r.wall_seconds;
  out.best_found_seconds = r.best_found_seconds;
  out.evaluations = r.evaluations;
  out.iterations = r.iterations;
  out.evaluations_at_best = r.evaluations_at_best;
  for (const solvers::AnytimePoint& a : r.trajectory) {
    out.trajectory.emplace_back(a.seconds, a.evaluations, a.score.soft, a.score.hard);
  }
  for (const csp::ConstraintCost& c : r.breakdown) {
    // Named by its label, else by its kind over its variables' names: "not_equal(a, b)".
    const std::string name = p.problem->constraint_name(c.id);
    out.breakdown.emplace_back(name, c.cost);
  }
  return out;
}

// A scene read once (sightline.load_scene): follow, compose, evaluate_pose and
// evaluate_trace take it or a path, so a script judging many instants of one scene (a
// Quake III level's above all) does not read and build it again for each.
struct PyScene {
  std::shared_ptr<const camera::Scene> scene;
  std::string path;  // the file it was read from, in messages
};

PyScene load_scene(const std::string& path) {
  return PyScene{std::make_shared<const camera::Scene>(camera::read_scene_file(path)), path};
}

// A Scene, or a path (str or os.PathLike) read now.
PyScene scene_of(const py::object& scene) {
  if (py::isinstance<PyScene>(scene)) return scene.cast<PyScene>();
  if (!py::isinstance<py::str>(scene) && !py::hasattr(scene, "__fspath__")) {
    throw py::type_error("scene: expected a sightline.Scene or a path, got " +
                         std::string(py::str(scene.get_type())));
  }
  return load_scene(py::str(py::module_::import("os").attr("fspath")(scene)));
}

py::dict follow(const py::object& scene_in, const std::string& solver, const std::string& profile,
                std::uint64_t seed) {
  const PyScene loaded = scene_of(scene_in);
  const camera::Scene& scene = *loaded.scene;
  camera::CameraProfile chosen = scene.profile();
  if (!profile.empty()) {
    chosen = camera::is_preset(profile) ? camera::preset_profile(profile) : camera::read_profile_file(profile);
  }
  camera::ChaseCameraOptions options;
  options.solver = !solver.empty() ? solver : experiments::recommended_solver(scene);
  options.seed = seed;
  experiments::CameraRun run;
  {
    py::gil_scoped_release release;
    run = experiments::run_camera(scene, chosen, options);
  }
  py::dict out;
  out["trace"] = python::trace_array(run.trace);
  out["summary"] = experiments::summary_paragraph(scene, run);
  py::dict metrics;
  const std::vector<std::string> names = experiments::metric_names();
  const std::vector<double> values = experiments::metric_values(run.metrics);
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) metrics[py::str(names[i])] = values[i];
  out["metrics"] = metrics;
  if (run.edit) {
    // An edited film: its shots [(start time, name)] and the continuity judge's metrics.
    py::list shots;
    for (std::size_t i = 0; i < run.trace.size(); ++i) {
      if (i == 0 || run.trace[i].cut) shots.append(py::make_tuple(run.trace[i].t, run.trace[i].shot));
    }
    out["shots"] = shots;
    py::dict edit;
    const std::vector<double> edit_values = experiments::edit_metric_values(*run.edit);
    for (std::size_t i = 0; i < edit_values.size(); ++i) {
      edit[py::str(experiments::edit_metric_names()[i])] = edit_values[i];
    }
    out["edit"] = edit;
  }
  return out;
}

// A shot's pose and its verdict, as compose's pose file has them (FORMATS.md "Shots").
py::dict shot_dict(const camera::CameraPose& pose, const camera::CompositionProblem& problem,
                   const camera::ShotEvaluation& e, double t) {
  auto point = [](const Eigen::Vector3d& v) { return py::make_tuple(v.x(), v.y(), v.z()); };
  py::dict d;
  d["position"] = point(pose.position);
  d["look_at"] = point(pose.look_at);
  d["roll"] = pose.roll;
  d["fov"] = pose.fov;
  d["aspect"] = pose.aspect;
  d["time"] = t;
  d["feasible"] = e.feasible;
  d["why_infeasible"] = e.why_infeasible;
  d["satisfaction"] = e.satisfaction;
  d["cost"] = e.cost;
  py::list properties;
  const std::vector<camera::ShotProperty>& shot = problem.shot().properties;
  for (std::size_t i = 0; i < shot.size(); ++i) {
    properties.append(py::dict(py::arg("kind") = shot[i].kind, py::arg("targets") = shot[i].targets,
                               py::arg("line") = shot[i].where.line, py::arg("hard") = shot[i].hard,
                               py::arg("measure") = e.measures[i], py::arg("score") = e.scores[i]));
  }
  d["properties"] = properties;
  return d;
}

py::dict compose(const py::object& scene_in, const std::string& solver_name, std::optional<double> time,
                 double budget_ms, std::uint64_t seed, const py::dict& options) {
  if (!(budget_ms > 0) || !std::isfinite(budget_ms)) throw std::invalid_argument("budget_ms: expected > 0");
  const PyScene loaded = scene_of(scene_in);
  const camera::Scene& scene = *loaded.scene;
  const camera::Shot& shot = camera::shot_to_compose(scene, loaded.path);
  const double t = camera::compose_time(scene, time, "time");
  const camera::CompositionProblem problem(scene, shot, t);
  std::unique_ptr<solvers::Solver> solver = solvers::SolverRegistry::global().create(
      solver_name.empty() ? camera::kRecommendedCompositionSolver : solver_name, option_values(options));
  solvers::SolveContext context;
  context.seed = seed;
  context.limits.time_limit_seconds = budget_ms / 1000;
  camera::Composed composed;
  {
    py::gil_scoped_release release;
    composed = camera::compose(problem, *solver, context);
  }
  py::dict d = shot_dict(composed.pose, problem, composed.evaluation, t);
  d["solver"] = solver->name();
  d["solve_seconds"] = composed.result.wall_seconds;
  d["evaluations"] = composed.result.evaluations;
  return d;
}

// A pose from Python: a pose file's path, or a mapping with FORMATS.md's fields as compose()
// returns them (roll optional); the aspect is always the shot's (FORMATS.md).
camera::CameraPose pose_of(const py::object& pose_in, const camera::Shot& shot) {
  camera::CameraPose pose;
  if (py::isinstance<py::str>(pose_in)) {
    pose = camera::read_pose_file(pose_in.cast<std::string>());
  } else {
    const py::dict d = pose_in.cast<py::dict>();
    auto point = [&](const char* key) {
      if (!d.contains(key)) throw std::invalid_argument(std::string("pose: missing '") + key + "'");
      const std::vector<double> v = d[key].cast<std::vector<double>>();
      if (v.size() != 3) throw std::invalid_argument(std::string("pose: '") + key + "' needs 3 numbers");
      return Eigen::Vector3d(v[0], v[1], v[2]);
    };
    pose.position = point("position");
    pose.look_at = point("look_at");
    pose.roll = d.contains("roll") ? d["roll"].cast<double>() : 0.0;
    if (!d.contains("fov")) throw std::invalid_argument("pose: missing 'fov'");
    pose.fov = d["fov"].cast<double>();
  }
  pose.aspect = shot.aspect;
  return pose;
}

py::dict evaluate_pose(const py::object& scene_in, const py::object& pose_in, std::optional<double> time) {
  const PyScene loaded = scene_of(scene_in);
  const camera::Scene& scene = *loaded.scene;
  const camera::Shot& shot = camera::shot_to_compose(scene, loaded.path);
  const double t = camera::compose_time(scene, time, "time");
  const camera::CompositionProblem problem(scene, shot, t);
  const camera::CameraPose pose = pose_of(pose_in, shot);
  if (!camera::View::of(pose)) {
    throw std::invalid_argument("pose: not a view (the look-at point at the position or straight "
                                "above or below it, a fov outside (0, 180), or a number not finite)");
  }
  return shot_dict(pose, problem, problem.evaluate(pose), t);
}

// Every frame of a filmed trace judged by the scene's shot, as evaluate_pose judges one pose
// at its time: the trace is anything whose columns t, cam_x, cam_y, cam_z, target_x,
// target_y, target_z, fov and roll index as arrays of numbers of one length (follow()'s
// trace, a pandas DataFrame of it, a dict of lists). One problem is built and moved to each
// frame's time; a frame whose pose is no view is judged infeasible, saying why.
py::dict evaluate_trace(const py::object& scene_in, const py::object& trace) {
  const PyScene loaded = scene_of(scene_in);
  const camera::Scene& scene = *loaded.scene;
  const camera::Shot& shot = camera::shot_to_compose(scene, loaded.path);
  using Column = py::array_t<double, py::array::c_style | py::array::forcecast>;
  static constexpr const char* kColumns[] = {"t", "cam_x", "cam_y", "cam_z", "target_x", "target_y",
                                             "target_z", "fov", "roll"};
  std::vector<Column> columns;
  for (const char* name : kColumns) {
    py::object column;
    try {
      column = trace[py::str(name)];
    } catch (const py::error_already_set&) {
      throw std::invalid_argument(std::string("trace: no column '") + name +
                                  "' (expected t, cam_x/y/z, target_x/y/z, fov and roll, as follow() gives)");
    }
    Column values = Column::ensure(column);
    if (!values || values.ndim() != 1) {
      throw std::invalid_argument(std::string("trace: column '") + name + "' is not a list of numbers");
    }
    if (!columns.empty() && values.shape(0) != columns.front().shape(0)) {
      throw std::invalid_argument(std::string("trace: column '") + name + "' has " +
                                  std::to_string(values.shape(0)) + " values, 't' has " +
                                  std::to_string(columns.front().shape(0)));
    }
    columns.push_back(std::move(values));
  }
  const auto frames = static_cast<std::size_t>(columns.front().shape(0));
  const double* t = columns[0].data();
  for (std::size_t i = 0; i < frames; ++i) {
    if (!std::isfinite(t[i])) {
      throw std::invalid_argument("trace: t of frame " + std::to_string(i) + " is not a finite number");
    }
  }
  const std::size_t n = shot.properties.size();
  py::array_t<double> satisfaction(static_cast<py::ssize_t>(frames)), cost(static_cast<py::ssize_t>(frames));
  py::array_t<bool> feasible(static_cast<py::ssize_t>(frames));
  const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(frames), static_cast<py::ssize_t>(n)};
  py::array_t<double> scores(shape), measures(shape);
  std::vector<std::string> why(frames);
  {
    std::array<const double*, 9> c{};
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = columns[k].data();
    double* out_satisfaction = satisfaction.mutable_data();
    double* out_cost = cost.mutable_data();
    bool* out_feasible = feasible.mutable_data();
    double* out_scores = scores.mutable_data();
    double* out_measures = measures.mutable_data();
    py::gil_scoped_release release;  // only the arrays' memory is touched below
    camera::CompositionProblem problem(scene, shot, frames > 0 ? t[0] : 0.0);
    camera::ShotEvaluation e;
    for (std::size_t i = 0; i < frames; ++i) {
      problem.set_time(t[i]);
      camera::CameraPose pose;
      pose.position = Eigen::Vector3d(c[1][i], c[2][i], c[3][i]);
      pose.look_at = Eigen::Vector3d(c[4][i], c[5][i], c[6][i]);
      pose.fov = c[7][i];
      pose.roll = c[8][i];
      pose.aspect = shot.aspect;
      problem.evaluate_into(pose, e);
      out_satisfaction[i] = e.satisfaction;
      out_cost[i] = e.cost;
      out_feasible[i] = e.feasible;
      std::copy(e.scores.begin(), e.scores.end(), out_scores + i * n);
      std::copy(e.measures.begin(), e.measures.end(), out_measures + i * n);
      why[i] = e.why_infeasible;
    }
  }
  py::list properties;
  for (const camera::ShotProperty& p : shot.properties) {
    properties.append(py::dict(py::arg("kind") = p.kind, py::arg("targets") = p.targets,
                               py::arg("line") = p.where.line, py::arg("hard") = p.hard));
  }
  py::dict d;
  d["t"] = columns[0];
  d["satisfaction"] = satisfaction;
  d["cost"] = cost;
  d["feasible"] = feasible;
  d["why_infeasible"] = why;
  d["scores"] = scores;
  d["measures"] = measures;
  d["properties"] = properties;
  return d;
}

py::dict run_suite(const std::string& path, const std::string& out_dir, unsigned jobs,
                   bool isolated, const std::string& program) {
  const experiments::Suite suite = experiments::read_suite_file(path);
  experiments::RunnerOptions options;
  options.out_dir = out_dir;
  options.jobs = jobs;
  options.progress = false;
  options.isolation.isolated = isolated;
  options.isolation.program = program;
  experiments::SuiteOutcome outcome;
  {
    py::gil_scoped_release release;
    outcome = experiments::run_suite(suite, options);  // Ctrl-C: it keeps what is done
  }
  if (outcome.interrupted) {
    const std::string resume = "; resume with: sightline.run_suite(" + std::string(py::repr(py::str(path))) +
                               ", " + std::string(py::repr(py::str(out_dir))) + ")";
    PyErr_SetString(PyExc_KeyboardInterrupt, (experiments::interruption_text(outcome) + resume).c_str());
    throw py::error_already_set();
  }
  py::dict d;
  d["total"] = outcome.total;
  d["reused"] = outcome.reused;
  d["ran"] = outcome.ran;
  d["failed"] = outcome.failed;
  d["seconds"] = outcome.seconds;
  d["results_csv"] = out_dir + "/results.csv";
  return d;
}

}  // namespace

PYBIND11_MODULE(_sightline, m) {
  m.doc() = "sightline: weighted constraint satisfaction with pluggable solvers, and camera control";
  // Every solver the program offers (toulbar2 too, when installed), here and in suites.
  apps::register_all_solvers();

  static py::exception<csp::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<solvers::OptionError> option_error(m, "OptionError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const csp::InputError& e) {
      py::object type = py::reinterpret_borrow<py::object>(input_error.ptr());
      py::object instance = type(e.what());
      instance.attr("file") = e.where().file;
      instance.attr("line") = e.where().line;
      instance.attr("column") = e.where().column;
      instance.attr("detail") = e.detail();
      PyErr_SetObject(input_error.ptr(), instance.ptr());
    } catch (const solvers::OptionError& e) {
      PyErr_SetString(option_error.ptr(), e.what());
    }
  });

  py::class_<PyProblem>(m, "Problem", "A weighted CSP (variables, domains, constraints).")
      .def_property_readonly("name", [](const PyProblem& p) { return p.problem->name(); })
      .def_property_readonly("variables", &PyProblem::variables, "variable names, in id order")
      .def_property_readonly("num_constraints", [](const PyProblem& p) { return p.problem->num_constraints(); })
      .def("score", [](const PyProblem& p, const std::vector<double>& values) {
             if (values.size() != p.problem->num_variables()) throw std::invalid_argument("one value per variable");
             const csp::Score s = p.problem->score(values);
             return py::make_tuple(s.hard, s.soft);
           }, "(hard violation, soft cost) of an assignment")
      .def("__repr__", [](const PyProblem& p) {
        return "<sightline.Problem '" + p.problem->name() + "': " + std::to_string(p.problem->num_variables()) +
               " variables, " + std::to_string(p.problem->num_constraints()) + " constraints>";
      });

  py::class_<PyBuilder>(m, "ProblemBuilder", "Builds a problem: variables, then constraints of registered kinds.")
      .def(py::init<const std::string&>(), py::arg("name") = "problem")
      .def("integer", [](PyBuilder& b, const std::string& n, std::int64_t lo, std::int64_t hi) { return b.get().integer(n, lo, hi); },
           py::arg("name"), py::arg("lo"), py::arg("hi"))
      .def("values", [](PyBuilder& b, const std::string& n, std::vector<double> v) { return b.get().values(n, std::move(v)); },
           py::arg("name"), py::arg("values"))
      .def("real", [](PyBuilder& b, const std::string& n, double lo, double hi) { return b.get().real(n, lo, hi); },
           py::arg("name"), py::arg("lo"), py::arg("hi"))
      .def("parameter", [](PyBuilder& b, const std::string& n, double v) { return b.get().parameter(n, v); })
      .def("constrain",
           [](PyBuilder& b, const std::string& kind, const std::vector<std::string>& scope, double weight, bool hard,
              const py::kwargs& fields) {
             std::vector<std::pair<std::string, csp::Spec>> spec;
             for (const auto& [k, v] : fields) spec.emplace_back(py::str(k), to_spec(v));
             return b.get().constrain(kind, scope, csp::Spec::map(std::move(spec)), weight, hard);
           },
           py::arg("kind"), py::arg("scope"), py::arg("weight") = 1.0, py::arg("hard") = false,
           "A constraint of a registered kind over the named variables; its own fields as keywords.")
      .def("function",
           [](PyBuilder& b, const std::vector<std::string>& scope, const py::function& f, double weight, bool hard,
              const std::string& label) {
             if (!(weight >= 0) || !std::isfinite(weight)) throw py::value_error("weight must be a finite number >= 0");
             std::vector<csp::VariableId> ids;
             for (const std::string& n : scope) {
               const auto id = b.get().problem().find_variable(n);
               if (!id) throw py::value_error("unknown variable '" + n + "' in the scope of a python constraint");
               ids.push_back(*id);
             }
             if (ids.empty()) throw py::value_error("a python constraint needs at least one variable in its scope");
             auto c = std::make_unique<PythonConstraint>(std::move(ids), f, weight, hard);
             c->set_label(label);
             return b.get().add(std::move(c));
           },
           py::arg("scope"), py::arg("function"), py::arg("weight") = 1.0, py::arg("hard") = false,
           py::arg("label") = "",
           "A constraint defined in Python: function(*values of the scope) returns the violation "
           "(a number >= 0, 0 when satisfied). Slower than a registered kind (a Python call per "
           "evaluation); an exception it raises comes out of solve().")
      .def("build", [](PyBuilder& b) {
        PyProblem p{std::shared_ptr<csp::Problem>(b.get().build()), {}};
        b.builder.reset();
        return p;
      });

  py::class_<PyResult>(m, "Result", "What a solver found.")
      .def_property_readonly("assignment", &PyResult::assignment, "value of each variable, by name")
      .def_readonly("values", &PyResult::values)
      .def_readonly("cost", &PyResult::cost)
      .def_readonly("hard", &PyResult::hard, "sum of hard violations (0: feasible)")
      .def_readonly("feasible", &PyResult::feasible)
      .def_readonly("solver", &PyResult::solver)
      .def_readonly("stop", &PyResult::stop)
      .def_readonly("message", &PyResult::message)
      .def_readonly("wall_seconds", &PyResult::wall_seconds)
      .def_readonly("best_found_seconds", &PyResult::best_found_seconds, "time to best, -1 when not recorded")
      .def_readonly("evaluations", &PyResult::evaluations)
      .def_readonly("evaluations_at_best", &PyResult::evaluations_at_best)
      .def_readonly("iterations", &PyResult::iterations)
      .def_readonly("breakdown", &PyResult::breakdown, "(constraint, cost) pairs")
      .def_readonly("trajectory", &PyResult::trajectory,
                    "the anytime trajectory: (seconds, evaluations, cost, hard) at each improvement "
                    "of the best, in order; the last is the result")
      .def("__repr__", [](const PyResult& r) {
        return "<sightline.Result " + r.solver + ": cost " + std::to_string(r.cost) +
               (r.feasible ? ", feasible" : ", infeasible") + ", stop: " + r.stop + ">";
      });

  m.def("load_problem", [](const std::string& path, int colours) {
          apps::LoadOptions o;
          o.colours = colours;
          o.colours_name = "colours";  // load_problem's argument, in messages
          o.colours_usage = "colours=K";
          csp::LoadedProblem model = apps::load_model(path, o);
          return PyProblem{std::shared_ptr<csp::Problem>(std::move(model.problem)),
                           std::move(model.value_labels)};
        },
        py::arg("path"), py::arg("colours") = 0,
        "A problem file (.yaml), a toulbar2 .wcsp or .cfn, or a DIMACS graph (.col, with colours).");
  m.def("solve", &solve, py::arg("problem"), py::arg("solver") = "sls", py::arg("options") = py::dict(),
        py::arg("time_limit") = py::none(), py::arg("max_evaluations") = py::none(),
        py::arg("max_iterations") = py::none(), py::arg("seed") = 1, py::arg("start") = py::none(),
        "Solves with a registered solver or pipeline (\"sls\", \"bnb\", \"sls>bnb\", ...).");
  m.def("solvers", [] {
    py::list out;
    for (const std::string& n : solvers::SolverRegistry::global().names()) {
      const solvers::SolverInfo& info = solvers::SolverRegistry::global().info(n);
      py::list options;
      for (const solvers::OptionInfo& o : info.options) {
        options.append(py::dict(py::arg("name") = o.name, py::arg("type") = o.type,
                                py::arg("default") = o.default_value, py::arg("help") = o.help));
      }
      out.append(py::dict(py::arg("name") = n, py::arg("description") = info.description,
                          py::arg("options") = options));
    }
    return out;
  }, "Every registered solver with its options.");
  m.def("kinds", [] {
    py::list out;
    for (const std::string& n : csp::ConstraintKinds::global().names()) {
      const csp::ConstraintKindInfo& k = csp::ConstraintKinds::global().get(n, {});
      out.append(py::dict(py::arg("name") = n, py::arg("description") = k.description,
                          py::arg("fields") = k.fields, py::arg("example_arity") = k.example_arity,
                          py::arg("example") = k.example));
    }
    return out;
  }, "Every registered constraint kind with its fields and an example (its scope's size, and its "
     "fields as a problem file writes them).");
  py::class_<PyScene>(m, "Scene",
                      "A scene read once (load_scene): follow, compose, evaluate_pose and evaluate_trace "
                      "take it as they take a path, without reading the file again.")
      .def_property_readonly("path", [](const PyScene& s) { return s.path; })
      .def_property_readonly("name", [](const PyScene& s) { return s.scene->name(); })
      .def_property_readonly("frames", [](const PyScene& s) { return s.scene->frame_count(); })
      .def_property_readonly("frame_rate", [](const PyScene& s) { return s.scene->frame_rate(); })
      .def_property_readonly("has_shot", [](const PyScene& s) { return s.scene->shot() != nullptr; })
      .def_property_readonly(
          "people",
          [](const PyScene& s) {
            std::vector<std::string> names;  // those a shot's properties can name
            if (s.scene->has_character()) names.push_back(s.scene->character_name());
            for (const camera::Actor& a : s.scene->actors()) names.push_back(a.name);
            return names;
          },
          "the followed character (when the scene has one), then the actors")
      .def("__repr__", [](const PyScene& s) {
        return "<sightline.Scene '" + s.scene->name() + "' from " + s.path + ", " +
               std::to_string(s.scene->frame_count()) + " frames" + (s.scene->shot() ? ", a shot" : "") + ">";
      });
  m.def("load_scene", &load_scene, py::arg("path"),
        "Reads a scene file (and the level, movers and actors it names) once: a Scene.");
  m.def("follow", &follow, py::arg("scene"), py::arg("solver") = "", py::arg("profile") = "",
        py::arg("seed") = 1,
        "Films a scene: {'trace': numpy structured array, 'summary': str, 'metrics': dict}; a scene "
        "with only a script is edited (solver: the editing model's, default chain; 'greedy'), "
        "adding 'shots' [(start, name)] and 'edit' (the continuity judge's metrics).");
  m.def("compose", &compose, py::arg("scene"), py::arg("solver") = "", py::arg("time") = py::none(),
        py::arg("budget_ms") = 20.0, py::arg("seed") = 1, py::arg("options") = py::dict(),
        "Solves a scene's shot: at one instant (time None: the earliest keyframe), as `sightline "
        "compose`: the pose (position, look_at, roll, fov, aspect), feasible, why_infeasible, "
        "satisfaction, cost, properties [{kind, targets, line, hard, measure, score}], solver, "
        "solve_seconds, evaluations.");
  m.def("evaluate_pose", &evaluate_pose, py::arg("scene"), py::arg("pose"), py::arg("time") = py::none(),
        "Judges a pose on a scene's shot, as `sightline compose --evaluate`: `pose` is a pose file's "
        "path or a dict with position, look_at, fov and roll (as compose() returns); the shot's "
        "aspect is used. Returns what compose() does but the solver's fields.");
  m.def("evaluate_trace", &evaluate_trace, py::arg("scene"), py::arg("trace"),
        "Judges every frame of a trace (follow()'s, or anything with columns t, cam_x/y/z, "
        "target_x/y/z, fov, roll) by the scene's shot at the frame's time: numpy arrays t, "
        "satisfaction, cost, feasible, scores and measures (frames x properties), why_infeasible "
        "(one str a frame, empty when feasible) and properties [{kind, targets, line, hard}].");
  m.def("run_suite", &run_suite, py::arg("suite"), py::arg("out"), py::arg("jobs") = 1,
        py::arg("isolated") = false, py::arg("program") = "",
        "Runs (or resumes) a suite into `out`; isolated runs need `program` (the sightline binary).");
}
