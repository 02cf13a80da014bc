#include "sightline/csp/kinds/table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "sightline/csp/problem.h"

namespace sightline::csp {
namespace {

constexpr std::uint64_t kMaxKeys = std::uint64_t{1} << 63;

std::string format_tuple(std::span<const double> values) {
  std::ostringstream out;
  out << "(";
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << values[i];
  out << ")";
  return out.str();
}

// Moving one variable changes one local index, so the key moves by (l_new - l_old) * stride
// (unsigned arithmetic wraps, and the sum of the terms is exact). Positions whose value is
// in no listed tuple ("unmatched") contribute nothing to the key; while any is unmatched the
// cost is the default.
class TableState : public IncrementalState {
 public:
  TableState(const Table& table, std::span<const double> values)
      : table_(table), local_(table.arity()) {
    const auto scope = table.scope();
    for (std::size_t p = 0; p < scope.size(); ++p) {
      local_[p] = table.local_index(p, values[scope[p]]);
      if (local_[p] < 0) {
        ++unmatched_;
      } else {
        key_ += static_cast<std::uint64_t>(local_[p]) * table.stride(p);
      }
    }
    cost_ = cost_for(unmatched_, key_);
  }

  double delta(std::span<const double>, std::size_t position, double new_value) override {
    Move m = move(position, new_value);
    return cost_for(m.unmatched, m.key) - cost_;
  }
  void commit(std::span<const double>, std::size_t position, double new_value) override {
    Move m = move(position, new_value);
    local_[position] = m.local;
    unmatched_ = m.unmatched;
    key_ = m.key;
    cost_ = cost_for(unmatched_, key_);
  }
  // Every variable of the scope shares the tuple's whole cost.
  double involvement(std::span<const double>, std::size_t) override { return cost_; }

 private:
  struct Move {
    std::int64_t local;
    int unmatched;
    std::uint64_t key;
  };
  Move move(std::size_t position, double new_value) const {
    Move m{table_.local_index(position, new_value), unmatched_, key_};
    const std::int64_t old = local_[position];
    const std::uint64_t stride = table_.stride(position);
    if (old < 0) {
      --m.unmatched;
    } else {
      m.key -= static_cast<std::uint64_t>(old) * stride;
    }
    if (m.local < 0) {
      ++m.unmatched;
    } else {
      m.key += static_cast<std::uint64_t>(m.local) * stride;
    }
    return m;
  }
  double cost_for(int unmatched, std::uint64_t key) const {
    return unmatched > 0 ? table_.default_cost() : table_.cost_of_key(key);
  }

  const Table& table_;
  std::vector<std::int64_t> local_;
  int unmatched_ = 0;
  std::uint64_t key_ = 0;
  double cost_ = 0;
};

std::vector<double> flatten_values(const std::vector<Table::Entry>& entries, std::size_t arity) {
  std::vector<double> flat;
  flat.reserve(entries.size() * arity);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].values.size() != arity) {
      throw TableError("tuple " + std::to_string(i) + " has " +
                           std::to_string(entries[i].values.size()) +
                           " values but the table's scope has " + std::to_string(arity),
                       i);
    }
    flat.insert(flat.end(), entries[i].values.begin(), entries[i].values.end());
  }
  return flat;
}

std::vector<double> entry_costs(const std::vector<Table::Entry>& entries) {
  std::vector<double> costs;
  costs.reserve(entries.size());
  for (const auto& e : entries) costs.push_back(e.cost);
  return costs;
}

}  // namespace

Table::Table(std::vector<VariableId> scope, const std::vector<Entry>& entries, double default_cost,
             double weight, bool hard)
    : Constraint(std::move(scope), weight, hard), default_cost_(default_cost) {
  build(flatten_values(entries, arity()), entry_costs(entries));
}

Table::Table(std::vector<VariableId> scope, std::span<const double> tuple_values,
             std::span<const double> costs, double default_cost, double weight, bool hard)
    : Constraint(std::move(scope), weight, hard), default_cost_(default_cost) {
  build(tuple_values, costs);
}

