#include "sightline/csp/problem.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace sightline::csp {

namespace {

// Whether `name` is `prefix` followed by a decimal number below `count` without leading
// zeros: one of the names add_variables(prefix, count) makes. The number, if so.
std::optional<std::size_t> generated_index(std::string_view name, std::string_view prefix,
                                           std::size_t count) {
  if (name.size() <= prefix.size() || name.substr(0, prefix.size()) != prefix) return {};
  const std::string_view digits = name.substr(prefix.size());
  if (digits.size() > 1 && digits[0] == '0') return {};
  std::size_t value = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return {};
    if (value > (count / 10) + 1) return {};  // already too large, and no overflow
    value = value * 10 + static_cast<std::size_t>(c - '0');
  }
  if (value >= count) return {};
  return value;
}

std::string generated_name(std::string_view prefix, std::size_t index) {
  char digits[24];
  const auto [end, error] = std::to_chars(digits, digits + sizeof digits, index);
  (void)error;
  std::string name;
  name.reserve(prefix.size() + static_cast<std::size_t>(end - digits));
  name.append(prefix).append(digits, end);
  return name;
}

}  // namespace

VariableId Problem::add_variable(std::string name, Domain domain) {
  if (name.empty()) throw std::invalid_argument("a variable needs a name");
  const auto id = static_cast<VariableId>(num_variables());
  for (const NameRun& run : runs_) {
    if (run.generated && generated_index(name, run.prefix, run.count)) {
      throw std::invalid_argument("variable '" + name + "' is defined twice");
    }
  }
  if (!variable_ids_.emplace(name, id).second) {
    throw std::invalid_argument("variable '" + name + "' is defined twice");
  }
  if (runs_.empty() || runs_.back().generated) {
    runs_.push_back({id, 0, false, {}, named_.size()});
  }
  ++runs_.back().count;
  named_.push_back(std::move(name));
  slot_owner_.push_back(id);
  domain_slot_.push_back(static_cast<std::uint32_t>(domains_.size()));
  domains_.push_back(std::move(domain));
  incidence_ready_.store(false, std::memory_order_release);
  return id;
}

