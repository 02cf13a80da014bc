#include "sightline/csp/spec.h"

#include "sightline/csp/json_text.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace sightline::csp {

Spec Spec::null(SourceLocation where) {
  Spec s;
  s.where_ = std::move(where);
  return s;
}

Spec Spec::number(double value, SourceLocation where) {
  Spec s;
  s.type_ = Type::kNumber;
  s.number_ = value;
  s.where_ = std::move(where);
  return s;
}

Spec Spec::string(std::string text, SourceLocation where) {
  Spec s;
  s.type_ = Type::kString;
  s.text_ = std::move(text);
  s.where_ = std::move(where);
  return s;
}

Spec Spec::list(std::vector<Spec> items, SourceLocation where) {
  Spec s;
  s.type_ = Type::kList;
  s.items_ = std::move(items);
  s.where_ = std::move(where);
  return s;
}

Spec Spec::map(std::vector<std::pair<std::string, Spec>> fields, SourceLocation where) {
  Spec s;
  s.type_ = Type::kMap;
  s.fields_ = std::move(fields);
  s.where_ = std::move(where);
  return s;
}

void Spec::fail(const std::string& message) const { throw InputError(where_, message); }

std::string Spec::preview() const {
  switch (type_) {
    case Type::kNull: return "nothing";
    case Type::kNumber: return "'" + short_number(number_) + "'";  // 5, not 5.000000
    case Type::kString: return "'" + (text_.size() > 40 ? text_.substr(0, 40) + "..." : text_) + "'";
    case Type::kList: {
      // A short list of scalars as written ([5, 2]: the values a message is about), else its
      // length.
      constexpr std::size_t kShown = 6;
      constexpr std::size_t kLongest = 16;
      const bool scalars = !items_.empty() && items_.size() <= kShown &&
                           std::all_of(items_.begin(), items_.end(), [](const Spec& item) {
                             return item.type_ == Type::kNumber ||
                                    (item.type_ == Type::kString && item.text_.size() <= kLongest);
                           });
      if (!scalars) return "a list of " + std::to_string(items_.size());
      std::string text = "[";
      for (const Spec& item : items_) {
        if (text.size() > 1) text += ", ";
        text += item.type_ == Type::kNumber ? short_number(item.number_) : item.text_;
      }
      return text + "]";
    }
    case Type::kMap: return "a mapping";
  }
  return "?";
}

double Spec::as_number(const std::string& what) const {
  double value = 0;
  if (type_ == Type::kNumber) {
    value = number_;
  } else if (type_ == Type::kString) {
    const char* begin = text_.c_str();
    char* end = nullptr;
    errno = 0;
    value = std::strtod(begin, &end);
    if (end == begin || *end != '\0' || errno == ERANGE) fail("expected " + what + ", got " + preview());
  } else {
    fail("expected " + what + ", got " + preview());
  }
  if (!std::isfinite(value)) fail("expected " + what + " (a finite number), got " + preview());
  return value;
}

long long Spec::as_integer(const std::string& what) const {
  const double v = as_number(what);
  if (v != std::floor(v) || std::abs(v) > 9.0e15) fail("expected " + what + ", got " + preview());
  return static_cast<long long>(v);
}

bool Spec::as_bool(const std::string& what) const {
  if (type_ == Type::kString) {
    if (text_ == "true" || text_ == "yes" || text_ == "on") return true;
    if (text_ == "false" || text_ == "no" || text_ == "off") return false;
  }
  fail("expected " + what + ", got " + preview());
}

const std::string& Spec::as_string(const std::string& what) const {
  if (type_ != Type::kString) fail("expected " + what + ", got " + preview());
  return text_;
}

std::vector<double> Spec::as_numbers(const std::string& what) const {
  std::vector<double> out;
  for (const Spec& item : items(what)) out.push_back(item.as_number("a number in " + what));
  return out;
}

std::vector<std::string> Spec::as_strings(const std::string& what) const {
  std::vector<std::string> out;
  for (const Spec& item : items(what)) out.push_back(item.as_string("a name in " + what));
  return out;
}

const std::vector<Spec>& Spec::items(const std::string& what) const {
  if (type_ != Type::kList) fail("expected " + what + ", got " + preview());
  return items_;
}

const std::vector<std::pair<std::string, Spec>>& Spec::fields() const {
  if (type_ != Type::kMap) fail("expected a mapping of fields, got " + preview());
  return fields_;
}

const Spec* Spec::find(const std::string& key) const {
  if (type_ != Type::kMap) return nullptr;
  for (const auto& [k, v] : fields_) {
    if (k == key) return &v;
  }
  return nullptr;
}

const Spec& Spec::at(const std::string& key) const {
  if (type_ != Type::kMap) fail("expected a mapping with '" + key + "', got " + preview());
  if (const Spec* s = find(key)) return *s;
  fail("missing required field '" + key + "'");
}

void Spec::check_keys(std::initializer_list<const char*> allowed) const {
  check_keys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void Spec::check_keys(const std::vector<std::string>& allowed) const {
  for (const auto& [k, v] : fields()) {
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      v.fail("unknown field '" + k + "' (expected one of: " + list + ")");
    }
  }
}

double Spec::number_or(const std::string& key, double fallback) const {
  const Spec* s = find(key);
  return s ? s->as_number("a number for '" + key + "'") : fallback;
}

std::string Spec::string_or(const std::string& key, const std::string& fallback) const {
  const Spec* s = find(key);
  return s ? s->as_string("a string for '" + key + "'") : fallback;
}

bool Spec::bool_or(const std::string& key, bool fallback) const {
  const Spec* s = find(key);
  return s ? s->as_bool("true or false for '" + key + "'") : fallback;
}

Spec& Spec::set(const std::string& key, Spec value) {
  if (type_ == Type::kNull) type_ = Type::kMap;
  for (auto& [k, v] : fields_) {
    if (k == key) {
      v = std::move(value);
      return v;
    }
  }
  fields_.emplace_back(key, std::move(value));
  return fields_.back().second;
}

}  // namespace sightline::csp
