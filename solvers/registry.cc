#include "sightline/solvers/registry.h"

#include <stdexcept>

#include "sightline/solvers/pipeline.h"

namespace sightline::solvers {

void register_builtin_solvers(SolverRegistry& registry);  // builtin.cc

SolverRegistry& SolverRegistry::global() {
  static SolverRegistry* registry = [] {
    auto* r = new SolverRegistry;
    register_builtin_solvers(*r);
    return r;
  }();
  return *registry;
}

void SolverRegistry::add(SolverInfo info) {
  if (info.name.empty() || info.name.find('>') != std::string::npos) {
    throw std::invalid_argument("invalid solver name '" + info.name + "'");
  }
  if (contains(info.name)) throw std::invalid_argument("solver '" + info.name + "' registered twice");
  solvers_.emplace(info.name, std::move(info));
}

const SolverInfo& SolverRegistry::info(const std::string& name) const {
  auto it = solvers_.find(name);
  if (it != solvers_.end()) return it->second;
  std::string known;
  for (const auto& [n, i] : solvers_) known += (known.empty() ? "" : ", ") + n;
  throw OptionError("unknown solver '" + name + "' (known solvers: " + known +
                    "; pipelines join them with '>')");
}

std::vector<std::string> SolverRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [n, i] : solvers_) out.push_back(n);
  return out;
}

std::pair<std::string, std::string> split_option(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw OptionError("option '" + text + "' is not of the form key=value");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::unique_ptr<Solver> SolverRegistry::create(const std::string& name,
                                               const OptionValues& options) const {
  std::vector<std::string> stage_names;
  std::size_t begin = 0;
  while (true) {
    const auto end = name.find('>', begin);
    stage_names.push_back(name.substr(begin, end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  std::vector<const SolverInfo*> infos;
  for (const auto& s : stage_names) {
    if (s.empty()) throw OptionError("solver name '" + name + "' has an empty pipeline stage");
    infos.push_back(&info(s));
  }
  // Distribute options: "stage.key" to that stage, "key" to every stage that has it.
  std::vector<OptionValues> per_stage(infos.size());
  for (const auto& [key, value] : options) {
    bool used = false;
    const auto dot = key.find('.');
    if (dot != std::string::npos) {
      const std::string stage = key.substr(0, dot);
      const std::string sub = key.substr(dot + 1);
      for (std::size_t i = 0; i < infos.size(); ++i) {
        if (infos[i]->name == stage) {
          per_stage[i][sub] = value;  // the stage's own schema reports an unknown sub-key
          used = true;
        }
      }
      if (!used) throw OptionError("option '" + key + "' names stage '" + stage + "', which is not in '" + name + "'");
      continue;
    }
    for (std::size_t i = 0; i < infos.size(); ++i) {
      if (infos[i]->has_option(key)) {
        per_stage[i][key] = value;
        used = true;
      }
    }
    if (!used) {
      std::string valid;
      for (const auto* inf : infos) {
        for (const auto& o : inf->options) valid += (valid.empty() ? "" : ", ") + o.name;
      }
      throw OptionError("no stage of '" + name + "' has an option '" + key +
                        "' (valid options: " + (valid.empty() ? "none" : valid) + ")");
    }
  }
  if (infos.size() == 1) return infos[0]->create(per_stage[0]);
  std::vector<std::unique_ptr<Solver>> stages;
  for (std::size_t i = 0; i < infos.size(); ++i) stages.push_back(infos[i]->create(per_stage[i]));
  return std::make_unique<Pipeline>(name, std::move(stages));
}

}  // namespace sightline::solvers
