// Spec: a small tree of named values (numbers, strings, lists, maps) with source locations.
//
// Constraint kinds, solvers' options and profiles are described by Specs, whatever the file
// format they came from: the YAML reader turns a node into a Spec, the C++ builder writes one
// by hand. A kind reading its parameters from a Spec gets typed accessors that throw
// InputError naming the file, line and what was expected, so no kind re-invents validation.
#pragma once

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "sightline/csp/input_error.h"

namespace sightline::csp {

class Spec {
 public:
  enum class Type { kNull, kNumber, kString, kList, kMap };

  Spec() = default;
  // An empty value that still knows where it was written ("key:" with nothing after it).
  static Spec null(SourceLocation where);
  static Spec number(double value, SourceLocation where = {});
  // A scalar as written; numbers written in files arrive as strings and convert on demand.
  static Spec string(std::string text, SourceLocation where = {});
  static Spec list(std::vector<Spec> items, SourceLocation where = {});
  static Spec map(std::vector<std::pair<std::string, Spec>> fields, SourceLocation where = {});

  Type type() const { return type_; }
  bool is_null() const { return type_ == Type::kNull; }
  bool is_scalar() const { return type_ == Type::kNumber || type_ == Type::kString; }
  bool is_list() const { return type_ == Type::kList; }
  bool is_map() const { return type_ == Type::kMap; }
  const SourceLocation& where() const { return where_; }

  // Typed reads; each throws InputError("expected <what>, got ...") at this node's location.
  // as_number refuses NaN and infinities.
  double as_number(const std::string& what = "a number") const;
  long long as_integer(const std::string& what = "an integer") const;
  bool as_bool(const std::string& what = "true or false") const;
  const std::string& as_string(const std::string& what = "a string") const;
  std::vector<double> as_numbers(const std::string& what = "a list of numbers") const;
  std::vector<std::string> as_strings(const std::string& what = "a list of strings") const;

  // Lists.
  const std::vector<Spec>& items(const std::string& what = "a list") const;
  // Maps: find returns nullptr when absent; at throws InputError naming the missing key.
  const Spec* find(const std::string& key) const;
  const Spec& at(const std::string& key) const;
  const std::vector<std::pair<std::string, Spec>>& fields() const;
  // Throws InputError at the first key not in `allowed`, listing the allowed ones.
  void check_keys(std::initializer_list<const char*> allowed) const;
  void check_keys(const std::vector<std::string>& allowed) const;

  // Convenience: optional fields with defaults.
  double number_or(const std::string& key, double fallback) const;
  std::string string_or(const std::string& key, const std::string& fallback) const;
  bool bool_or(const std::string& key, bool fallback) const;

  // Adds or replaces a field of a map (for builders).
  Spec& set(const std::string& key, Spec value);

  // Throws InputError at this node.
  [[noreturn]] void fail(const std::string& message) const;
  // A short rendering of the value for error messages.
  std::string preview() const;

 private:
  Type type_ = Type::kNull;
  double number_ = 0;
  std::string text_;
  std::vector<Spec> items_;
  std::vector<std::pair<std::string, Spec>> fields_;
  SourceLocation where_;
};

}  // namespace sightline::csp