void Table::build(std::span<const double> tuple_values, std::span<const double> costs) {
  const std::size_t k = arity();
  const std::size_t n = costs.size();
  if (k == 0) throw TableError("a table needs at least one variable", TableError::kNoEntry);
  if (tuple_values.size() != k * n) {
    throw TableError("a table of arity " + std::to_string(k) + " with " + std::to_string(n) +
                         " costs needs " + std::to_string(k * n) + " values, got " +
                         std::to_string(tuple_values.size()),
                     TableError::kNoEntry);
  }
  if (!std::isfinite(default_cost_) || default_cost_ < 0) {
    throw TableError(
        "the default cost must be finite and >= 0, got " + std::to_string(default_cost_),
        TableError::kNoEntry);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(costs[i]) || costs[i] < 0) {
      throw TableError("tuple " + format_tuple(tuple_values.subspan(i * k, k)) + " has cost " +
                           std::to_string(costs[i]) + "; costs must be finite and >= 0",
                       i);
    }
    for (std::size_t p = 0; p < k; ++p) {
      if (!std::isfinite(tuple_values[i * k + p])) {
        throw TableError("tuple " + std::to_string(i) + " holds a non-finite value", i);
      }
    }
  }

  // Distinct values per position, and their lookup.
  positions_.assign(k, {});
  for (std::size_t p = 0; p < k; ++p) {
    PositionValues& pv = positions_[p];
    pv.sorted.reserve(n);
    for (std::size_t i = 0; i < n; ++i) pv.sorted.push_back(tuple_values[i * k + p] + 0.0);
    std::sort(pv.sorted.begin(), pv.sorted.end());
    pv.sorted.erase(std::unique(pv.sorted.begin(), pv.sorted.end()), pv.sorted.end());
    const bool integral = std::all_of(pv.sorted.begin(), pv.sorted.end(), [](double v) {
      return std::abs(v) < 9e15 && v == std::floor(v);
    });
    if (integral && !pv.sorted.empty()) {
      const auto lo = static_cast<std::int64_t>(pv.sorted.front());
      const auto hi = static_cast<std::int64_t>(pv.sorted.back());
      const auto span = static_cast<std::uint64_t>(hi - lo) + 1;
      if (span <= std::max<std::uint64_t>(64, 4 * pv.sorted.size())) {
        pv.direct_lo = lo;
        pv.direct.assign(span, -1);
        for (std::size_t l = 0; l < pv.sorted.size(); ++l) {
          pv.direct[static_cast<std::int64_t>(pv.sorted[l]) - lo] = static_cast<std::int32_t>(l);
        }
      }
    }
  }

  // Mixed-radix strides over the listed values; refuse key spaces above 2^63.
  strides_.assign(k, 1);
  std::uint64_t key_space = 1;
  for (std::size_t p = 0; p < k; ++p) {
    strides_[p] = key_space;
    const std::uint64_t np = std::max<std::uint64_t>(1, positions_[p].sorted.size());
    if (key_space > kMaxKeys / np) {
      throw TableError(
          "the table's tuples combine too many distinct values per position "
          "(more than 2^63 combinations) to be indexed",
          TableError::kNoEntry);
    }
    key_space *= np;
  }

  // Local indices and keys of the listed tuples.
  locals_.resize(n * k);
  costs_.assign(costs.begin(), costs.end());
  std::vector<std::uint64_t> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t key = 0;
    for (std::size_t p = 0; p < k; ++p) {
      const auto l = local_index(p, tuple_values[i * k + p]);
      locals_[i * k + p] = static_cast<std::int32_t>(l);
      key += static_cast<std::uint64_t>(l) * strides_[p];
    }
    keys[i] = key;
  }
  auto duplicate = [&](std::size_t first, std::size_t second) {
    return TableError(
        "tuple " + format_tuple(tuple_values.subspan(second * k, k)) + " is listed twice", second,
        first);
  };
  const std::uint64_t dense_limit = std::max<std::uint64_t>(4096, 8 * std::uint64_t{n});
  dense_.clear();
  sparse_.clear();
  if (key_space <= dense_limit) {
    std::vector<std::int64_t> first(key_space, -1);
    dense_.assign(key_space, default_cost_);
    for (std::size_t i = 0; i < n; ++i) {
      if (first[keys[i]] >= 0) throw duplicate(static_cast<std::size_t>(first[keys[i]]), i);
      first[keys[i]] = static_cast<std::int64_t>(i);
      dense_[keys[i]] = costs_[i];
    }
  } else {
    sparse_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!sparse_.emplace(keys[i], costs_[i]).second) {
        const auto first =
            static_cast<std::size_t>(std::find(keys.begin(), keys.end(), keys[i]) - keys.begin());
        throw duplicate(first, i);
      }
    }
  }

  min_cost_ = default_cost_;
  for (double c : costs_) min_cost_ = std::min(min_cost_, c);

  // Posting lists (a counting sort of the tuples by their local value at each position).
  posting_start_.assign(k, {});
  postings_.resize(n * k);
  std::uint32_t offset = 0;
  for (std::size_t p = 0; p < k; ++p) {
    auto& start = posting_start_[p];
    start.assign(positions_[p].sorted.size() + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++start[locals_[i * k + p] + 1];
    start[0] = offset;
    for (std::size_t l = 1; l < start.size(); ++l) start[l] += start[l - 1];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) {
      postings_[fill[locals_[i * k + p]]++] = static_cast<std::uint32_t>(i);
    }
    offset = start.back();
  }
}

