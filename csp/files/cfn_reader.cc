#include "sightline/csp/files/cfn_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "sightline/csp/files/compressed_text.h"
#include "sightline/csp/files/json_source.h"
#include "sightline/csp/input_error.h"
#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/table.h"

namespace sightline::csp {
namespace {

// ordered_json: a network's variables are numbered in the order the file gives them.
using Json = nlohmann::ordered_json;

// Domains above this many values are refused, as by the .wcsp reader.
constexpr std::size_t kMaxDomainSize = std::size_t{1} << 31;

class CfnReader {
 public:
  CfnReader(std::string_view text, std::string origin) : source_(text, std::move(origin)) {}

  std::unique_ptr<Problem> read() {
    const Json doc = parse();
    if (!doc.is_object()) fail(0, "expected a JSON object with problem, variables and functions");
    for (const auto& [key, value] : doc.items()) {
      if (key != "problem" && key != "variables" && key != "functions") {
        fail(find_key(key), "unknown key '" + key + "' (expected problem, variables, functions)");
      }
    }
    read_problem(doc);
    if (!doc.contains("variables")) fail(0, "missing 'variables'");
    read_variables(doc["variables"]);
    if (doc.contains("functions")) read_functions(doc["functions"]);
    return std::move(problem_);
  }

 private:
  // --- positions (json_source.h) ---------------------------------------------------------

  [[noreturn]] void fail(std::size_t offset, const std::string& message) const {
    source_.fail(offset, message);
  }
  std::size_t find_key(const std::string& key, std::size_t from = 0) const {
    return source_.find_key(key, from);
  }
  std::size_t function_at(const std::string& name) const {
    const std::size_t functions = find_key("functions");
    const std::size_t at = find_key(name, functions);
    return at ? at : functions;
  }

  // --- parsing ----------------------------------------------------------------------------

  Json parse() {
    return source_.parse("; toulbar2's relaxed CFN syntax (unquoted names, no commas) is not read");
  }

  static bool is_number_text(std::string_view s, double& out) {
    if (s.empty()) return false;
    const char* first = s.data();
    const char* last = first + s.size();
    if (*first == '+') ++first;
    const auto [end, error] = std::from_chars(first, last, out, std::chars_format::fixed);
    return error == std::errc() && end == last && std::isfinite(out);
  }

  // A cost: a number, or a decimal number written as a string.
  double cost(const Json& j, std::size_t where, const std::string& what) const {
    double value = 0;
    if (j.is_number()) {
      value = j.get<double>();
    } else if (!j.is_string() || !is_number_text(j.get<std::string>(), value)) {
      fail(where, "expected " + what + " (a number), got " + j.dump());
    }
    if (!std::isfinite(value)) fail(where, what + " must be finite, got " + j.dump());
    if (value < 0) fail(where, "not supported: negative cost " + j.dump() + " (" + what + ")");
    return value;
  }

  void read_problem(const Json& doc) {
    std::string name = "cfn";
    if (!doc.contains("problem")) fail(0, "missing 'problem' (with \"mustbe\": \"<UB\")");
    const Json& p = doc["problem"];
    const std::size_t at = find_key("problem");
    if (!p.is_object()) fail(at, "expected 'problem' to be an object with name and mustbe");
    for (const auto& [key, value] : p.items()) {
      if (key != "name" && key != "mustbe") {
        fail(find_key(key, at), "unknown key '" + key + "' in problem (expected name, mustbe)");
      }
    }
    if (p.contains("name")) {
      if (!p["name"].is_string()) fail(find_key("name", at), "expected the problem name as a string");
      name = p["name"].get<std::string>();
    }
    const std::size_t mustbe_at = find_key("mustbe", at);
    if (!p.contains("mustbe")) fail(at, "missing \"mustbe\": \"<UB\" in problem");
    if (!p["mustbe"].is_string()) {
      fail(mustbe_at, "expected mustbe as a string \"<UB\", got " + p["mustbe"].dump());
    }
    const std::string mustbe = p["mustbe"].get<std::string>();
    if (!mustbe.empty() && mustbe[0] == '>') {
      fail(mustbe_at, "not supported: maximisation (mustbe \"" + mustbe +
                          "\"); only minimisation, \"<UB\", is read");
    }
    if (mustbe.empty() || mustbe[0] != '<' || !is_number_text(mustbe.substr(1), ub_)) {
      fail(mustbe_at, "expected mustbe as \"<\" and a decimal upper bound, got \"" + mustbe + "\"");
    }
    if (ub_ <= 0) {
      fail(mustbe_at, "not supported: an upper bound <= 0 (\"" + mustbe + "\"): negative costs");
    }
    problem_ = std::make_unique<Problem>(name);
  }

