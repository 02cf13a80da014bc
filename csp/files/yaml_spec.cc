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

Spec convert(const YAML::Node& node, const std::string& origin) {
  switch (node.Type()) {
    case YAML::NodeType::Undefined: return Spec();
    case YAML::NodeType::Null: return Spec::null(where(node, origin));
    case YAML::NodeType::Scalar: return Spec::string(node.Scalar(), where(node, origin));
    case YAML::NodeType::Sequence: {
      std::vector<Spec> items;
      items.reserve(node.size());
      for (const auto& child : node) items.push_back(convert(child, origin));
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
        Spec value = convert(kv.second, origin);
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
    return convert(YAML::Load(text), origin);
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
