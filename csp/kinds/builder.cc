#include "sightline/csp/kinds/builder.h"

#include <cmath>
#include <stdexcept>

#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/constraint_entry.h"

namespace sightline::csp {

ProblemBuilder::ProblemBuilder(std::string name)
    : problem_(std::make_unique<Problem>(std::move(name))) {}

Problem& ProblemBuilder::mutable_problem() {
  if (!problem_) throw std::logic_error("ProblemBuilder used after build()");
  return *problem_;
}

const Problem& ProblemBuilder::problem() const {
  if (!problem_) throw std::logic_error("ProblemBuilder used after build()");
  return *problem_;
}

namespace {

// Domain factories throw std::invalid_argument without the variable's name; add it.
template <class MakeDomain>
VariableId add_named(Problem& problem, const std::string& name, MakeDomain make) {
  if (problem.parameters().find(name)) {
    throw std::invalid_argument("variable '" + name + "': the name is already a parameter");
  }
  try {
    return problem.add_variable(name, make());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("variable '" + name + "': " + e.what());
  }
}

}  // namespace

VariableId ProblemBuilder::integer(const std::string& name, std::int64_t lo, std::int64_t hi) {
  return add_named(mutable_problem(), name, [&] { return Domain::integer_range(lo, hi); });
}

VariableId ProblemBuilder::values(const std::string& name, std::vector<double> values) {
  return add_named(mutable_problem(), name, [&] { return Domain::value_set(std::move(values)); });
}

VariableId ProblemBuilder::real(const std::string& name, double lo, double hi) {
  return add_named(mutable_problem(), name, [&] { return Domain::real_interval(lo, hi); });
}

std::size_t ProblemBuilder::parameter(const std::string& name, double value) {
  Problem& p = mutable_problem();
  if (p.find_variable(name)) {
    throw std::invalid_argument("parameter '" + name + "': the name is already a variable");
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument("parameter '" + name + "' must be a finite number");
  }
  return p.parameters().add(name, value);
}

ConstraintId ProblemBuilder::constrain(const std::string& kind,
                                       const std::vector<std::string>& scope, const Spec& params,
                                       double weight, bool hard) {
  Problem& p = mutable_problem();
  std::string described = kind + "(";
  std::vector<VariableId> ids;
  for (const std::string& name : scope) {
    described += (ids.empty() ? "" : ", ") + name;
    auto id = p.find_variable(name);
    if (!id) throw std::invalid_argument(kind + ": unknown variable '" + name + "'");
    ids.push_back(*id);
  }
  described += ")";
  if (!std::isfinite(weight) || weight < 0) {
    throw std::invalid_argument(described + ": weight must be a finite number >= 0");
  }
  if (params.is_map()) {
    for (const char* common : {"kind", "scope", "vars", "weight", "hard"}) {
      if (params.find(common)) {
        throw std::invalid_argument(described + ": '" + common +
                                    "' is an argument of constrain(), not a field of params");
      }
    }
  }
  try {
    return p.add_constraint(create_constraint(ConstraintKinds::global(), p, kind, std::move(ids),
                                              weight, hard, params, params.where()));
  } catch (const InputError& e) {
    throw std::invalid_argument(described + ": " + e.detail());
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(described + ": " + e.what());
  }
}

ConstraintId ProblemBuilder::add(std::unique_ptr<Constraint> constraint) {
  if (!constraint) throw std::invalid_argument("ProblemBuilder::add: null constraint");
  return mutable_problem().add_constraint(std::move(constraint));
}

std::unique_ptr<Problem> ProblemBuilder::build() {
  mutable_problem();  // refuses a second build
  return std::move(problem_);
}

SpecField::SpecField(std::string k, double number)
    : key(std::move(k)), value(Spec::number(number)) {}
SpecField::SpecField(std::string k, int number) : key(std::move(k)), value(Spec::number(number)) {}
SpecField::SpecField(std::string k, const char* text)
    : key(std::move(k)), value(Spec::string(text)) {}
SpecField::SpecField(std::string k, std::string text)
    : key(std::move(k)), value(Spec::string(std::move(text))) {}
SpecField::SpecField(std::string k, bool flag)
    : key(std::move(k)), value(Spec::string(flag ? "true" : "false")) {}
SpecField::SpecField(std::string k, std::vector<double> numbers) : key(std::move(k)) {
  std::vector<Spec> items;
  for (double x : numbers) items.push_back(Spec::number(x));
  value = Spec::list(std::move(items));
}

Spec spec_from(std::initializer_list<SpecField> fields) {
  std::vector<std::pair<std::string, Spec>> out;
  for (const SpecField& f : fields) out.emplace_back(f.key, f.value);
  return Spec::map(std::move(out));
}

}  // namespace sightline::csp
