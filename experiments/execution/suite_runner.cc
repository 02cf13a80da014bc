#include "sightline/experiments/execution/suite_runner.h"

#include <atomic>

#include "sightline/experiments/execution/interruption.h"

#include "sightline/experiments/runs/output_text.h"

#include <unistd.h>

#include <algorithm>
#include <boost/asio/post.hpp>
#include <boost/asio/thread_pool.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <new>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "sightline/csp/files/problem_file.h"
#include "sightline/experiments/runs/camera_run.h"
#include "sightline/experiments/execution/isolated_run.h"
#include "sightline/experiments/execution/output_manifest.h"
#include "sightline/experiments/suite/suite_problem.h"
#include "sightline/experiments/reports/suite_outputs.h"
#include "sightline/solvers/registry.h"

namespace sightline::experiments {
namespace {

namespace fs = std::filesystem;


std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

// Labels and notes go on one line of a key=value file and into CSV: no line breaks.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

std::string run_file_text(const Suite& suite, const RunResult& r) {
  std::ostringstream out;
  out << "id=" << r.id << "\nkind=" << r.kind << "\nsubject=" << one_line(r.subject)
      << "\nsolver=" << one_line(r.solver) << "\nprofile=" << one_line(r.profile)
      << "\nseed=" << r.seed << "\nstatus=" << r.status << "\nnote=" << one_line(r.note)
      << "\ndefinition=" << r.definition << "\nhost=" << one_line(r.provenance.host)
      << "\ncpu_model=" << one_line(r.provenance.cpu_model)
      << "\nbuild_commit=" << one_line(r.provenance.build_commit)
      << "\ncommand_line=" << one_line(r.provenance.command_line) << '\n';
  if (!r.run_wall_s.empty()) {
    out << "run_wall_s=" << r.run_wall_s << "\nrun_cpu_s=" << r.run_cpu_s
        << "\nrun_max_rss_mb=" << r.run_max_rss_mb << '\n';
  }
  const std::vector<std::string> columns = metric_columns(suite);
  for (std::size_t i = 0; i < columns.size() && i < r.values.size(); ++i) {
    if (!r.values[i].empty()) out << "metric." << columns[i] << '=' << r.values[i] << '\n';
  }
  out << "end=1\n";  // a file without this line was cut short
  return out.str();
}

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%ld:%02ld", s / 60, s % 60);
  return buffer;
}

RunResult skeleton(const Suite& suite, const SuiteRun& run) {
  RunResult r;
  r.id = run.id;
  r.seed = run.seed;
  r.definition = run.definition;
  r.values.assign(metric_columns(suite).size(), "");
  if (run.kind == SuiteRun::Kind::kCamera) {
    r.kind = "camera";
    r.subject = suite.scenes[run.subject].label;
    r.solver = suite.camera_solvers[run.solver].label;
    r.profile = suite.profiles[run.profile].label;
  } else {
    r.kind = "toy";
    r.subject = suite.problems[run.subject].label;
    r.solver = suite.toy_solvers[run.solver].label;
    r.profile = "-";
  }
  return r;
}

void execute_camera(const Suite& suite, const SuiteRun& run, const std::string& trace_path,
                    RunResult& r) {
  const SuiteScene& scene = suite.scenes[run.subject];
  const camera::CameraProfile profile = run_profile(suite, run);
  camera::ChaseCameraOptions options = suite.camera_solvers[run.solver].options;
  options.seed = run.seed;
  const CameraRun camera_run = run_camera(*scene.scene, profile, options);
  if (!trace_path.empty()) write_trace_csv(trace_path, camera_run.trace);
  const std::vector<double> values = metric_values(camera_run.metrics);
  for (std::size_t i = 0; i < values.size(); ++i) r.values[i] = number_text(values[i]);
  // An edit's or a tracking shot's own columns, where the suite has them.
  const std::vector<std::string> columns = metric_columns(suite);
  auto put = [&](const std::vector<std::string>& names, const std::vector<double>& extra) {
    for (std::size_t i = 0; i < extra.size(); ++i) {
      const auto c = std::find(columns.begin(), columns.end(), names[i]);
      if (c != columns.end()) r.values[static_cast<std::size_t>(c - columns.begin())] = number_text(extra[i]);
    }
  };
  if (camera_run.edit) put(edit_metric_names(), edit_metric_values(*camera_run.edit));
  if (camera_run.shot) put(shot_metric_names(), shot_metric_values(*camera_run.shot));
  r.status = "ok";
}

// The best cost at `fraction` of the time limit from an anytime trajectory ("" without a
// limit, or before the first feasible point).
std::string cost_at(const solvers::SolverResult& result, double limit, double fraction) {
  if (!(limit > 0)) return "";
  std::string cost;
  for (const solvers::AnytimePoint& p : result.trajectory) {
    if (p.seconds > fraction * limit) break;
    if (p.score.feasible()) cost = number_text(p.score.soft);
  }
  return cost;
}

// The anytime trajectory as CSV (seconds,evaluations,cost,hard), beside the run's result.
void write_anytime_csv(const std::string& path, const solvers::SolverResult& result) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << "seconds,evaluations,cost,hard\n";
    for (const solvers::AnytimePoint& p : result.trajectory) {
      out << number_text(p.seconds) << ',' << p.evaluations << ',' << number_text(p.score.soft) << ','
          << number_text(p.score.hard) << '\n';
    }
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  std::filesystem::rename(tmp, path);
}

