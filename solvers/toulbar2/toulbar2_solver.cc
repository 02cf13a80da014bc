#include "sightline/solvers/toulbar2/toulbar2_solver.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "sightline/csp/files/decimal_costs.h"
#include "sightline/csp/files/wcsp_writer.h"
#include "sightline/solvers/detail/start.h"

extern char** environ;

namespace sightline::solvers {
namespace fs = std::filesystem;

namespace {

// A stream buffer that drops everything: unsuitable_reason writes the problem to see
// whether the writer can express it.
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

// A fresh private directory under the system's temporary directory, removed on scope exit
// unless kept.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "sightline-toulbar2-XXXXXX").string();
    if (!mkdtemp(pattern.data())) {
      throw std::runtime_error(std::string("toulbar2: cannot create a temporary directory: ") +
                               std::strerror(errno));
    }
    path_ = pattern;
  }
  ~TempDir() {
    if (!keep_) {
      std::error_code ignored;
      fs::remove_all(path_, ignored);
    }
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }
  void keep() { keep_ = true; }

 private:
  fs::path path_;
  bool keep_ = false;
};

struct Run {
  int status = 0;               // waitpid status
  bool interrupted = false;     // sent SIGINT, at the time limit or on a stop request
  bool stop_requested = false;  // on a stop request (SolveLimits::stop)
};

// Runs `argv` with stdout and stderr to `output`; interrupts it at `time_limit` seconds
// (0 = none) or when `limits` asks to stop, and kills it if it has not stopped a second
// after that.
Run run_program(const std::vector<std::string>& args, const fs::path& output, double time_limit,
                const SolveLimits& limits) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, output.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) {
    throw std::runtime_error("toulbar2: cannot run '" + args[0] + "': " + std::strerror(error));
  }
  Run run;
  double interrupted_at = 0;
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  while (true) {
    const pid_t done = waitpid(pid, &run.status, WNOHANG);
    if (done == pid) return run;
    if (done < 0 && errno != EINTR) {
      throw std::runtime_error(std::string("toulbar2: waitpid failed: ") + std::strerror(errno));
    }
    if (!run.interrupted && ((time_limit > 0 && elapsed() >= time_limit) || limits.stop_requested())) {
      kill(pid, SIGINT);  // toulbar2 stops as on its own timer, writing its best
      run.interrupted = true;
      run.stop_requested = limits.stop_requested();
      interrupted_at = elapsed();
    }
    if (run.interrupted && elapsed() >= interrupted_at + 1.0) kill(pid, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The number after the last occurrence of `key` in `text`, if any.
std::optional<double> number_after_last(const std::string& text, const std::string& key) {
  const std::size_t at = text.rfind(key);
  if (at == std::string::npos) return std::nullopt;
  std::istringstream in(text.substr(at + key.size()));
  double value = 0;
  if (!(in >> value)) return std::nullopt;
  return value;
}

// The node count of toulbar2's last "... in B backtracks and N nodes" line.
std::uint64_t nodes_of(const std::string& text) {
  const std::size_t at = text.rfind(" nodes");
  if (at == std::string::npos) return 0;
  std::size_t begin = at;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(text[begin - 1]))) --begin;
  return begin < at ? std::stoull(text.substr(begin, at - begin)) : 0;
}

// .wcsp costs are integers: fractional weighted costs go scaled by a power of ten, up to
// kMaxCostDecimals places, and toulbar2's reported costs are divided back.
const csp::WcspWriteOptions kWriting{csp::kMaxCostDecimals};

}  // namespace

const OptionSchema<Toulbar2Solver::Options>& Toulbar2Solver::Options::schema() {
  static const OptionSchema<Options> schema = [] {
    OptionSchema<Options> s;
    s.text("binary", &Options::binary, "the toulbar2 program: a path, or a name in PATH");
    s.boolean("keep_files", &Options::keep_files,
              "keep the temporary directory with the .wcsp, solution and output");
    return s;
  }();
  return schema;
}

std::string Toulbar2Solver::Options::validate() const {
  if (binary.empty()) return "binary must name the toulbar2 program";
  return "";
}

Toulbar2Solver::Toulbar2Solver(std::string name, Options options)
    : name_(std::move(name)), options_(std::move(options)) {}

