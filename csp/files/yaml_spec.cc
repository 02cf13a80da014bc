#include "sightline/csp/files/yaml_spec.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>

namespace sightline::csp {
namespace {

SourceLocation where(const YAML::Node& node, const std::string& origin) {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {origin, 0, 0};
  return {origin, mark.line + 1, mark.column + 1};
}

// Limits on a document once its aliases are expanded. An alias (`*name`) stands for the whole
// node its anchor (`&name`) names, so a line or two can stand for an infinite document (an
// alias inside the node it names: `a: &a [*a]`) or an exponential one (each anchor's node
// repeating the alias before it ten times: "billion laughs"). Without aliases neither limit
// is ever reached: yaml-cpp refuses text nested about 500 deep, and every value takes at least
// one character of the text.
constexpr int kMaxDepth = 1000;
constexpr std::size_t kMaxValuesBeyondText = 1'000'000;

// `depth` counts the node's containers (1 for the document); `values_left` what the document
// may still hold.
Spec convert(const YAML::Node& node, const std::string& origin, int depth,
             std::size_t& values_left) {
  if (depth > kMaxDepth) {
    throw InputError(where(node, origin),
                     "values nested more than " + std::to_string(kMaxDepth) +
                         " deep once YAML aliases are expanded (an alias inside the node "
                         "its anchor names, as in `a: &a [*a]`, nests forever)");
  }
  if (values_left == 0) {
    throw InputError(where(node, origin),
                     "the document holds more than " + std::to_string(kMaxValuesBeyondText) +
                         " values beyond one per character of its text once YAML aliases are "
                         "expanded (each alias repeats the whole node its anchor names)");
  }
  --values_left;
  switch (node.Type()) {
    case YAML::NodeType::Undefined: return Spec();
    case YAML::NodeType::Null: return Spec::null(where(node, origin));
    case YAML::NodeType::Scalar: return Spec::string(node.Scalar(), where(node, origin));
    case YAML::NodeType::Sequence: {
      std::vector<Spec> items;
      items.reserve(node.size());
      for (const auto& child : node)
        items.push_back(convert(child, origin, depth + 1, values_left));
      return Spec::list(std::move(items), where(node, origin));
    }
    case YAML::NodeType::Map: {
      std::vector<std::pair<std::string, Spec>> fields;
      for (const auto& kv : node) {
        if (!kv.first.IsScalar()) {
          throw InputError(where(kv.first, origin), "expected a plain key");
        }
        const std::string key = kv.first.Scalar();
        for (const auto& [k, v] : fields) {
          if (k == key) throw InputError(where(kv.first, origin), "key '" + key + "' appears twice");
        }
        Spec value = convert(kv.second, origin, depth + 1, values_left);
        fields.emplace_back(key, std::move(value));
      }
      return Spec::map(std::move(fields), where(node, origin));
    }
  }
  return Spec();
}

}  // namespace

Spec parse_yaml(const std::string& text, const std::string& origin) {
  try {
    std::size_t values_left = text.size() + kMaxValuesBeyondText;
    return convert(YAML::Load(text), origin, 1, values_left);
  } catch (const YAML::Exception& e) {
    SourceLocation loc{origin, e.mark.is_null() ? 0 : e.mark.line + 1,
                       e.mark.is_null() ? 0 : e.mark.column + 1};
    throw InputError(loc, "malformed YAML: " + e.msg);
  }
}

Spec read_yaml_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, "cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_yaml(text.str(), path);
}

}  // namespace sightline::csp