// The run's best assignment, a variable per row by name (runs/<id>.solution.csv), a value by
// its label where the problem file gives labels (as `solve --format json` writes it), for
// problems of up to kMostSolutionVariables variables (a million queens would write 15 MB a run).
constexpr std::size_t kMostSolutionVariables = 100000;
void write_solution_csv(const std::string& path, const LoadedSuiteProblem& loaded,
                        const solvers::SolverResult& result) {
  const csp::Problem& problem = *loaded.problem;
  if (problem.num_variables() > kMostSolutionVariables) return;
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << "variable,value\n";
    for (csp::VariableId v = 0; v < problem.num_variables(); ++v) {
      const std::string* label = csp::find_value_label(loaded.value_labels, v, result.best[v]);
      out << csv_field(problem.variable_name(v)) << ','
          << (label ? csv_field(*label) : number_text(result.best[v])) << '\n';
    }
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  std::filesystem::rename(tmp, path);
}

void execute_toy(const Suite& suite, const SuiteRun& run, const std::string& file_base,
                 RunResult& r) {
  const LoadedSuiteProblem loaded = load_suite_problem(suite.problems[run.subject]);
  const SuiteToySolver& entry = suite.toy_solvers[run.solver];
  const std::unique_ptr<solvers::Solver> solver =
      solvers::SolverRegistry::global().create(entry.name, entry.options);
  if (const std::string why = solver->unsuitable_reason(*loaded.problem); !why.empty()) {
    r.status = "skipped";
    r.note = why;
    return;
  }
  solvers::SolveContext context;
  context.seed = run.seed;
  context.limits = suite.toy_limits;
  context.want_breakdown = false;
  context.want_trajectory = true;
  const solvers::SolverResult result =
      solver->solve(*loaded.problem, loaded.problem->default_assignment(), context);
  const long long broken =
      loaded.count_broken ? static_cast<long long>(loaded.count_broken(result.best)) : -1;
  const std::size_t first = suite.scenes.empty() ? 0 : metric_names().size();
  const std::vector<std::string> values = {number_text(result.score.soft),
                                           number_text(static_cast<double>(result.score.hard)),
                                           result.feasible() ? "1" : "0",
                                           number_text(result.wall_seconds),
                                           std::to_string(result.evaluations),
                                           std::to_string(result.iterations),
                                           std::string(solvers::to_string(result.stop)),
                                           broken >= 0 ? std::to_string(broken) : std::string(),
                                           // When the best was found, if the solver says.
                                           result.best_found_seconds >= 0
                                               ? number_text(result.best_found_seconds)
                                               : std::string(),
                                           result.best_found_seconds >= 0
                                               ? std::to_string(result.evaluations_at_best)
                                               : std::string(),
                                           // The best cost at checkpoints of the time limit.
                                           cost_at(result, suite.toy_limits.time_limit_seconds, 0.01),
                                           cost_at(result, suite.toy_limits.time_limit_seconds, 0.1),
                                           cost_at(result, suite.toy_limits.time_limit_seconds, 0.5)};
  for (std::size_t i = 0; i < values.size(); ++i) r.values[first + i] = values[i];
  if (!file_base.empty()) {
    write_anytime_csv(file_base + ".anytime.csv", result);
    write_solution_csv(file_base + ".solution.csv", loaded, result);
  }
  r.status = "ok";
  if (loaded.count_broken) r.note = "independent_broken counts " + loaded.broken_name;
  if (const std::string why =
          toy_answer_problem(*loaded.problem, result.best, result.score, broken);
      !why.empty()) {
    r.status = "wrong";
    r.note = why;
  }
}

