// The Python module `sightline` (pybind11; its package is python/sightline/): the library's
// weighted-CSP layer, solvers, cameras and suites for researchers, as Python objects.
//
// Build problems (ProblemBuilder, or problem files: .yaml, .wcsp, .cfn, .col), list solvers
// and kinds, solve with options and limits (the GIL released while solving; Ctrl-C stops a
// solve or a suite and raises KeyboardInterrupt), read results
// (assignment by variable name, cost, breakdown, stop reason, time and evaluations to
// best); run a suite and read its results (scenes, films and shots: camera_bindings.cc).
// Errors become Python exceptions: sightline.InputError (a ValueError with file, line,
// column and detail) for bad input, sightline.OptionError for bad names and options.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "apps/problem_loader.h"
#include "apps/solver_registration.h"
#include "python/camera_bindings.h"
#include "python/interruptible_call.h"
#include "python/option_values.h"
#include "sightline/csp/input_error.h"
#include "sightline/csp/kinds/builder.h"
#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/experiments/execution/interruption.h"
#include "sightline/experiments/execution/suite_runner.h"
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

PyResult solve(const PyProblem& p, const std::string& solver_name, const py::dict& options,
               std::optional<double> time_limit, std::optional<std::uint64_t> max_evaluations,
               std::optional<std::uint64_t> max_iterations, std::uint64_t seed,
               std::optional<std::vector<double>> start) {
  std::unique_ptr<solvers::Solver> solver =
      solvers::SolverRegistry::global().create(solver_name, python::option_values(options));
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
  python::add_camera_bindings(m);  // Scene, load_scene, follow, compose, evaluate_*
  m.def("run_suite", &run_suite, py::arg("suite"), py::arg("out"), py::arg("jobs") = 1,
        py::arg("isolated") = false, py::arg("program") = "",
        "Runs (or resumes) a suite into `out`; isolated runs need `program` (the sightline binary).");
}