std::int64_t Table::local_index(std::size_t position, double value) const {
  const PositionValues& pv = positions_[position];
  if (!pv.direct.empty()) {
    const double lo = static_cast<double>(pv.direct_lo);
    if (!(value >= lo && value <= lo + static_cast<double>(pv.direct.size() - 1))) return -1;
    const auto i = static_cast<std::int64_t>(value);
    if (static_cast<double>(i) != value) return -1;
    return pv.direct[i - pv.direct_lo];
  }
  auto it = std::lower_bound(pv.sorted.begin(), pv.sorted.end(), value);
  if (it == pv.sorted.end() || *it != value) return -1;
  return it - pv.sorted.begin();
}

double Table::tuple_value(std::size_t i, std::size_t position) const {
  return positions_[position].sorted[locals_[i * arity() + position]];
}

double Table::cost_of(std::span<const double> tuple) const {
  std::uint64_t key = 0;
  for (std::size_t p = 0; p < tuple.size(); ++p) {
    const auto l = local_index(p, tuple[p]);
    if (l < 0) return default_cost_;
    key += static_cast<std::uint64_t>(l) * strides_[p];
  }
  return cost_of_key(key);
}

double Table::violation(std::span<const double> values) const {
  const auto s = scope();
  std::uint64_t key = 0;
  for (std::size_t p = 0; p < s.size(); ++p) {
    const auto l = local_index(p, values[s[p]]);
    if (l < 0) return default_cost_;
    key += static_cast<std::uint64_t>(l) * strides_[p];
  }
  return cost_of_key(key);
}

std::unique_ptr<IncrementalState> Table::make_incremental_state(
    std::span<const double> values) const {
  return std::make_unique<TableState>(*this, values);
}

double Table::min_violation(std::span<const double> values,
                            std::span<const std::uint8_t> assigned) const {
  const auto s = scope();
  const std::size_t k = s.size();
  // Local indices of the assigned positions (-2 = unassigned). Small scopes use the stack.
  std::array<std::int64_t, 32> small;
  std::vector<std::int64_t> large;
  std::span<std::int64_t> local;
  if (k <= small.size()) {
    local = std::span<std::int64_t>(small.data(), k);
  } else {
    large.resize(k);
    local = large;
  }
  std::size_t num_assigned = 0;
  std::size_t pivot = k;  // the assigned position with the shortest posting list
  std::uint32_t pivot_length = 0;
  for (std::size_t p = 0; p < k; ++p) {
    if (!assigned[s[p]]) {
      local[p] = -2;
      continue;
    }
    ++num_assigned;
    local[p] = local_index(p, values[s[p]]);
    if (local[p] < 0) return default_cost_;  // no listed tuple is compatible
    const auto& start = posting_start_[p];
    const std::uint32_t length = start[local[p] + 1] - start[local[p]];
    if (pivot == k || length < pivot_length) {
      pivot = p;
      pivot_length = length;
    }
  }
  if (num_assigned == 0) return min_cost_;
  if (num_assigned == k) return violation(values);
  double best = default_cost_;
  const auto& start = posting_start_[pivot];
  for (std::uint32_t j = start[local[pivot]]; j < start[local[pivot] + 1]; ++j) {
    const std::uint32_t t = postings_[j];
    if (costs_[t] >= best) continue;
    bool compatible = true;
    for (std::size_t p = 0; p < k && compatible; ++p) {
      compatible = local[p] == -2 || locals_[t * k + p] == local[p];
    }
    if (compatible) best = costs_[t];
  }
  return best;
}

