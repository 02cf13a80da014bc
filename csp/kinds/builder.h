// ProblemBuilder: a weighted CSP in a few lines of C++, for people who would rather not write
// a file.
//
//     ProblemBuilder b("colouring");
//     b.integer("x", 0, 2);
//     b.integer("y", 0, 2);
//     b.constrain("not_equal", {"x", "y"});
//     b.constrain("linear", {"x", "y"}, spec_from({{"op", "<="}, {"rhs", 3}}), 2.0);
//     std::unique_ptr<Problem> p = b.build();
//
// Kinds are found by name in ConstraintKinds::global(), exactly as problem files find them,
// so a kind registered once is usable from both. Constraints may also be added as objects
// (add). Each call checks its input at once: a bad domain, a duplicate or unknown name
// throws std::invalid_argument naming it; a kind's own field errors arrive as
// std::invalid_argument too, prefixed with the kind and scope.
#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sightline/csp/problem.h"
#include "sightline/csp/spec.h"

namespace sightline::csp {

class ProblemBuilder {
 public:
  explicit ProblemBuilder(std::string name = "problem");

  // Variables; each returns the new variable's id.
  VariableId integer(const std::string& name, std::int64_t lo, std::int64_t hi);
  VariableId values(const std::string& name, std::vector<double> values);
  VariableId real(const std::string& name, double lo, double hi);
  // A named parameter constraints may read (declare it before the constraints that use it).
  std::size_t parameter(const std::string& name, double value);

  // A constraint of a registered kind over the named variables; `params` holds the kind's
  // own fields (a map Spec, or an empty one). Returns its id.
  ConstraintId constrain(const std::string& kind, const std::vector<std::string>& scope,
                         const Spec& params = Spec(), double weight = 1.0, bool hard = false);
  // A ready-made constraint (its scope must use ids returned above).
  ConstraintId add(std::unique_ptr<Constraint> constraint);

  // The problem so far, for reading ids and domains.
  const Problem& problem() const;
  // Hands the problem over; the builder cannot be used afterwards.
  std::unique_ptr<Problem> build();

 private:
  Problem& mutable_problem();
  std::unique_ptr<Problem> problem_;
};

// A map Spec from literal fields, for kind parameters in C++:
//     spec_from({{"op", "<="}, {"rhs", 3.0}, {"coefficients", std::vector<double>{1, 2}}})
struct SpecField {
  SpecField(std::string key, double number);
  SpecField(std::string key, int number);
  SpecField(std::string key, const char* text);
  SpecField(std::string key, std::string text);
  SpecField(std::string key, bool flag);
  SpecField(std::string key, std::vector<double> numbers);
  std::string key;
  Spec value;
};
Spec spec_from(std::initializer_list<SpecField> fields);

}  // namespace sightline::csp
