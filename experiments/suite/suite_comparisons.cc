#include "sightline/experiments/suite/suite_comparisons.h"

#include <algorithm>

namespace sightline::experiments {
namespace {

bool contains(const std::vector<std::string>& labels, const std::string& label) {
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

std::string joined(const std::vector<std::string>& labels) {
  std::string text;
  for (const std::string& l : labels) text += (text.empty() ? "" : ", ") + l;
  return text.empty() ? "(none)" : text;
}

}  // namespace

std::vector<std::string> camera_labels(const Suite& suite) {
  std::vector<std::string> labels;
  for (const SuiteCameraSolver& s : suite.camera_solvers) labels.push_back(s.label);
  return labels;
}

std::vector<std::string> problem_labels(const Suite& suite) {
  std::vector<std::string> labels;
  for (const SuiteToySolver& s : suite.toy_solvers) labels.push_back(s.label);
  return labels;
}


void add_comparison(Suite& suite, const std::string& a, const std::string& b,
                    const csp::SourceLocation& where) {
  const std::vector<std::string> camera = camera_labels(suite), problems = problem_labels(suite);
  auto solvers_text = [&] {
    return "the suite's camera solvers: " + joined(camera) +
           "; its problem solvers: " + joined(problems);
  };
  for (const std::string& name : {a, b})
    if (!contains(camera, name) && !contains(problems, name))
      throw csp::InputError(
          where, "'" + name + "' is not a solver of suite '" + suite.name + "'; " + solvers_text());
  if (a == b)
    throw csp::InputError(where,
                          "expected two different solvers to compare, got '" + a + "' twice");
  const bool same_family = (contains(camera, a) && contains(camera, b)) ||
                           (contains(problems, a) && contains(problems, b));
  if (!same_family)
    throw csp::InputError(where, "'" + a + "' and '" + b +
                                     "' are not solvers of one family (camera or problems); " +
                                     solvers_text());
  suite.comparisons.push_back({a, b, where});
}

void add_comparison_option(Suite& suite, const std::string& text) {
  const std::size_t comma = text.find(',');
  const csp::SourceLocation where{"--compare", 0, 0};
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos || comma == 0 ||
      comma + 1 == text.size())
    throw csp::InputError(
        where, "expected two solver labels separated by a comma (A,B), got '" + text + "'");
  add_comparison(suite, text.substr(0, comma), text.substr(comma + 1), where);
}

void read_statistics_settings(const csp::Spec& section, Suite& suite) {
  if (!section.is_map()) section.fail("expected a mapping: statistics: {compare: [A, B]}");
  section.check_keys({"compare"});
  const csp::Spec* compare = section.find("compare");
  if (!compare) return;
  const std::vector<csp::Spec>& items =
      compare->items("a pair of solver labels [A, B], or a list of pairs [[A, B], [C, D]]");
  const bool one_pair =
      std::all_of(items.begin(), items.end(), [](const csp::Spec& s) { return s.is_scalar(); });
  std::vector<const csp::Spec*> pairs;
  if (one_pair) {
    pairs.push_back(compare);
  } else {
    for (const csp::Spec& item : items) pairs.push_back(&item);
  }
  for (const csp::Spec* pair : pairs) {
    const std::vector<std::string> names = pair->as_strings("a pair of solver labels [A, B]");
    if (names.size() != 2)
      pair->fail("expected a pair of solver labels [A, B], got " + std::to_string(names.size()) +
                 " names");
    add_comparison(suite, names[0], names[1], pair->where());
  }
}

}  // namespace sightline::experiments