ConstraintKindInfo table_kind() {
  return {
      "table",
      "cost function in extension: listed tuples with costs, every other tuple at `default`",
      {"tuples", "default"},
      [](const ConstraintRequest& r) -> std::unique_ptr<Constraint> {
        const std::size_t k = r.scope.size();
        for (VariableId v : r.scope) {
          const Variable& var = r.problem.variable(v);
          if (!var.domain.is_discrete()) {
            throw InputError(r.where, "table needs discrete variables; '" + var.name +
                                          "' has domain " + var.domain.describe());
          }
        }
        double default_cost = 0;
        if (const Spec* d = r.params.find("default")) {
          default_cost = d->as_number("a default cost (a number >= 0)");
          if (default_cost < 0) d->fail("the default cost must be >= 0, got " + d->preview());
        }
        std::vector<Table::Entry> entries;
        const Spec* tuples = r.params.find("tuples");
        const std::vector<Spec> no_items;
        const std::vector<Spec>& items = tuples ? tuples->items(
                                                      "a list of tuples, each [values..., cost] or "
                                                      "{values: [...], cost: c}")
                                                : no_items;
        entries.reserve(items.size());
        for (const Spec& item : items) {
          Table::Entry e;
          std::vector<const Spec*> value_nodes;
          const Spec* cost_node = nullptr;
          if (item.is_list()) {
            const auto& parts = item.items();
            if (parts.size() != k + 1) {
              item.fail("expected a tuple of " + std::to_string(k) +
                        " values followed by its cost, got " + std::to_string(parts.size()) +
                        " numbers");
            }
            for (std::size_t p = 0; p < k; ++p) value_nodes.push_back(&parts[p]);
            cost_node = &parts[k];
          } else if (item.is_map()) {
            item.check_keys({"values", "cost"});
            const auto& parts = item.at("values").items("a list of values");
            if (parts.size() != k) {
              item.at("values").fail("expected " + std::to_string(k) +
                                     " values (one per scope variable), got " +
                                     std::to_string(parts.size()));
            }
            for (const Spec& part : parts) value_nodes.push_back(&part);
            cost_node = &item.at("cost");
          } else {
            item.fail("expected a tuple [values..., cost] or {values: [...], cost: c}, got " +
                      item.preview());
          }
          for (std::size_t p = 0; p < k; ++p) {
            const double v = value_nodes[p]->as_number("a value");
            const Variable& var = r.problem.variable(r.scope[p]);
            if (!var.domain.contains(v)) {
              value_nodes[p]->fail("value " + value_nodes[p]->preview() + " is not in the domain " +
                                   var.domain.describe() + " of variable '" + var.name + "'");
            }
            e.values.push_back(v);
          }
          e.cost = cost_node->as_number("a cost (a number >= 0)");
          if (e.cost < 0) cost_node->fail("costs must be >= 0, got " + cost_node->preview());
          entries.push_back(std::move(e));
        }
        try {
          return std::make_unique<Table>(r.scope, entries, default_cost, r.weight, r.hard);
        } catch (const TableError& e) {
          if (e.entry() == TableError::kNoEntry) throw InputError(r.where, e.what());
          std::string message = e.what();
          if (e.first_entry() != TableError::kNoEntry) {
            message += " (first listed at " + items[e.first_entry()].where().str() + ")";
          }
          throw InputError(items[e.entry()].where(), message);
        }
      },
      2, "default: 1, tuples: [[0, 1, 0], [1, 1, 3], [2, 0, 2]]"};
}

}  // namespace sightline::csp
