#include "python/camera_bindings.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/option_values.h"
#include "python/trace_array.h"
#include "sightline/domains/camera/composition/compose.h"
#include "sightline/domains/camera/composition/composition_solvers.h"
#include "sightline/domains/camera/composition/pose_reading.h"
#include "sightline/domains/camera/profile_file.h"
#include "sightline/domains/camera/scene_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/runs/edit_metrics.h"
#include "sightline/solvers/registry.h"

namespace py = pybind11;

namespace sightline::python {
namespace {

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
      solver_name.empty() ? camera::kRecommendedCompositionSolver : solver_name, python::option_values(options));
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
    std::array<const double*, std::size(kColumns)> c{};
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

}  // namespace

void add_camera_bindings(py::module_& m) {
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
}

}  // namespace sightline::python