// Progress on stderr, one line rewritten in place.
class Progress {
 public:
  Progress(bool enabled, std::size_t total, std::size_t reused)
      : enabled_(enabled), total_(total), done_(reused), reused_(reused),
        start_(std::chrono::steady_clock::now()) {
    show();
  }
  void finished_one() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    show();
  }
  void end() {
    if (enabled_) std::cerr << '\n';
  }

 private:
  void show() {
    if (!enabled_) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const std::size_t ran = done_ - reused_;
    std::string left = "?";
    if (ran > 0) left = clock_text(elapsed / ran * (total_ - done_));
    std::cerr << "\rruns " << done_ << '/' << total_ << " (" << reused_ << " reused), elapsed "
              << clock_text(elapsed) << ", about " << left << " left   " << std::flush;
  }
  bool enabled_;
  std::size_t total_, done_, reused_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

}  // namespace


std::string toy_answer_problem(const csp::Problem& problem, const csp::Assignment& best,
                               const csp::Score& reported, long long broken) {
  if (best.size() != problem.num_variables()) {
    return "wrong answer: the assignment has " + std::to_string(best.size()) + " values for " +
           std::to_string(problem.num_variables()) + " variables";
  }
  const csp::Score actual = problem.score(best);
  auto differs = [](double a, double b) {
    return std::abs(a - b) > 1e-6 * std::max({1.0, std::abs(a), std::abs(b)});
  };
  if (differs(actual.hard, reported.hard) || differs(actual.soft, reported.soft)) {
    return "wrong answer: reported hard " + number_text(reported.hard) + ", cost " +
           number_text(reported.soft) + "; a full re-evaluation gives hard " +
           number_text(actual.hard) + ", cost " + number_text(actual.soft);
  }
  // The judge counts what the model's constraints mean (attacking queens: hard; conflicting
  // edges: soft, a Max-CSP), so only a perfect score is comparable whatever the weights.
  if (reported.feasible() && std::abs(reported.soft) <= 1e-9 && broken > 0) {
    return "wrong answer: reported feasible at cost 0, but the independent check counts " +
           std::to_string(broken) + " broken";
  }
  return "";
}


RunResult execute_run(const Suite& suite, const SuiteRun& run, const std::string& file_base) {
  RunResult r = skeleton(suite, run);
  try {
    if (run.kind == SuiteRun::Kind::kCamera) {
      execute_camera(suite, run, file_base.empty() ? "" : file_base + ".trace.csv", r);
    } else {
      execute_toy(suite, run, file_base, r);
    }
  } catch (const std::bad_alloc&) {
    r.status = "memout";
    r.note = "out of memory (std::bad_alloc)";
  } catch (const std::exception& e) {
    r.status = "failed";
    r.note = one_line(e.what());
  }
  return r;
}

bool read_run_file(const std::string& path, RunResult& r) {
  std::ifstream in(path);
  if (!in) return false;
  std::map<std::string, std::string> fields;
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) return false;
    fields[line.substr(0, eq)] = line.substr(eq + 1);
  }
  if (fields["end"] != "1") return false;
  for (const char* key : {"id", "kind", "status", "definition", "seed"}) {
    if (!fields.count(key)) return false;
  }
  r.id = fields["id"];
  r.kind = fields["kind"];
  r.subject = fields["subject"];
  r.solver = fields["solver"];
  r.profile = fields["profile"];
  r.status = fields["status"];
  r.note = fields["note"];
  r.definition = fields["definition"];
  r.provenance = {fields["host"], fields["cpu_model"], fields["build_commit"],
                  fields["command_line"]};
  r.run_wall_s = fields["run_wall_s"];
  r.run_cpu_s = fields["run_cpu_s"];
  r.run_max_rss_mb = fields["run_max_rss_mb"];
  try {
    r.seed = std::stoull(fields["seed"]);
  } catch (const std::exception&) {
    return false;
  }
  r.values.clear();
  for (const auto& [key, value] : fields) {
    if (key.rfind("metric.", 0) == 0) r.values.push_back(key.substr(7) + "=" + value);
  }
  return true;
}

std::string run_file_base(const std::string& out_dir, const std::string& id) {
  return (fs::path(out_dir) / "runs" / id).string();
}

void write_run_file(const Suite& suite, const RunResult& result, const std::string& path) {
  write_atomically(path, run_file_text(suite, result));
}

RunResult record_run_here(const Suite& suite, const SuiteRun& run, const std::string& out_dir,
                          const std::string& command_line) {
  const std::string base = run_file_base(out_dir, run.id);
  RunResult r = execute_run(suite, run, base);
  r.provenance = this_process_provenance();
  r.provenance.command_line = command_line;
  write_run_file(suite, r, base + ".result");
  return r;
}

