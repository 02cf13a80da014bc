#include "sightline/csp/files/problem_file.h"

#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/files/yaml_spec.h"
#include "sightline/csp/kinds/constraint_entry.h"

namespace sightline::csp {
namespace {

const char* const kDomainFields[] = {"int", "values", "real", "labels"};

// Reads the one domain field of a variable entry; also returns the labels, if any.
Domain read_domain(const Spec& entry, std::vector<std::string>& labels) {
  const Spec* field = nullptr;
  const char* which = nullptr;
  for (const char* name : kDomainFields) {
    if (const Spec* f = entry.find(name)) {
      if (field != nullptr) {
        f->fail(std::string("a variable has one domain, but both '") + which + "' and '" + name +
                "' are given");
      }
      field = f;
      which = name;
    }
  }
  if (field == nullptr) {
    entry.fail(
        "expected a domain for the variable: int: [lo, hi], values: [...], "
        "real: [lo, hi] or labels: [...]");
  }
  const std::string key = which;
  try {
    if (key == "int" || key == "real") {
      const auto& bounds = field->items("a list [lo, hi] for '" + key + "'");
      if (bounds.size() != 2) {
        field->fail("expected two bounds [lo, hi] for '" + key + "', got " +
                    std::to_string(bounds.size()) + " values");
      }
      if (key == "int") {
        return Domain::integer_range(bounds[0].as_integer("an integer lower bound"),
                                     bounds[1].as_integer("an integer upper bound"));
      }
      return Domain::real_interval(bounds[0].as_number("a finite lower bound"),
                                   bounds[1].as_number("a finite upper bound"));
    }
    if (key == "values") {
      const auto& items = field->items("a list of numbers for 'values'");
      std::vector<double> values;
      for (const Spec& item : items) {
        const double v = item.as_number("a number in 'values'");
        for (double seen : values) {
          if (seen == v) item.fail("value " + item.preview() + " appears twice in 'values'");
        }
        values.push_back(v);
      }
      if (values.empty()) field->fail("expected at least one value in 'values' (empty domain)");
      return Domain::value_set(std::move(values));
    }
    // labels: symbolic values, stored as their indices 0 .. n-1.
    const auto& items = field->items("a list of names for 'labels'");
    for (const Spec& item : items) {
      const std::string& label = item.as_string("a name in 'labels'");
      for (const std::string& seen : labels) {
        if (seen == label) item.fail("label '" + label + "' appears twice");
      }
      labels.push_back(label);
    }
    if (labels.empty()) field->fail("expected at least one name in 'labels' (empty domain)");
    return Domain::integer_range(0, static_cast<std::int64_t>(labels.size()) - 1);
  } catch (const std::invalid_argument& e) {
    field->fail(e.what());
  }
}

class Reader {
 public:
  Reader(const Spec& document, const std::string& default_name) : doc_(document) {
    result_.problem = std::make_unique<Problem>(default_name);
  }

  LoadedProblem read() {
    if (!doc_.is_map())
      doc_.fail("expected a problem: a mapping with 'variables' and 'constraints'");
    doc_.check_keys({"name", "description", "variables", "parameters", "constraints"});
    if (const Spec* name = doc_.find("name")) {
      problem().set_name(name->as_string("a problem name"));
    }
    result_.description = doc_.string_or("description", "");
    read_variables(doc_.at("variables"));
    if (const Spec* parameters = doc_.find("parameters")) read_parameters(*parameters);
    if (const Spec* constraints = doc_.find("constraints")) read_constraints(*constraints);
    result_.value_labels.resize(problem().num_variables());
    return std::move(result_);
  }

 private:
  Problem& problem() { return *result_.problem; }

  // Names of variables, arrays and parameters share one namespace: scopes and formulas
  // could not tell them apart otherwise.
  void claim_name(const std::string& name, const Spec& where, const std::string& what) {
    if (name.empty()) where.fail("expected a non-empty name");
    auto [it, inserted] = names_.emplace(name, what);
    if (!inserted) where.fail("name '" + name + "' is already used by a " + it->second);
  }

  void add_variable(const std::string& name, const Spec& where, const Domain& domain,
                    const std::vector<std::string>& labels) {
    claim_name(name, where, "variable");
    const VariableId id = problem().add_variable(name, domain);
    if (!labels.empty()) {
      result_.value_labels.resize(id + 1);
      result_.value_labels[id] = labels;
    }
  }

