#include "sightline/csp/kinds/constraint_kinds.h"

#include <stdexcept>

namespace sightline::csp {

ConstraintKinds& ConstraintKinds::global() {
  static ConstraintKinds* kinds = [] {
    auto* k = new ConstraintKinds;
    register_builtin_kinds(*k);
    return k;
  }();
  return *kinds;
}

void ConstraintKinds::add(ConstraintKindInfo info) {
  if (info.name.empty()) throw std::invalid_argument("a constraint kind needs a name");
  if (contains(info.name)) {
    throw std::invalid_argument("constraint kind '" + info.name + "' registered twice");
  }
  kinds_.emplace(info.name, std::move(info));
}

const ConstraintKindInfo& ConstraintKinds::get(const std::string& name,
                                               const SourceLocation& where) const {
  auto it = kinds_.find(name);
  if (it != kinds_.end()) return it->second;
  std::string known;
  for (const auto& [n, i] : kinds_) known += (known.empty() ? "" : ", ") + n;
  throw InputError(where, "unknown constraint kind '" + name + "' (known kinds: " + known + ")");
}

std::unique_ptr<Constraint> ConstraintKinds::create(const std::string& name,
                                                    const ConstraintRequest& request) const {
  return get(name, request.where).factory(request);
}

std::vector<std::string> ConstraintKinds::names() const {
  std::vector<std::string> out;
  for (const auto& [n, i] : kinds_) out.push_back(n);
  return out;
}

}  // namespace sightline::csp