bool runs_isolated(const Suite& suite, const IsolationOptions& isolation) {
  const bool isolated = isolation.isolated.value_or(suite.isolated) && !isolation.program.empty();
  if (!isolated) {
    bool limited = suite.limits.any();
    for (const auto& s : suite.camera_solvers) limited = limited || s.limits.any();
    for (const auto& s : suite.toy_solvers) limited = limited || s.limits.any();
    if (limited) {
      throw std::runtime_error("suite '" + suite.name +
                               "' sets run limits, which only isolated runs can be held to: "
                               "run it without --in-process or `isolation: false`" +
                               (isolation.program.empty()
                                    ? std::string(" (and name the sightline program)")
                                    : std::string()));
    }
  }
  return isolated;
}

RunResult run_and_record(const Suite& suite, const SuiteRun& run, const std::string& out_dir,
                         const IsolationOptions& isolation) {
  if (runs_isolated(suite, isolation)) return run_isolated(suite, run, out_dir, isolation.program);
  return record_run_here(suite, run, out_dir, this_process_provenance().command_line);
}

RunResult restore_result(const Suite& suite, const SuiteRun& run, const RunResult& stored) {
  // Metric values were stored by name: put them back in this suite's column order.
  const std::vector<std::string> columns = metric_columns(suite);
  RunResult r = skeleton(suite, run);
  r.status = stored.status;
  r.note = stored.note;
  r.provenance = stored.provenance;
  r.run_wall_s = stored.run_wall_s;
  r.run_cpu_s = stored.run_cpu_s;
  r.run_max_rss_mb = stored.run_max_rss_mb;
  for (const std::string& kv : stored.values) {
    const std::size_t eq = kv.find('=');
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (columns[c] == kv.substr(0, eq)) r.values[c] = kv.substr(eq + 1);
    }
  }
  return r;
}

SuiteState read_suite_state(const Suite& suite, const std::string& out_dir) {
  SuiteState state;
  state.runs = expand_runs(suite);
  claim_output_folder(suite, state.runs, out_dir);
  const fs::path runs_dir = fs::path(out_dir) / "runs";
  std::error_code ec;
  fs::create_directories(runs_dir, ec);
  if (ec) throw std::runtime_error("cannot create " + runs_dir.string() + ": " + ec.message());
  state.results.resize(state.runs.size());
  state.finished.assign(state.runs.size(), 0);
  for (std::size_t i = 0; i < state.runs.size(); ++i) {
    const SuiteRun& run = state.runs[i];
    RunResult stored;
    if (read_run_file(run_file_base(out_dir, run.id) + ".result", stored) &&
        stored.definition == run.definition) {
      state.results[i] = restore_result(suite, run, stored);
      state.finished[i] = 1;
      ++state.reused;
    } else {
      state.pending.push_back(i);
    }
  }
  return state;
}


SuiteOutcome run_suite(const Suite& suite, const RunnerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  (void)runs_isolated(suite, options.isolation);  // refuses limits without isolation, early
  SuiteState state = read_suite_state(suite, options.out_dir);
  std::vector<std::size_t> pending = state.pending;
  if (options.max_new_runs > 0 && pending.size() > options.max_new_runs) {
    pending.resize(options.max_new_runs);
  }

  unsigned jobs = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  Progress progress(options.progress && ::isatty(STDERR_FILENO), state.runs.size(),
                    state.reused);
  std::mutex error_mutex;
  std::string write_error;
  std::atomic<std::size_t> ran{0}, abandoned{0};
  {
    const InterruptionHandlers handlers;  // Ctrl-C / SIGTERM: stop starting runs
    boost::asio::thread_pool pool(jobs);
    for (std::size_t i : pending) {
      boost::asio::post(pool, [&, i] {
        if (interruption_requested()) return;
        try {
          state.results[i] =
              run_and_record(suite, state.runs[i], options.out_dir, options.isolation);
          state.finished[i] = 1;
          ++ran;
        } catch (const RunAbandoned&) {
          ++abandoned;
        } catch (const std::exception& e) {
          std::lock_guard<std::mutex> lock(error_mutex);
          write_error = e.what();
        }
        progress.finished_one();
      });
    }
    pool.join();
  }
  progress.end();
  if (!write_error.empty()) throw std::runtime_error(write_error);

  SuiteOutcome outcome = write_suite_outputs(suite, options.out_dir, state);
  outcome.ran = ran;
  outcome.interrupted = interruption_requested();
  outcome.abandoned = abandoned;
  outcome.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_atomically((fs::path(options.out_dir) / "summary.md").string(),
                   markdown_summary(suite, outcome));
  return outcome;
}

}  // namespace sightline::experiments