  void read_variables(const Spec& list) {
    const auto& entries = list.items("a list of variables under 'variables'");
    if (entries.empty()) list.fail("expected at least one variable under 'variables'");
    for (const Spec& entry : entries) {
      if (!entry.is_map()) entry.fail("expected a variable: {name: x, int: [lo, hi]} or similar");
      entry.check_keys({"name", "names", "count", "int", "values", "real", "labels"});
      std::vector<std::string> labels;
      const Domain domain = read_domain(entry, labels);
      const Spec* name = entry.find("name");
      const Spec* names = entry.find("names");
      const Spec* count = entry.find("count");
      if ((name == nullptr) == (names == nullptr)) {
        entry.fail(
            "expected exactly one of 'name' (one variable, or an array with 'count') "
            "and 'names' (a list of variables)");
      }
      if (names != nullptr) {
        if (count != nullptr) count->fail("'count' goes with 'name', not with 'names'");
        const auto& items = names->items("a list of names for 'names'");
        if (items.empty()) names->fail("expected at least one name in 'names'");
        for (const Spec& item : items) {
          add_variable(item.as_string("a variable name"), item, domain, labels);
        }
      } else if (count != nullptr) {
        // An array: name q with count n declares q0 .. q{n-1}; `q` in a scope means all of them.
        const std::string& base = name->as_string("an array name");
        const long long n = count->as_integer("a count (an integer >= 1)");
        if (n < 1) count->fail("expected a count >= 1, got " + count->preview());
        claim_name(base, *name, "variable array");
        std::vector<VariableId>& members = arrays_[base];
        for (long long i = 0; i < n; ++i) {
          add_variable(base + std::to_string(i), *name, domain, labels);
          members.push_back(static_cast<VariableId>(problem().num_variables() - 1));
        }
      } else {
        add_variable(name->as_string("a variable name"), *name, domain, labels);
      }
    }
  }

  void read_parameters(const Spec& map) {
    if (!map.is_map()) map.fail("expected parameters as a mapping name: value");
    for (const auto& [name, value] : map.fields()) {
      claim_name(name, value, "parameter");
      problem().parameters().add(name, value.as_number("a number for parameter '" + name + "'"));
    }
  }

  std::vector<VariableId> resolve_scope(const Spec& list) {
    std::vector<VariableId> scope;
    for (const Spec& item : list.items("a list of variable names for the scope")) {
      const std::string& name = item.as_string("a variable name in the scope");
      if (auto id = problem().find_variable(name)) {
        scope.push_back(*id);
      } else if (auto array = arrays_.find(name); array != arrays_.end()) {
        scope.insert(scope.end(), array->second.begin(), array->second.end());
      } else {
        item.fail("unknown variable '" + name + "' in the scope" + known_variables());
      }
    }
    if (scope.empty()) list.fail("expected at least one variable in the scope");
    return scope;
  }

  std::string known_variables() const {
    const auto& vars = result_.problem->variables();
    if (vars.size() > 12)
      return " (the file declares " + std::to_string(vars.size()) + " variables)";
    std::string known;
    for (const auto& v : vars) known += (known.empty() ? "" : ", ") + v.name;
    return " (variables: " + known + ")";
  }

  void read_constraints(const Spec& list) {
    const ConstraintKinds& kinds = ConstraintKinds::global();
    for (const Spec& entry : list.items("a list of constraints under 'constraints'")) {
      if (!entry.is_map()) entry.fail("expected a constraint: {kind: ..., scope: [...], ...}");
      const Spec& kind_field = entry.at("kind");
      const std::string& kind = kind_field.as_string("a constraint kind name");
      kinds.get(kind, kind_field.where());  // unknown kinds fail at the kind, listing the known
      const double weight = read_weight(entry);
      const bool hard = read_hard(entry);

      const Spec* scope = entry.find("scope");
      const Spec* vars = entry.find("vars");
      const Spec* scopes = entry.find("scopes");
      if ((scope != nullptr) + (vars != nullptr) + (scopes != nullptr) != 1) {
        entry.fail(
            "expected exactly one of 'scope' (or its synonym 'vars') and 'scopes' "
            "(one constraint per listed scope)");
      }
      if (scopes == nullptr) {
        add(kinds, kind, *(scope ? scope : vars), weight, hard, entry);
        continue;
      }
      // `scopes`: the same constraint over each listed scope. The kind sees the entry without
      // the `scopes` field, so its field check stays the usual one.
      std::vector<std::pair<std::string, Spec>> fields;
      for (const auto& [k, v] : entry.fields()) {
        if (k != "scopes") fields.emplace_back(k, v);
      }
      const Spec single = Spec::map(std::move(fields), entry.where());
      const auto& each = scopes->items("a list of scopes for 'scopes'");
      if (each.empty()) scopes->fail("expected at least one scope in 'scopes'");
      for (const Spec& one : each) {
        const ConstraintId id = add(kinds, kind, one, weight, hard, single);
        // One label for several constraints: each is told apart by its scope, in every
        // message, table and breakdown ("no clash(r5, r7)").
        Constraint& c = problem().mutable_constraint(id);
        if (each.size() > 1 && !c.label().empty()) {
          c.set_label(c.label() + "(" + problem().scope_names(id) + ")");
        }
      }
    }
  }

