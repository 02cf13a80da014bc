// Typed, validated solver options.
//
// Each solver has a plain options struct with in-class defaults and a `validate()` returning
// an empty string when the options are usable, or a sentence naming the bad field and why
// (as Ceres' Solver::Options::IsValid does). An OptionSchema binds the struct's fields to
// names, so the registry can build options from "key=value" text (command line, suite
// files), list every option with its default for `sightline solvers`, and answer an unknown
// name with the list of valid ones.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace sightline::solvers {

// Options as written by a user: name -> text.
using OptionValues = std::map<std::string, std::string>;

// Thrown for an unknown option, a value that does not parse, or a failed validate().
class OptionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct OptionInfo {
  std::string name;
  std::string type;           // "int", "real", "bool", "text"
  std::string default_value;  // as text
  std::string help;           // one line, with units and range
};

namespace detail {
std::int64_t parse_integer(const std::string& option, const std::string& text);
double parse_real(const std::string& option, const std::string& text);
bool parse_bool(const std::string& option, const std::string& text);
std::string format_real(double value);
}  // namespace detail

template <class Options>
class OptionSchema {
 public:
  OptionSchema& integer(std::string name, std::int64_t Options::*field, std::string help,
                        std::int64_t min = INT64_MIN, std::int64_t max = INT64_MAX) {
    Entry e{{name, "int", "", std::move(help)}, {}, {}};
    e.set = [field, min, max, name](Options& o, const std::string& text) {
      const std::int64_t v = detail::parse_integer(name, text);
      if (v < min || v > max) {
        throw OptionError("option '" + name + "' must be in [" + std::to_string(min) + ", " +
                          std::to_string(max) + "], got " + text);
      }
      o.*field = v;
    };
    e.get = [field](const Options& o) { return std::to_string(o.*field); };
    entries_.push_back(std::move(e));
    return *this;
  }
  OptionSchema& real(std::string name, double Options::*field, std::string help,
                     double min = -1e300, double max = 1e300) {
    Entry e{{name, "real", "", std::move(help)}, {}, {}};
    e.set = [field, min, max, name](Options& o, const std::string& text) {
      const double v = detail::parse_real(name, text);
      if (v < min || v > max) {
        throw OptionError("option '" + name + "' must be in [" + detail::format_real(min) +
                          ", " + detail::format_real(max) + "], got " + text);
      }
      o.*field = v;
    };
    e.get = [field](const Options& o) { return detail::format_real(o.*field); };
    entries_.push_back(std::move(e));
    return *this;
  }
  OptionSchema& boolean(std::string name, bool Options::*field, std::string help) {
    Entry e{{name, "bool", "", std::move(help)}, {}, {}};
    e.set = [field, name](Options& o, const std::string& text) {
      o.*field = detail::parse_bool(name, text);
    };
    e.get = [field](const Options& o) { return std::string(o.*field ? "true" : "false"); };
    entries_.push_back(std::move(e));
    return *this;
  }
  OptionSchema& text(std::string name, std::string Options::*field, std::string help) {
    Entry e{{name, "text", "", std::move(help)}, {}, {}};
    e.set = [field](Options& o, const std::string& t) { o.*field = t; };
    e.get = [field](const Options& o) { return o.*field; };
    entries_.push_back(std::move(e));
    return *this;
  }

  bool has(const std::string& name) const {
    for (const auto& e : entries_) {
      if (e.info.name == name) return true;
    }
    return false;
  }

  // Defaults, overridden by `values`, then validated. Throws OptionError.
  Options parse(const OptionValues& values, const std::string& solver) const {
    Options options{};
    for (const auto& [name, text] : values) {
      const Entry* entry = nullptr;
      for (const auto& e : entries_) {
        if (e.info.name == name) entry = &e;
      }
      if (!entry) {
        std::string valid;
        for (const auto& e : entries_) valid += (valid.empty() ? "" : ", ") + e.info.name;
        throw OptionError("solver '" + solver + "' has no option '" + name +
                          "' (valid options: " + (valid.empty() ? "none" : valid) + ")");
      }
      entry->set(options, text);
    }
    if (std::string why = options.validate(); !why.empty()) {
      throw OptionError("solver '" + solver + "': " + why);
    }
    return options;
  }

  // Every option with its default value.
  std::vector<OptionInfo> describe() const {
    const Options defaults{};
    std::vector<OptionInfo> out;
    for (const auto& e : entries_) {
      OptionInfo info = e.info;
      info.default_value = e.get(defaults);
      out.push_back(std::move(info));
    }
    return out;
  }

 private:
  struct Entry {
    OptionInfo info;
    std::function<void(Options&, const std::string&)> set;
    std::function<std::string(const Options&)> get;
  };
  std::vector<Entry> entries_;
};

}  // namespace sightline::solvers