void Problem::check_batch_names(std::string_view prefix, std::size_t count) const {
  auto twice = [](std::string_view name) {
    throw std::invalid_argument("variable '" + std::string(name) + "' is defined twice");
  };
  for (const std::string& name : named_) {
    if (generated_index(name, prefix, count)) twice(name);
  }
  // Two batches can only share a name when one prefix begins the other and the rest of the
  // longer one is digits; then the names of the longer-prefixed batch are checked against
  // the other's form.
  auto digits_only = [](std::string_view text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  for (const NameRun& run : runs_) {
    if (!run.generated || count == 0 || run.count == 0) continue;
    const std::string_view other = run.prefix;
    if (!digits_only(other.size() > prefix.size() ? other.substr(prefix.size())
                                                  : prefix.substr(other.size()))) {
      continue;
    }
    if (other.starts_with(prefix)) {
      for (std::size_t k = 0; k < run.count; ++k) {
        const std::string name = generated_name(other, k);
        if (generated_index(name, prefix, count)) twice(name);
      }
    } else if (prefix.starts_with(other)) {
      for (std::size_t k = 0; k < count; ++k) {
        const std::string name = generated_name(prefix, k);
        if (generated_index(name, other, run.count)) twice(name);
      }
    }
  }
}

VariableId Problem::add_variables(std::string_view prefix, std::size_t count,
                                  const Domain& domain) {
  if (prefix.empty()) throw std::invalid_argument("generated variable names need a prefix");
  check_batch_names(prefix, count);
  const auto first = static_cast<VariableId>(num_variables());
  if (count == 0) return first;
  runs_.push_back({first, count, true, std::string(prefix), 0});
  const auto slot = static_cast<std::uint32_t>(domains_.size());
  domains_.push_back(domain);
  slot_owner_.push_back(kSharedSlot);
  domain_slot_.resize(domain_slot_.size() + count, slot);
  incidence_ready_.store(false, std::memory_order_release);
  return first;
}

const Problem::NameRun& Problem::run_of(VariableId id) const {
  auto it = std::upper_bound(runs_.begin(), runs_.end(), id,
                             [](VariableId v, const NameRun& run) { return v < run.first; });
  return *(it - 1);
}

std::string Problem::constraint_name(ConstraintId id) const {
  const Constraint& c = constraint(id);
  if (!c.label().empty()) return c.label();
  return std::string(c.kind()) + "(" + scope_names(id) + ")";
}

std::string Problem::scope_names(ConstraintId id) const {
  const auto scope = constraint(id).scope();
  std::string names;
  for (std::size_t i = 0; i < scope.size(); ++i) {
    if (i == 6 && scope.size() > 8) return names + ", ... " + std::to_string(scope.size()) + " variables";
    names += (i ? ", " : "") + variable_name(scope[i]);
  }
  return names;
}

std::string Problem::variable_name(VariableId id) const {
  const NameRun& run = run_of(id);
  if (run.generated) return generated_name(run.prefix, id - run.first);
  return named_[run.named_base + (id - run.first)];
}

const std::vector<Variable>& Problem::variables() const {
  if (view_size_.load(std::memory_order_acquire) == num_variables()) return view_;
  std::lock_guard<std::mutex> lock(view_mutex_);
  const std::size_t n = num_variables();
  view_.reserve(n);
  for (std::size_t i = view_.size(); i < n; ++i) {
    const auto v = static_cast<VariableId>(i);
    view_.push_back({variable_name(v), domain(v)});
  }
  view_size_.store(n, std::memory_order_release);
  return view_;
}

void Problem::set_domain(VariableId id, Domain domain) {
  if (id < view_.size()) view_[id].domain = domain;
  std::uint32_t& slot = domain_slot_[id];
  if (slot_owner_[slot] != id) {  // a batch's shared domain: give this variable its own
    slot = static_cast<std::uint32_t>(domains_.size());
    domains_.push_back(std::move(domain));
    slot_owner_.push_back(id);
  } else {
    domains_[slot] = std::move(domain);
  }
}

ConstraintId Problem::add_constraint(std::unique_ptr<Constraint> constraint) {
  const auto scope = constraint->scope();
  if (scope.empty()) throw std::invalid_argument("a constraint needs at least one variable");
  for (VariableId v : scope) {
    if (v >= num_variables()) {
      throw std::invalid_argument("constraint scope names variable id " + std::to_string(v) +
                                  " but the problem has " + std::to_string(num_variables()));
    }
  }
  // Repeated variables would make one-variable deltas wrong; refuse them. A scope that
  // covers a good part of the variables (N-queens' all_differents: all of a million) is
  // checked with one mark per variable, in linear time; a small one by sorting a copy.
  auto repeated = [&](VariableId v) {
    throw std::invalid_argument("variable '" + variable_name(v) +
                                "' appears twice in one constraint's scope");
  };
  if (scope.size() * 8 >= num_variables()) {
    std::vector<bool> seen(num_variables(), false);
    for (VariableId v : scope) {
      if (seen[v]) repeated(v);
      seen[v] = true;
    }
  } else {
    std::vector<VariableId> sorted(scope.begin(), scope.end());
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1; i < sorted.size(); ++i) {
      if (sorted[i] == sorted[i - 1]) repeated(sorted[i]);
    }
  }
  const auto id = static_cast<ConstraintId>(constraints_.size());
  constraints_.push_back(std::move(constraint));
  incidence_ready_.store(false, std::memory_order_release);
  return id;
}

void Problem::build_incidences() const {
  std::lock_guard<std::mutex> lock(incidence_mutex_);
  if (incidence_ready_.load(std::memory_order_acquire)) return;
  // Counting sort of (variable, constraint, position) by variable: two passes over the
  // scopes, and within a variable the constraints stay in id order.
  // Filled backwards from each variable's end, so that no second array of cursors is
  // needed and the starts are where the cursors stop.
  const std::size_t n = num_variables();
  std::size_t total = 0;
  for (const auto& c : constraints_) total += c->scope().size();
  if (total > UINT32_MAX) {
    throw std::length_error("problem '" + name_ + "': " + std::to_string(total) +
                            " variable occurrences in constraint scopes; at most 2^32 - 1");
  }
  incidence_start_.assign(n + 1, 0);
  for (const auto& c : constraints_) {
    for (VariableId v : c->scope()) ++incidence_start_[v];
  }
  for (std::size_t v = 1; v <= n; ++v) incidence_start_[v] += incidence_start_[v - 1];
  incidence_.resize(total);
  for (auto id = static_cast<ConstraintId>(constraints_.size()); id-- > 0;) {
    const auto scope = constraints_[id]->scope();
    for (std::size_t i = scope.size(); i-- > 0;) {
      incidence_[--incidence_start_[scope[i]]] = {id, static_cast<std::uint32_t>(i)};
    }
  }
  incidence_ready_.store(true, std::memory_order_release);
}