  void add_variable(const std::string& name, const Json& domain, std::size_t at) {
    std::vector<std::string> names;
    std::int64_t size = 0;
    if (domain.is_number_integer()) {
      size = domain.get<std::int64_t>();
      if (size < 0) fail(at, "not supported: interval domain (negative size) of " + name);
    } else if (domain.is_array()) {
      for (const Json& v : domain) {
        if (!v.is_string()) fail(at, "expected value names (strings) in the domain of " + name);
        names.push_back(v.get<std::string>());
      }
      size = static_cast<std::int64_t>(names.size());
      std::vector<std::string> sorted = names;
      std::sort(sorted.begin(), sorted.end());
      if (auto d = std::adjacent_find(sorted.begin(), sorted.end()); d != sorted.end()) {
        fail(at, "value '" + *d + "' appears twice in the domain of " + name);
      }
    } else {
      fail(at, "expected the domain of " + name + " as a size or a list of value names, got " +
                   domain.dump());
    }
    if (size == 0) fail(at, "variable " + name + " has an empty domain");
    if (static_cast<std::size_t>(size) > kMaxDomainSize) {
      fail(at, "not supported: domain size above 2^31 (" + name + ")");
    }
    if (name.empty()) fail(at, "a variable needs a name (got \"\")");
    if (problem_->find_variable(name)) fail(at, "variable " + name + " is declared twice");
    problem_->add_variable(name, Domain::integer_range(0, size - 1));
    sizes_.push_back(size);
    value_names_.push_back(std::move(names));
  }

  void read_variables(const Json& variables) {
    const std::size_t at = find_key("variables");
    if (variables.is_object()) {
      for (const auto& [name, domain] : variables.items()) {
        add_variable(name, domain, find_key(name, at));
      }
    } else if (variables.is_array()) {
      for (std::size_t i = 0; i < variables.size(); ++i) {
        add_variable("x" + std::to_string(i), variables[i], at);
      }
    } else {
      fail(at, "expected 'variables' as an object (name: domain) or an array of domains");
    }
  }

  // --- functions --------------------------------------------------------------------------

  struct Function {
    std::string name;
    std::size_t at = 0;
    std::vector<VariableId> scope;
    const Json* body = nullptr;
  };

  void read_functions(const Json& functions) {
    std::vector<Function> all;
    if (functions.is_object()) {
      for (const auto& [name, body] : functions.items()) {
        all.push_back({name, function_at(name), {}, &body});
      }
    } else if (functions.is_array()) {
      for (std::size_t i = 0; i < functions.size(); ++i) {
        all.push_back({"f" + std::to_string(i), find_key("functions"), {}, &functions[i]});
      }
    } else {
      fail(find_key("functions"), "expected 'functions' as an object (name: function)");
    }
    for (Function& f : all) read_scope(f);
    for (const Function& f : all) {
      const Json& body = *f.body;
      if (body.contains("type")) {
        read_global(f);
      } else if (body.contains("costs") && body["costs"].is_string()) {
        read_shared(f, all);
      } else {
        add_table(f, f, body);
      }
    }
  }

