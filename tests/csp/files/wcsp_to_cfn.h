// Test helper: writes a .wcsp file's network as toulbar2's JSON .cfn, so the .cfn reader can
// be checked against the .wcsp reader (and the independent evaluator) on every instance.
// It uses the CFN's variety on purpose: variables are named "v<i>", values "a<j>"; tuples
// name their values in even-numbered functions and give indices in odd ones; small tables
// without forbidden default (at most 64 tuples) are written dense, without defaultcost;
// every third cost is written as a string. Shared functions are written out in full.
// Tables, shared tables and salldiff only, as in the instances. Test data only.
#pragma once

#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace sightline::testing {

inline std::string wcsp_to_cfn(const std::string& wcsp_path) {
  using Json = nlohmann::ordered_json;
  std::ifstream in(wcsp_path);
  std::string name;
  long long n, max_d, e, ub;
  in >> name >> n >> max_d >> e >> ub;
  std::vector<long long> domains(n);
  for (auto& d : domains) in >> d;
  Json doc;
  doc["problem"] = {{"name", name}, {"mustbe", "<" + std::to_string(ub)}};
  Json variables = Json::object();
  for (long long i = 0; i < n; ++i) {
    Json values = Json::array();
    for (long long j = 0; j < domains[i]; ++j) values.push_back("a" + std::to_string(j));
    variables["v" + std::to_string(i)] = values;
  }
  doc["variables"] = variables;
  struct Table {
    std::vector<long long> scope;
    long long default_cost = 0;
    std::vector<std::pair<std::vector<long long>, long long>> tuples;
  };
  std::vector<Table> shared;
  Json functions = Json::object();
  int counter = 0;
  auto cost_json = [&](long long c) -> Json {
    return (counter++ % 3 == 0) ? Json(std::to_string(c)) : Json(c);
  };
  for (long long k = 0; k < e; ++k) {
    long long arity;
    in >> arity;
    Table t;
    t.scope.resize(std::abs(arity));
    for (auto& v : t.scope) in >> v;
    Json f;
    Json scope = Json::array();
    for (long long v : t.scope) scope.push_back("v" + std::to_string(v));
    f["scope"] = scope;
    in >> t.default_cost;
    if (t.default_cost == -1) {
      std::string keyword, semantics;
      long long cost;
      in >> keyword >> semantics >> cost;
      f["type"] = keyword;
      f["params"] = {{"metric", semantics}, {"cost", cost}};
      functions["F" + std::to_string(k)] = f;
      continue;
    }
    long long count;
    in >> count;
    if (count < 0) {
      const auto scope_ids = t.scope;
      t = shared[-count - 1];
      t.scope = scope_ids;
    }
    for (long long i = 0; i < count; ++i) {
      std::vector<long long> tuple(t.scope.size());
      for (auto& v : tuple) in >> v;
      long long c;
      in >> c;
      t.tuples.emplace_back(tuple, c);
    }
    if (arity < 0) shared.push_back(t);
    long long size = 1;
    for (long long v : t.scope) size *= domains[v];
    Json costs = Json::array();
    if (size <= 64 && t.default_cost < ub) {
      std::map<std::vector<long long>, long long> listed(t.tuples.begin(), t.tuples.end());
      std::vector<long long> tuple(t.scope.size(), 0);
      for (long long i = 0; i < size; ++i) {
        const auto it = listed.find(tuple);
        costs.push_back(cost_json(it == listed.end() ? t.default_cost : it->second));
        for (std::size_t p = tuple.size(); p-- > 0;) {
          if (++tuple[p] < domains[t.scope[p]]) break;
          tuple[p] = 0;
        }
      }
    } else {
      f["defaultcost"] = cost_json(t.default_cost);
      for (const auto& [tuple, c] : t.tuples) {
        for (long long v : tuple) {
          if (k % 2 == 0) {
            costs.push_back("a" + std::to_string(v));
          } else {
            costs.push_back(v);
          }
        }
        costs.push_back(cost_json(c));
      }
    }
    f["costs"] = costs;
    functions["F" + std::to_string(k)] = f;
  }
  doc["functions"] = functions;
  return doc.dump(1);
}

}  // namespace sightline::testing