std::optional<VariableId> Problem::find_variable(std::string_view name) const {
  if (auto it = variable_ids_.find(std::string(name)); it != variable_ids_.end()) {
    return it->second;
  }
  for (const NameRun& run : runs_) {
    if (!run.generated) continue;
    if (auto k = generated_index(name, run.prefix, run.count)) {
      return run.first + static_cast<VariableId>(*k);
    }
  }
  return std::nullopt;
}

bool Problem::all_discrete() const {
  // Per variable, not per slot: set_domain may have left a batch's slot unused.
  for (std::uint32_t slot : domain_slot_) {
    if (!domains_[slot].is_discrete()) return false;
  }
  return true;
}

bool Problem::all_continuous() const {
  // Per variable, not per slot: set_domain may have left a batch's slot unused.
  for (std::uint32_t slot : domain_slot_) {
    if (!domains_[slot].is_continuous()) return false;
  }
  return true;
}

Score Problem::constraint_score(ConstraintId id, std::span<const double> values) const {
  const Constraint& c = *constraints_[id];
  return c.score_of(c.violation(values));
}

Score Problem::score(std::span<const double> values) const {
  Score total;
  for (ConstraintId id = 0; id < constraints_.size(); ++id) total += constraint_score(id, values);
  return total;
}

Score Problem::score_below(std::span<const double> values, const Score& bound, bool& complete,
                           std::span<Score> terms) const {
  if (terms.size() < constraints_.size()) {
    throw std::invalid_argument("score_below: terms needs one entry per constraint");
  }
  Score partial;
  bool left_out = false;
  for (ConstraintId id = 0; id < constraints_.size(); ++id) {
    if (constraints_[id]->query_cost() > 0) {
      left_out = true;
      continue;
    }
    terms[id] = constraint_score(id, values);
    partial += terms[id];
  }
  complete = !left_out || partial.before(bound);
  if (!complete) return partial;
  Score total;
  for (ConstraintId id = 0; id < constraints_.size(); ++id) {
    if (constraints_[id]->query_cost() > 0) terms[id] = constraint_score(id, values);
    total += terms[id];
  }
  return total;
}

std::vector<ConstraintCost> Problem::breakdown(std::span<const double> values) const {
  std::vector<ConstraintCost> out;
  out.reserve(constraints_.size());
  for (ConstraintId id = 0; id < constraints_.size(); ++id) {
    const Constraint& c = *constraints_[id];
    const double v = c.violation(values);
    out.push_back({id, v, c.weight() * v, c.is_hard()});
  }
  return out;
}

Score Problem::delta(std::span<double> values, VariableId var, double new_value) const {
  Score before, after;
  for (const Incidence& inc : incidences(var)) before += constraint_score(inc.constraint, values);
  const double old_value = values[var];
  values[var] = new_value;
  for (const Incidence& inc : incidences(var)) after += constraint_score(inc.constraint, values);
  values[var] = old_value;
  return after - before;
}

Assignment Problem::default_assignment() const {
  Assignment a(num_variables());
  // Runs of variables share a Domain (a batch from add_variables): its middle is taken
  // once per run, not once per variable.
  const Domain* last = nullptr;
  double middle = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Domain& d = domain(static_cast<VariableId>(i));
    if (&d != last) {
      last = &d;
      middle = d.middle();
    }
    a[i] = middle;
  }
  return a;
}

void Problem::check_assignment(std::span<const double> values) const {
  if (values.size() != num_variables()) {
    throw std::invalid_argument("assignment has " + std::to_string(values.size()) +
                                " values but the problem has " +
                                std::to_string(num_variables()) + " variables");
  }
  // An integer range, the usual discrete domain, is tested here without a call (this runs
  // over every variable at every start and check); other kinds ask the Domain.
  const Domain* last = nullptr;
  bool integer_range = false;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto v = static_cast<VariableId>(i);
    const Domain& d = domain(v);
    if (&d != last) {
      last = &d;
      integer_range = d.kind() == DomainKind::kIntegerRange;
    }
    const double x = values[i];
    if (integer_range && x >= d.lower() && x <= d.upper() && x == std::floor(x)) continue;
    if (integer_range || std::isnan(x) || !d.contains(x)) {
      throw std::invalid_argument("value " + std::to_string(values[i]) + " of variable '" +
                                  variable_name(v) + "' is outside its domain " +
                                  domain(v).describe());
    }
  }
}

}  // namespace sightline::csp