  void read_scope(Function& f) const {
    const Json& body = *f.body;
    if (!body.is_object()) fail(f.at, "expected function " + f.name + " as an object with a scope");
    for (const auto& [key, value] : body.items()) {
      if (key != "scope" && key != "defaultcost" && key != "costs" && key != "type" &&
          key != "params") {
        fail(f.at, "unknown key '" + key + "' in function " + f.name +
                       " (expected scope, defaultcost, costs, type, params)");
      }
    }
    if (!body.contains("scope") || !body["scope"].is_array()) {
      fail(f.at, "function " + f.name + " needs a scope (a list of variables)");
    }
    for (const Json& v : body["scope"]) {
      VariableId id = 0;
      if (v.is_number_integer()) {
        const std::int64_t i = v.get<std::int64_t>();
        if (i < 0 || i >= static_cast<std::int64_t>(sizes_.size())) {
          fail(f.at, "variable index " + v.dump() + " out of range in the scope of " + f.name);
        }
        id = static_cast<VariableId>(i);
      } else if (v.is_string()) {
        const auto found = problem_->find_variable(v.get<std::string>());
        if (!found) fail(f.at, "unknown variable " + v.dump() + " in the scope of " + f.name);
        id = *found;
      } else {
        fail(f.at, "expected a variable name or index in the scope of " + f.name);
      }
      if (std::find(f.scope.begin(), f.scope.end(), id) != f.scope.end()) {
        fail(f.at, "variable " + v.dump() + " appears twice in the scope of " + f.name);
      }
      f.scope.push_back(id);
    }
  }

  // A value in a tuple of `f` at scope position p: an index, or a name of the variable's
  // domain (or an index written as a string).
  double value_index(const Function& f, std::size_t p, const Json& v) const {
    const VariableId var = f.scope[p];
    const std::int64_t size = sizes_[var];
    std::int64_t index = -1;
    if (v.is_number_integer()) {
      index = v.get<std::int64_t>();
    } else if (v.is_string()) {
      const std::string& text = v.get_ref<const std::string&>();
      const auto& names = value_names_[var];
      if (const auto it = std::find(names.begin(), names.end(), text); it != names.end()) {
        index = it - names.begin();
      } else {
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
        if (error != std::errc() || end != text.data() + text.size()) {
          fail(f.at, "unknown value " + v.dump() + " of variable " +
                         problem_->variable_name(var) + " in function " + f.name);
        }
      }
    } else {
      fail(f.at, "expected a value name or index in function " + f.name + ", got " + v.dump());
    }
    if (index < 0 || index >= size) {
      fail(f.at, "value index " + std::to_string(index) + " out of range for variable " +
                     problem_->variable_name(var) + " (" + std::to_string(size) +
                     " values) in function " + f.name);
    }
    return static_cast<double>(index);
  }

  // `table` holds the costs (itself, or the function it shares them with); `f` the scope.
  void add_table(const Function& f, const Function& table, const Json& body) {
    if (!body.contains("costs") || !body["costs"].is_array()) {
      fail(table.at, "function " + table.name + " needs costs (a list) or a type");
    }
    const Json& costs = body["costs"];
    const std::size_t arity = f.scope.size();
    std::vector<double> values, tuple_costs;
    double default_cost = 0;
    if (body.contains("defaultcost")) {  // sparse: tuples, each followed by its cost
      default_cost = cost(body["defaultcost"], table.at, "the default cost of " + table.name);
      if (costs.size() % (arity + 1) != 0) {
        fail(table.at, "function " + table.name + " lists " + std::to_string(costs.size()) +
                           " items, not a multiple of arity + 1 = " + std::to_string(arity + 1) +
                           " (each tuple's values, then its cost)");
      }
      for (std::size_t i = 0; i < costs.size(); i += arity + 1) {
        for (std::size_t p = 0; p < arity; ++p) values.push_back(value_index(table, p, costs[i + p]));
        tuple_costs.push_back(cost(costs[i + arity], table.at, "a cost of " + table.name));
      }
    } else {  // dense: one cost per tuple, the last variable changing fastest
      std::size_t expected = 1;
      for (VariableId v : f.scope) {
        expected *= static_cast<std::size_t>(sizes_[v]);
        if (expected > costs.size()) break;
      }
      if (expected != costs.size()) {
        fail(table.at, "function " + table.name + " has no defaultcost, so its costs must list "
                       "every tuple: " + std::to_string(costs.size()) + " given, the scope has " +
                       (expected > costs.size() ? "more" : std::to_string(expected)));
      }
      std::vector<std::int64_t> tuple(arity, 0);
      for (std::size_t i = 0; i < costs.size(); ++i) {
        for (std::size_t p = 0; p < arity; ++p) values.push_back(static_cast<double>(tuple[p]));
        tuple_costs.push_back(cost(costs[i], table.at, "a cost of " + table.name));
        for (std::size_t p = arity; p-- > 0;) {  // next tuple, lexicographic
          if (++tuple[p] < sizes_[f.scope[p]]) break;
          tuple[p] = 0;
        }
      }
    }
    add_split(f, default_cost, values, tuple_costs);
  }