  ConstraintId add(const ConstraintKinds& kinds, const std::string& kind, const Spec& scope_field,
                   double weight, bool hard, const Spec& entry) {
    std::vector<VariableId> scope = resolve_scope(scope_field);
    // Repeated variables are refused by Problem; say where.
    for (std::size_t i = 0; i < scope.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (scope[i] == scope[j]) {
          scope_field.fail("variable '" + problem().variable_name(scope[i]) +
                           "' appears twice in the scope");
        }
      }
    }
    // The location of the scope line points at this very constraint when `scopes` lists many.
    const SourceLocation where = scope_field.where().line > 0 ? scope_field.where() : entry.where();
    // An expression may name its scope's value labels: they become its constants (label i
    // is value i), unless the entry gives constants of its own.
    Spec with_labels;
    if (kind == "expression" && !entry.find("constants")) {
      std::vector<std::pair<std::string, Spec>> constants;
      std::unordered_map<std::string, std::pair<std::size_t, VariableId>> seen;
      for (VariableId v : scope) {
        if (v >= result_.value_labels.size()) continue;
        const auto& labels = result_.value_labels[v];
        for (std::size_t i = 0; i < labels.size(); ++i) {
          const std::string& label = labels[i];
          if (names_.count(label) || problem().parameters().find(label)) continue;  // a name wins
          if (const auto it = seen.find(label); it != seen.end()) {
            if (it->second.first != i) {
              scope_field.fail("label '" + label + "' is value " + std::to_string(it->second.first) +
                               " of " + problem().variable_name(it->second.second) + " and value " +
                               std::to_string(i) + " of " + problem().variable_name(v) +
                               ": a formula could not tell which; give constants: yourself");
            }
            continue;
          }
          seen[label] = {i, v};
          constants.emplace_back(label, Spec::number(static_cast<double>(i)));
        }
      }
      if (!constants.empty()) {
        std::vector<std::pair<std::string, Spec>> fields(entry.fields().begin(), entry.fields().end());
        fields.emplace_back("constants", Spec::map(std::move(constants), entry.where()));
        with_labels = Spec::map(std::move(fields), entry.where());
      }
    }
    auto constraint = create_constraint(kinds, problem(), kind, std::move(scope), weight, hard,
                                        with_labels.is_map() ? with_labels : entry, where);
    try {
      return problem().add_constraint(std::move(constraint));
    } catch (const std::invalid_argument& e) {
      throw InputError(where, e.what());
    }
  }

  const Spec& doc_;
  LoadedProblem result_;
  std::unordered_map<std::string, std::string> names_;  // name -> what it names
  std::unordered_map<std::string, std::vector<VariableId>> arrays_;
};

std::string stem_of(const std::string& origin) {
  const std::string stem = std::filesystem::path(origin).stem().string();
  return stem.empty() ? "problem" : stem;
}

}  // namespace

const std::string* find_value_label(const std::vector<std::vector<std::string>>& value_labels,
                                    VariableId var, double value) {
  if (var >= value_labels.size()) return nullptr;
  const auto& labels = value_labels[var];
  if (value >= 0 && value < static_cast<double>(labels.size()) &&
      value == static_cast<double>(static_cast<std::size_t>(value))) {
    return &labels[static_cast<std::size_t>(value)];
  }
  return nullptr;
}

std::string LoadedProblem::value_name(VariableId var, double value) const {
  if (const std::string* label = find_value_label(value_labels, var, value)) return *label;
  std::ostringstream out;
  out << value;
  return out.str();
}

LoadedProblem load_problem_spec(const Spec& document, const std::string& default_name) {
  return Reader(document, default_name).read();
}

LoadedProblem load_problem_text(const std::string& text, const std::string& origin) {
  return load_problem_spec(parse_yaml(text, origin), stem_of(origin));
}

LoadedProblem load_problem_file(const std::string& path) {
  return load_problem_spec(read_yaml_file(path), stem_of(path));
}

std::unique_ptr<Problem> read_problem_file(const std::string& path) {
  return load_problem_file(path).problem;
}

std::unique_ptr<Problem> parse_problem(const std::string& text, const std::string& origin) {
  return load_problem_text(text, origin).problem;
}

}  // namespace sightline::csp
