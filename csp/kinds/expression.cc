#include "sightline/csp/kinds/expression.h"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sightline/csp/problem.h"

namespace sightline::csp {

struct ExpressionConstraint::Compiled {
  mu::Parser parser;
  // buffer[0 .. arity-1] hold the scope's values, then one slot per parameter. Sized once
  // before any DefineVar: muparser keeps pointers into it.
  std::vector<double> buffer;
  // The parameters the formula actually uses, and their slots in `buffer`.
  std::vector<std::pair<std::size_t, ParameterRef>> used_parameters;
};

namespace {

bool is_identifier(const std::string& name) {
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (char ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') return false;
  }
  return true;
}

// Integer functions a model needs for derived values (a slot from a slot-room number, ...):
// floor, ceil, mod (the remainder with the sign of the divisor, as in Python) and idiv (the
// floor of the quotient); a zero divisor gives NaN, which counts as undefined.
double floor_of(double x) { return std::floor(x); }
double ceil_of(double x) { return std::ceil(x); }
double mod_of(double a, double b) {
  return b == 0 ? std::numeric_limits<double>::quiet_NaN() : a - b * std::floor(a / b);
}
double idiv_of(double a, double b) {
  return b == 0 ? std::numeric_limits<double>::quiet_NaN() : std::floor(a / b);
}

}  // namespace

ExpressionConstraint::ExpressionConstraint(std::vector<VariableId> scope,
                                           std::vector<std::string> names, std::string formula,
                                           const Parameters* parameters, double weight, bool hard,
                                           const std::vector<std::pair<std::string, double>>& constants)
    : Constraint(std::move(scope), weight, hard),
      formula_(std::move(formula)),
      compiled_(std::make_unique<Compiled>()) {
  const std::size_t arity = this->scope().size();
  if (names.size() != arity) {
    throw std::invalid_argument("an expression needs one name per scope variable");
  }
  const std::size_t num_parameters = parameters ? parameters->size() : 0;
  Compiled& c = *compiled_;
  c.buffer.assign(arity + num_parameters, 0.0);
  try {
    c.parser.DefineFun("floor", floor_of);
    c.parser.DefineFun("ceil", ceil_of);
    c.parser.DefineFun("mod", mod_of);
    c.parser.DefineFun("idiv", idiv_of);
    for (std::size_t i = 0; i < arity; ++i) {
      if (!is_identifier(names[i])) {
        throw std::invalid_argument("variable '" + names[i] +
                                    "' cannot be used in a formula: names there are letters, "
                                    "digits and _, not starting with a digit");
      }
      c.parser.DefineVar(names[i], &c.buffer[i]);
    }
    // Positional names _1 .. _n for the scope's variables, so one formula can serve every
    // scope of a `scopes:` list; a scope variable of that very name keeps it.
    for (std::size_t i = 0; i < arity; ++i) {
      const std::string positional = "_" + std::to_string(i + 1);
      if (std::find(names.begin(), names.end(), positional) == names.end()) {
        c.parser.DefineVar(positional, &c.buffer[i]);
      }
    }
    for (std::size_t k = 0; k < num_parameters; ++k) {
      const std::string& name = parameters->name(k);
      if (!is_identifier(name)) continue;  // a formula could not name it anyway
      for (const std::string& n : names) {
        if (n == name) {
          throw std::invalid_argument("'" + name +
                                      "' is both a scope variable and a parameter; rename one");
        }
      }
      try {
        c.parser.DefineVar(name, &c.buffer[arity + k]);
      } catch (const mu::Parser::exception_type&) {
        // A parameter muparser will not take as a variable (it clashes with one of its
        // function or constant names) could not be named in a formula; leave it out.
      }
    }
    for (const auto& [name, value] : constants) {
      if (!is_identifier(name)) {
        throw std::invalid_argument("constant '" + name + "' cannot be used in a formula: names "
                                    "there are letters, digits and _, not starting with a digit");
      }
      const bool taken = std::find(names.begin(), names.end(), name) != names.end() ||
                         (parameters && parameters->find(name).has_value());
      if (taken) {
        throw std::invalid_argument("'" + name + "' is both a constant (a value's label) and a "
                                    "variable or parameter; rename one");
      }
      c.parser.DefineConst(name, value);
    }
    c.parser.SetExpr(formula_);
    // GetUsedVar parses the formula, so syntax errors and unknown names surface here.
    for (const auto& [name, slot] : c.parser.GetUsedVar()) {
      const auto index = static_cast<std::size_t>(slot - c.buffer.data());
      if (index >= arity) {
        c.used_parameters.emplace_back(index, ParameterRef(parameters, index - arity));
      }
    }
    (void)c.parser.Eval();  // compiles to bytecode now, not during the first search step
  } catch (const mu::Parser::exception_type& e) {
    std::string message = "formula '" + formula_ + "': " + e.GetMsg();
    if (e.GetCode() == mu::ecINTERNAL_ERROR) {
      // muparser's word for some syntax errors it does not catch by name ("x + +").
      message = "formula '" + formula_ + "': cannot be parsed (an operator without its operand?)";
    }
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN) {
      std::string usable;
      for (const std::string& n : names) usable += (usable.empty() ? "" : ", ") + n;
      message += " (a formula may name its scope's variables, here " + usable +
                 ", and the problem's parameters)";
    }
    throw std::invalid_argument(message);
  }
}

ExpressionConstraint::~ExpressionConstraint() = default;

double ExpressionConstraint::violation(std::span<const double> values) const {
  // compiled_ is owned state that evaluation writes into (see the header: one thread at a time).
  Compiled& c = *compiled_;
  const auto vars = scope();
  for (std::size_t i = 0; i < vars.size(); ++i) c.buffer[i] = values[vars[i]];
  for (const auto& [slot, ref] : c.used_parameters) c.buffer[slot] = ref.value();
  const double v = c.parser.Eval();
  if (std::isnan(v) || v == std::numeric_limits<double>::infinity()) return kUndefinedViolation;
  return v > 0 ? v : 0.0;
}

ConstraintKindInfo expression_kind() {
  return {"expression",
          "a muparser formula over the scope's names and the parameters; its value (>= 0) is the "
          "violation",
          {"formula", "constants"},
          [](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
            const Spec& field = r.params.at("formula");
            const std::string& formula = field.as_string("a formula for 'formula'");
            std::vector<std::string> names;
            names.reserve(r.scope.size());
            for (VariableId v : r.scope) names.push_back(r.problem.variable_name(v));
            // constants: {name: number, ...} (a problem file adds its scope's value labels).
            std::vector<std::pair<std::string, double>> constants;
            if (const Spec* given = r.params.find("constants"); given != nullptr) {
              if (!given->is_map()) given->fail("expected constants as {name: number, ...}");
              for (const auto& [name, value] : given->fields()) {
                constants.emplace_back(name, value.as_number("a number for constant '" + name + "'"));
              }
            }
            try {
              return std::make_unique<ExpressionConstraint>(
                  r.scope, std::move(names), formula, &r.problem.parameters(), r.weight, r.hard,
                  constants);
            } catch (const std::invalid_argument& e) {
              field.fail(e.what());
            }
          },
          2, "formula: 'abs(_1 - 2 * _2)'"};
}

}  // namespace sightline::csp