  // The same split as the .wcsp reader's: a hard table for the forbidden tuples (>= UB), a
  // soft one for the others, each left out when empty.
  void add_split(const Function& f, double default_cost, const std::vector<double>& values,
                 const std::vector<double>& costs) {
    const std::size_t arity = f.scope.size();
    if (arity == 0) {  // a constant: its own tuple (if any) overrides the default
      const double c = costs.empty() ? default_cost : costs.back();
      if (costs.size() > 1) fail(f.at, "a constant (empty scope) function has one cost at most");
      if (c == 0) return;
      if (problem_->num_variables() == 0) {
        fail(f.at, "not supported: a constant cost in a problem without variables");
      }
      const bool hard = c >= ub_;
      add(f, f.name + (hard ? "/hard" : "") + " (constant)", {0}, {}, {}, hard ? 1.0 : c, hard);
      return;
    }
    auto forbidden = [&](double c) { return c >= ub_; };
    const bool default_forbidden = forbidden(default_cost);
    const bool any = default_forbidden || std::any_of(costs.begin(), costs.end(), forbidden);
    std::vector<double> part_values, part_costs;
    auto push = [&](std::size_t i, double c) {
      part_values.insert(part_values.end(), values.begin() + i * arity,
                         values.begin() + (i + 1) * arity);
      part_costs.push_back(c);
    };
    if (any) {
      for (std::size_t i = 0; i < costs.size(); ++i) {
        if (forbidden(costs[i]) != default_forbidden) push(i, default_forbidden ? 0.0 : 1.0);
      }
      add(f, f.name + "/hard", f.scope, part_values, part_costs, default_forbidden ? 1.0 : 0.0,
          true);
    }
    double soft_default = default_cost;
    if (default_forbidden) {  // never met by a feasible assignment: the cheapest allowed
      soft_default = -1;
      for (double c : costs) {
        if (!forbidden(c) && (soft_default < 0 || c < soft_default)) soft_default = c;
      }
      soft_default = std::max(soft_default, 0.0);
    }
    part_values.clear();
    part_costs.clear();
    for (std::size_t i = 0; i < costs.size(); ++i) {
      if (!forbidden(costs[i]) && costs[i] != soft_default) push(i, costs[i]);
    }
    if (soft_default == 0 && part_costs.empty()) return;
    add(f, f.name, f.scope, part_values, part_costs, soft_default, false);
  }

  void add(const Function& f, const std::string& label, std::vector<VariableId> scope,
           const std::vector<double>& values, const std::vector<double>& costs,
           double default_cost, bool hard) {
    try {
      auto t = std::make_unique<Table>(std::move(scope), values, costs, default_cost, 1.0, hard);
      t->set_label(label);
      problem_->add_constraint(std::move(t));
    } catch (const TableError& e) {
      fail(f.at, "function " + f.name + ": " + e.what());
    }
  }

