#include "sightline/experiments/execution/run_isolation.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <vector>

extern char** environ;

namespace sightline::experiments {
namespace {

double seconds_of(const timeval& t) { return t.tv_sec + t.tv_usec * 1e-6; }

// The CPU limit the kernel enforces: whole seconds, rounded up.
rlim_t cpu_limit_seconds(double seconds) { return static_cast<rlim_t>(std::ceil(seconds)); }

void memout_handler() {
  static const char message[] = "sightline: out of memory (an allocation was refused)\n";
  (void)!::write(STDERR_FILENO, message, sizeof message - 1);
  ::_exit(kExitMemout);
}

// The runner's environment without the variables that tie a process to an MPI job (Open
// MPI's OMPI_*, PMIx's PMIX_*, PMI_*): inside an MPI rank, a child that inherited them and
// initialised MPI would present itself to the job as that rank. The child never uses MPI.
std::vector<char*> child_environment() {
  std::vector<char*> env;
  for (char** e = environ; *e; ++e) {
    const std::string_view v(*e);
    if (v.rfind("OMPI_", 0) == 0 || v.rfind("PMIX_", 0) == 0 || v.rfind("PMI_", 0) == 0) continue;
    env.push_back(*e);
  }
  env.push_back(nullptr);
  return env;
}

}  // namespace

ChildOutcome run_child(const std::vector<std::string>& args, const std::string& log_path,
                       const RunLimits& limits) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Its own process group, so a timeout kills the run and whatever it started; default
  // signal dispositions and an empty mask, whatever the runner (or MPI) set for itself.
  posix_spawnattr_setpgroup(&attributes, 0);
  sigset_t defaults, empty;
  sigemptyset(&defaults);
  for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGXCPU, SIGSEGV, SIGABRT, SIGCHLD}) {
    sigaddset(&defaults, s);
  }
  sigemptyset(&empty);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &empty);
  posix_spawnattr_setflags(&attributes,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);

  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  pid_t pid = 0;
  const int error =
      posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), child_environment().data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ChildOutcome out;
  if (error != 0) {
    out.how = "spawn-failed";
    out.note = "cannot start " + args[0] + ": " + std::strerror(error);
    return out;
  }

  // Wait: on a pidfd (Linux 5.3+), which wakes the moment the child ends; without one,
  // short sleeps first (most runs of a big suite are short), growing to 5 ms.
  const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
  int status = 0;
  rusage usage{};
  bool wall_timeout = false;
  auto pause = std::chrono::microseconds(50);
  while (true) {
    const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      ::kill(-pid, SIGKILL);
      if (pidfd >= 0) ::close(pidfd);
      throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
    }
    if (limits.wall_seconds > 0 && elapsed() >= limits.wall_seconds) {
      ::kill(-pid, SIGKILL);  // the group: the run and anything it started
      wall_timeout = true;
      while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
      }
      break;
    }
    if (pidfd >= 0) {
      double wait_ms = 1000;  // at most a second between looks at the clock
      if (limits.wall_seconds > 0) {
        wait_ms = std::min(wait_ms, (limits.wall_seconds - elapsed()) * 1000 + 1);
      }
      pollfd ready{pidfd, POLLIN, 0};
      ::poll(&ready, 1, std::max(1, static_cast<int>(wait_ms)));
    } else {
      std::this_thread::sleep_for(pause);
      pause = std::min(pause * 2, std::chrono::microseconds(5000));
    }
  }
  if (pidfd >= 0) ::close(pidfd);
  // Whatever the run started and left behind goes with it.
  ::kill(-pid, SIGKILL);
  out.wall_seconds = elapsed();
  out.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
  out.max_rss_mb = usage.ru_maxrss / 1024.0;

  const bool cpu_spent =
      limits.cpu_seconds > 0 &&
      out.cpu_seconds >= static_cast<double>(cpu_limit_seconds(limits.cpu_seconds));
  if (wall_timeout) {
    out.how = "timeout";
    out.signal = SIGKILL;
    out.note =
        "wall time limit of " + limit_seconds_text(limits.wall_seconds) + " s reached; killed";
  } else if (WIFSIGNALED(status)) {
    out.signal = WTERMSIG(status);
    if (out.signal == SIGXCPU || (out.signal == SIGKILL && cpu_spent)) {
      out.how = "timeout";
      out.note = "CPU time limit of " + limit_seconds_text(limits.cpu_seconds) + " s reached";
    } else {
      out.how = "crash";
      out.note = "killed by signal " + std::to_string(out.signal) + " (" +
                 std::string(strsignal(out.signal)) + ")";
    }
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == kExitMemout) {
    out.how = "memout";
    out.exit_code = kExitMemout;
    out.note = "out of memory: an allocation was refused" +
               (limits.memory_mb > 0
                    ? " under the memory limit of " + std::to_string(limits.memory_mb) + " MB"
                    : std::string());
  } else {
    out.how = "exited";
    out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return out;
}

void apply_limits_to_this_process(const RunLimits& limits) {
  auto set = [](int resource, rlim_t soft, rlim_t hard, const char* name) {
    rlimit current{};
    ::getrlimit(resource, &current);
    // Never raise what the runner itself was given (a cluster's own limits stay in force).
    if (current.rlim_max != RLIM_INFINITY) {
      hard = std::min(hard, current.rlim_max);
      soft = std::min(soft, hard);
    }
    const rlimit value{soft, hard};
    if (::setrlimit(resource, &value) != 0) {
      throw std::runtime_error(std::string("cannot set the ") + name +
                               " limit: " + std::strerror(errno));
    }
  };
  if (limits.cpu_seconds > 0) {
    // SIGXCPU at the limit; SIGKILL a second later if something ignores it.
    const rlim_t soft = cpu_limit_seconds(limits.cpu_seconds);
    set(RLIMIT_CPU, soft, soft + 1, "CPU time");
  }
  if (limits.memory_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(limits.memory_mb) * 1024 * 1024;
    set(RLIMIT_AS, bytes, bytes, "memory");
  }
}

void install_child_guards() {
  std::set_new_handler(memout_handler);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() == 1) ::_exit(1);  // the runner died before the line above
}

void inject_test_fault(const std::string& run_id, const RunLimits& limits) {
  const char* spec = std::getenv("SIGHTLINE_TEST_FAULT");
  if (!spec) return;
  std::istringstream items(spec);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::size_t colon = item.find(':');
    if (colon == std::string::npos) continue;
    const std::string kind = item.substr(0, colon);
    const std::string text = item.substr(colon + 1);
    if (text.empty() || run_id.find(text) == std::string::npos) continue;
    if (kind == "crash") {
      std::raise(SIGSEGV);
    } else if (kind == "hang") {
      if (limits.wall_seconds <= 0) throw std::runtime_error("test fault hang needs a wall limit");
      while (true) std::this_thread::sleep_for(std::chrono::seconds(1));
    } else if (kind == "spin") {
      if (limits.cpu_seconds <= 0) throw std::runtime_error("test fault spin needs a CPU limit");
      volatile std::uint64_t x = 0;
      while (true) x = x + 1;
    } else if (kind == "memory") {
      if (limits.memory_mb == 0) throw std::runtime_error("test fault memory needs a memory limit");
      std::vector<char*> blocks;
      while (true) {
        char* block = new char[16 << 20];
        std::memset(block, 1, 16 << 20);  // touched, so it is really used
        blocks.push_back(block);
      }
    }
  }
}

}  // namespace sightline::experiments
