#include "sightline/experiments/execution/interruption.h"

#include <atomic>
#include <csignal>

namespace sightline::experiments {
namespace {

std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void on_signal(int) { requested.store(true, std::memory_order_relaxed); }

}  // namespace

struct InterruptionHandlers::Saved {
  struct sigaction interrupt {}, terminate {};
};

bool interruption_requested() { return requested.load(std::memory_order_relaxed); }

void request_interruption() { requested.store(true, std::memory_order_relaxed); }

std::string interruption_text(const SuiteOutcome& outcome) {
  std::string text = "interrupted: " + std::to_string(outcome.results.size()) + " of " +
                     std::to_string(outcome.total) + " runs are done and saved";
  if (outcome.abandoned) {
    text += " (" + std::to_string(outcome.abandoned) + " in flight abandoned, to run again)";
  }
  return text;
}

InterruptionHandlers::InterruptionHandlers() : saved_(new Saved) {
  requested.store(false, std::memory_order_relaxed);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &saved_->interrupt);
  sigaction(SIGTERM, &action, &saved_->terminate);
}

InterruptionHandlers::~InterruptionHandlers() {
  sigaction(SIGINT, &saved_->interrupt, nullptr);
  sigaction(SIGTERM, &saved_->terminate, nullptr);
  delete saved_;
}

}  // namespace sightline::experiments