std::string Toulbar2Solver::unsuitable_reason(const csp::Problem& problem) const {
  if (!problem.all_discrete()) return "needs discrete domains (toulbar2 reads .wcsp)";
  NullBuffer null;
  std::ostream out(&null);
  try {
    csp::write_wcsp(problem, out, kWriting);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

void Toulbar2Solver::solve_into(const csp::Problem& problem, std::span<const double> start,
                                const SolveContext& context, SolverResult& result) {
  Budget budget(context);
  result.solutions_at_best = 0;
  result.alternatives.clear();
  result.message.clear();
  result.stop = StopReason::kCompleted;
  detail::prepare_start(problem, start, result.best);

  TempDir dir;
  const fs::path wcsp = dir.path() / "problem.wcsp";
  const fs::path solution = dir.path() / "solution.txt";
  const fs::path output = dir.path() / "output.txt";
  double scale = 1;  // toulbar2's costs are the problem's times this
  {
    std::ofstream out(wcsp);
    scale = csp::write_wcsp(problem, out, kWriting);  // std::invalid_argument: see unsuitable_reason
    if (!out) throw std::runtime_error("toulbar2: cannot write " + wcsp.string());
  }
  std::vector<std::string> args = {options_.binary, wcsp.string(), "-w=" + solution.string(),
                                   "-seed=" + std::to_string(context.seed)};
  const double time_limit = context.limits.time_limit_seconds;
  if (time_limit > 0) {
    args.push_back("-timer=" + std::to_string(static_cast<long long>(std::ceil(time_limit))));
  }
  if (context.limits.max_iterations) {
    args.push_back("-bt=" + std::to_string(context.limits.max_iterations));
  }
  const Run run = run_program(args, output, time_limit, context.limits);
  const std::string report = read_text(output);
  result.iterations = nodes_of(report);
  result.evaluations = 0;

  // The solution: value indices, in variable order.
  std::istringstream solution_text(read_text(solution));
  std::vector<double> indices;
  for (double index; solution_text >> index;) indices.push_back(index);
  const bool found = indices.size() == problem.num_variables();
  if (found) {
    for (csp::VariableId v = 0; v < problem.num_variables(); ++v) {
      const csp::Domain& d = problem.domain(v);
      const double index = indices[v];
      if (!(index >= 0 && index < static_cast<double>(d.size()) && index == std::floor(index))) {
        throw std::runtime_error("toulbar2: solution value " + std::to_string(index) +
                                 " out of range for variable " + problem.variable_name(v));
      }
      result.best[v] = d.value_at(static_cast<std::size_t>(index));
    }
    result.evaluations = 1;  // the score of its solution; toulbar2 does not say when it found
                             // it in a form worth parsing, so no time to best is recorded
  }

  const bool finished = WIFEXITED(run.status) && WEXITSTATUS(run.status) == 0 && !run.interrupted;
  const bool time_expired = run.interrupted || report.find("Time limit expired") != std::string::npos;
  std::optional<double> reported = number_after_last(report, "Optimum: ");
  std::ostringstream message;
  if (finished && reported && found) {
    result.stop = StopReason::kProvenOptimal;
    message << "toulbar2 proved optimality";
  } else if (finished && !found && report.find("No solution") != std::string::npos) {
    message << "toulbar2 proved infeasible";
  } else {
    reported = number_after_last(report, "New solution: ");
    if (const auto primal = number_after_last(report, "Primal bound: ")) reported = primal;
    if (run.stop_requested) {
      result.stop = StopReason::kInterrupted;
    } else if (time_expired) {
      result.stop = StopReason::kTimeLimit;
    } else if (context.limits.max_iterations && report.find("Primal bound") != std::string::npos) {
      result.stop = StopReason::kIterationLimit;
    }
    message << (found ? "best toulbar2 found, not proved optimal" : "toulbar2 found no solution");
    if (!WIFEXITED(run.status) && !run.interrupted) message << "; toulbar2 was killed by a signal";
    if (WIFEXITED(run.status) && WEXITSTATUS(run.status) != 0) {
      message << "; toulbar2 exited with status " << WEXITSTATUS(run.status);
    }
  }
  finish_result(problem, context, budget, result);
  if (found && reported) {
    const double cost = *reported / scale;
    if (std::abs(cost - result.score.soft) > 1e-9 * std::max(1.0, std::abs(cost))) {
      message << "; toulbar2 reports cost " << cost << " but the problem scores " << result.score.soft;
    }
  }
  if (found && !result.feasible()) message << "; its solution breaks a hard constraint here";
  if (options_.keep_files) {
    dir.keep();
    message << "; files in " << dir.path().string();
  }
  result.message = message.str();
}

std::optional<std::string> find_toulbar2(const std::string& name) {
  auto executable = [](const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
  };
  if (name.find('/') != std::string::npos) {
    return executable(name) ? std::optional<std::string>(name) : std::nullopt;
  }
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / name;
    if (executable(candidate)) return candidate.string();
  }
  return std::nullopt;
}

bool register_toulbar2_solver(SolverRegistry& registry) {
  if (registry.contains("toulbar2")) return true;
  if (!find_toulbar2()) return false;
  register_solver<Toulbar2Solver>(
      registry, "toulbar2",
      "the toulbar2 program on the problem written as .wcsp (exact; soft arc consistency)");
  return true;
}

}  // namespace sightline::solvers