  void read_shared(const Function& f, const std::vector<Function>& all) {
    const std::string target = (*f.body)["costs"].get<std::string>();
    const auto it = std::find_if(all.begin(), all.end(),
                                 [&](const Function& g) { return g.name == target; });
    if (it == all.end()) {
      fail(f.at, "function " + f.name + " shares the costs of '" + target + "', which is not defined");
    }
    const Json& body = *it->body;
    if (body.contains("type") || !body.contains("costs") || !body["costs"].is_array()) {
      fail(f.at, "function " + f.name + " shares the costs of '" + target +
                     "', which is not a table with its own costs");
    }
    if (it->scope.size() != f.scope.size()) {
      fail(f.at, "function " + f.name + " has arity " + std::to_string(f.scope.size()) +
                     ", the function whose costs it shares (" + target + ") " +
                     std::to_string(it->scope.size()));
    }
    for (std::size_t p = 0; p < f.scope.size(); ++p) {
      if (sizes_[f.scope[p]] != sizes_[it->scope[p]]) {
        fail(f.at, "function " + f.name + " shares the costs of '" + target +
                       "' but the domain sizes at scope position " + std::to_string(p) + " differ");
      }
    }
    add_table(f, *it, body);
  }

  void read_global(const Function& f) {
    const Json& body = *f.body;
    const Json& type = body["type"];
    if (!type.is_string() || type.get<std::string>() != "salldiff") {
      fail(f.at, "not supported: " + (type.is_string() ? type.get<std::string>() : type.dump()) +
                     " (function " + f.name + "; the only global type read is salldiff)");
    }
    if (!body.contains("params")) fail(f.at, "salldiff " + f.name + " needs params (metric, cost)");
    const Json& params = body["params"];
    Json metric, weight;
    if (params.is_object() && params.contains("metric") && params.contains("cost")) {
      metric = params["metric"];
      weight = params["cost"];
    } else if (params.is_array() && params.size() == 2) {
      metric = params[0];
      weight = params[1];
    } else {
      fail(f.at, "expected the params of salldiff " + f.name + " as {metric, cost}");
    }
    const auto measure = metric.is_string() ? AllDifferent::parse_measure(metric.get<std::string>())
                                            : std::nullopt;
    if (!measure) {
      fail(f.at, metric == Json("decbi") ? "not supported: salldiff decbi (" + f.name + ")"
                                         : "expected the salldiff metric var or dec in " + f.name +
                                               ", got " + metric.dump());
    }
    const double c = cost(weight, f.at, "the salldiff cost of " + f.name);
    if (f.scope.size() < 2) fail(f.at, "salldiff " + f.name + " needs at least 2 variables");
    if (c == 0) return;
    const bool hard = c >= ub_;
    try {
      auto all_different = std::make_unique<AllDifferent>(
          f.scope, std::vector<double>{}, *measure, hard ? 1.0 : c, hard,
          key_range_from_domains(*problem_, f.scope, {}));
      all_different->set_label(f.name + (hard ? "/hard" : ""));
      problem_->add_constraint(std::move(all_different));
    } catch (const std::invalid_argument& e) {
      fail(f.at, "salldiff " + f.name + ": " + e.what());
    }
  }

  JsonSource source_;
  std::unique_ptr<Problem> problem_;
  double ub_ = 0;
  std::vector<std::int64_t> sizes_;
  std::vector<std::vector<std::string>> value_names_;  // empty for anonymous values
};

}  // namespace

std::unique_ptr<Problem> parse_cfn(std::string_view text, const std::string& origin) {
  try {
    return CfnReader(text, origin).read();
  } catch (const nlohmann::json::exception& e) {
    // The reader checks every type before it reads a value; this is a safety net so that a
    // case it missed is still bad input, not a crash.
    throw InputError({origin, 0, 0}, std::string("unexpected content: ") + e.what());
  }
}

std::unique_ptr<Problem> read_cfn_file(const std::string& path) {
  const std::string text = read_possibly_compressed_file(path);
  return parse_cfn(text, path);
}

}  // namespace sightline::csp
