// An independent evaluator of toulbar2's .wcsp semantics for the tests: it reads a file
// into plain maps (no splitting into hard and soft parts, no Table) and scores an assignment
// as toulbar2 does: the sum of the costs, forbidden when one of them reaches UB. Only what
// the instances use: tables, shared tables, salldiff. No error handling: test data only.
#pragma once

#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sightline::testing {

// Tables are maps; shared functions are copied; salldiff costs `cost` per violation unit.
class ReferenceWcsp {
 public:
  explicit ReferenceWcsp(const std::string& path) {
    std::ifstream in(path);
    std::string name;
    long long n, max_d, e;
    in >> name >> n >> max_d >> e >> ub_;
    domains_.resize(n);
    for (auto& d : domains_) in >> d;
    std::vector<Function> shared;
    for (long long k = 0; k < e; ++k) {
      long long arity;
      in >> arity;
      const bool define_shared = arity < 0;
      Function f;
      f.scope.resize(std::abs(arity));
      for (auto& v : f.scope) in >> v;
      in >> f.default_cost;
      if (f.default_cost == -1) {
        std::string keyword;
        in >> keyword >> f.semantics >> f.alldiff_cost;
        f.is_alldiff = true;
      } else {
        long long tuples;
        in >> tuples;
        if (tuples < 0) {
          auto scope = f.scope;
          f = shared[-tuples - 1];
          f.scope = scope;
        }
        for (long long t = 0; t < tuples; ++t) {
          std::vector<long long> tuple(f.scope.size());
          for (auto& v : tuple) in >> v;
          in >> f.costs[tuple];
        }
      }
      if (define_shared) shared.push_back(f);
      functions_.push_back(f);
    }
  }
  // Total cost and whether some function reaches UB.
  std::pair<long long, bool> evaluate(const std::vector<double>& values) const {
    long long total = 0;
    bool forbidden = false;
    for (const Function& f : functions_) {
      long long c;
      if (f.is_alldiff) {
        std::map<long long, long long> count;
        for (auto v : f.scope) ++count[static_cast<long long>(values[v])];
        long long violation = 0;
        for (auto [key, k] : count) violation += f.semantics == "var" ? k - 1 : k * (k - 1) / 2;
        c = violation * f.alldiff_cost;
        // The reader makes salldiff hard only when its unit cost reaches UB.
        forbidden |= f.alldiff_cost >= ub_ && violation > 0;
        total += f.alldiff_cost >= ub_ ? 0 : c;
        continue;
      }
      std::vector<long long>& tuple = scratch_;
      tuple.clear();
      for (auto v : f.scope) tuple.push_back(static_cast<long long>(values[v]));
      auto it = f.costs.find(tuple);
      c = it == f.costs.end() ? f.default_cost : it->second;
      if (f.scope.empty() && !f.costs.empty()) c = f.costs.begin()->second;
      if (c >= ub_) {
        forbidden = true;
      } else {
        total += c;
      }
    }
    return {total, forbidden};
  }
  const std::vector<long long>& domains() const { return domains_; }

 private:
  struct Function {
    std::vector<long long> scope;
    long long default_cost = 0;
    std::map<std::vector<long long>, long long> costs;
    bool is_alldiff = false;
    std::string semantics;
    long long alldiff_cost = 0;
  };
  long long ub_ = 0;
  mutable std::vector<long long> scratch_;
  std::vector<long long> domains_;
  std::vector<Function> functions_;
};

}  // namespace sightline::testing
