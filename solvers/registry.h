// SolverRegistry: every solver, created by name from typed, validated options.
//
// Adding a solver touches one new file pair and one registration line (see builtin.cc, or a
// domain's own registration for domain-aware solvers). Names may be pipelines: "a>b>c" runs
// a, then b from a's result, then c. Options are "key=value" text: a plain key goes to every
// stage that has that option (an error if none has it); "stage.key" targets one stage
// ("sls.max_flips=1000").
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sightline/solvers/options.h"
#include "sightline/solvers/solver.h"

namespace sightline::solvers {

struct SolverInfo {
  std::string name;
  std::string description;          // one line
  std::vector<OptionInfo> options;  // with defaults
  // Answers whether an option name belongs to this solver.
  std::function<bool(const std::string&)> has_option;
  // Builds the solver from options (already restricted to this solver); throws OptionError.
  std::function<std::unique_ptr<Solver>(const OptionValues&)> create;
};

class SolverRegistry {
 public:
  // The process-wide registry with the solvers of solvers/ registered. Domains add theirs
  // with their own registration function (for example the camera's octrees).
  static SolverRegistry& global();

  // Throws std::invalid_argument if the name is taken or contains '>'.
  void add(SolverInfo info);
  bool contains(const std::string& name) const { return solvers_.count(name) != 0; }
  const SolverInfo& info(const std::string& name) const;  // throws OptionError if unknown
  std::vector<std::string> names() const;

  // Creates a solver or pipeline by name. Throws OptionError for an unknown solver name
  // (listing the known ones), an unknown option, or an invalid value.
  std::unique_ptr<Solver> create(const std::string& name, const OptionValues& options = {}) const;

 private:
  std::map<std::string, SolverInfo> solvers_;
};

// Registers a solver class S with `S::Options` (with `static const OptionSchema<Options>&
// schema()` and `std::string validate() const`) and a constructor S(std::string name, Options).
template <class S>
void register_solver(SolverRegistry& registry, std::string name, std::string description) {
  SolverInfo info;
  info.name = name;
  info.description = std::move(description);
  info.options = S::Options::schema().describe();
  info.has_option = [](const std::string& key) { return S::Options::schema().has(key); };
  info.create = [name](const OptionValues& values) -> std::unique_ptr<Solver> {
    return std::make_unique<S>(name, S::Options::schema().parse(values, name));
  };
  registry.add(std::move(info));
}

// Splits "key=value"; throws OptionError when there is no '='.
std::pair<std::string, std::string> split_option(const std::string& text);

}  // namespace sightline::solvers
