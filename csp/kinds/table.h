// Table: a cost function in extension: listed tuples with their costs, every other tuple at
// a default cost. It is what toulbar2's .wcsp files are made of, and the way to write any
// small relation by hand in a problem file.
//
// Violation is the cost of the current tuple: the listed cost if the tuple is listed, the
// default cost otherwise. Costs are >= 0, so a tuple of cost 0 satisfies the table; with
// hard = true every tuple of positive cost is forbidden.
//
// Tuples hold VALUES, not domain indices: a table means the same thing whatever order a
// domain lists its values in, and it needs no domain to be evaluated. (The .wcsp reader
// gives its variables the integer range 0..d-1, so there values and indices coincide.)
// Values are compared exactly, which is what discrete domains need.
//
// Representation (sparse: a table with default cost never enumerates its complement):
//  - per scope position, the distinct values that occur there in some listed tuple, each
//    with a local index 0..n_p-1; a value that occurs in no listed tuple at that position
//    means "not listed" at once, so the default cost applies;
//  - a tuple of local indices (l_0, .., l_{k-1}) has the mixed-radix key
//        key = sum_p l_p * stride_p,   stride_0 = 1, stride_{p+1} = stride_p * n_p,
//    unique for each combination of listed values. The key space has prod_p n_p entries,
//    counting only values that actually occur, so it is small for real tables; when it is
//    small (at most max(4096, 8 x tuples)) costs sit in a dense array indexed by the key,
//    otherwise in a hash map holding the listed tuples only.
//  - Changing the variable at position p changes the key by (l_new - l_old) * stride_p, so
//    the incremental state answers delta and commit in O(1) (one value lookup, one key
//    lookup), whatever the arity.
// Tables whose key space exceeds 2^63 (many positions each with many distinct listed
// values) are refused with std::invalid_argument.
//
// File form (values in scope order, then the cost; `default` is 0 when omitted):
//   {kind: table, scope: [x, y], default: 1, tuples: [[0, 1, 0], [1, 0, 0], [1, 1, 3]]}
//   {kind: table, scope: [x, y], tuples: [{values: [0, 1], cost: 2}]}
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/csp/kinds/constraint_kinds.h"

namespace sightline::csp {

// A malformed table (duplicate tuple, negative cost, ...). `entry()` is the index of the
// offending listed tuple, so readers can point at its line; kNoEntry when it is about the
// table as a whole. For a tuple listed twice, `first_entry()` is its first listing.
class TableError : public std::invalid_argument {
 public:
  static constexpr std::size_t kNoEntry = std::numeric_limits<std::size_t>::max();
  TableError(const std::string& message, std::size_t entry, std::size_t first_entry = kNoEntry)
      : std::invalid_argument(message), entry_(entry), first_entry_(first_entry) {}
  std::size_t entry() const { return entry_; }
  std::size_t first_entry() const { return first_entry_; }

 private:
  std::size_t entry_;
  std::size_t first_entry_;
};

class Table final : public Constraint, public TableCosts {
 public:
  struct Entry {
    std::vector<double> values;  // one per scope position
    double cost = 0;             // finite, >= 0
  };

  // Throws TableError on a tuple of the wrong length, a non-finite value, a negative or
  // non-finite cost (or default), a tuple listed twice, or a key space above 2^63.
  Table(std::vector<VariableId> scope, const std::vector<Entry>& entries, double default_cost,
        double weight = 1.0, bool hard = false);
  // The same from flat arrays, for readers of large tables: tuple i is
  // tuple_values[i * arity .. (i + 1) * arity), its cost costs[i].
  Table(std::vector<VariableId> scope, std::span<const double> tuple_values,
        std::span<const double> costs, double default_cost, double weight = 1.0, bool hard = false);

  std::string_view kind() const override { return "table"; }
  double violation(std::span<const double> values) const override;
  std::unique_ptr<IncrementalState> make_incremental_state(
      std::span<const double> values) const override;
  // The cheapest tuple compatible with the assigned part: the listed ones are found through
  // an index from (position, value) to the tuples holding it; the default is counted as
  // reachable whenever some variable is unassigned (a table does not know its domains, so
  // it cannot tell whether the listed tuples cover every completion; this only ever makes
  // the bound lower, never wrong).
  double min_violation(std::span<const double> values,
                       std::span<const std::uint8_t> assigned) const override;

  const TableCosts* table_costs() const override { return this; }

  std::size_t arity() const { return scope().size(); }
  double default_cost() const override { return default_cost_; }
  std::size_t num_tuples() const override { return costs_.size(); }
  // Listed tuple i: its values in scope order, and its cost.
  double tuple_value(std::size_t i, std::size_t position) const override;
  double tuple_cost(std::size_t i) const override { return costs_[i]; }
  // The cheapest cost over every tuple (the default included).
  double min_cost() const { return min_cost_; }
  // Cost of a tuple given in scope order (tuple.size() == arity()).
  double cost_of(std::span<const double> tuple) const;
  // True when the costs sit in a dense array (see the header comment), false for the hash.
  bool is_dense() const { return !dense_.empty(); }

  // The local index of `value` at `position`, or -1 if no listed tuple holds it there.
  std::int64_t local_index(std::size_t position, double value) const;
  // The cost of a key of listed values (every position matched).
  double cost_of_key(std::uint64_t key) const {
    if (!dense_.empty()) return dense_[key];
    auto it = sparse_.find(key);
    return it == sparse_.end() ? default_cost_ : it->second;
  }
  std::uint64_t stride(std::size_t position) const { return strides_[position]; }

 private:
  // Distinct values of one position. Integer values in a compact range are looked up in a
  // direct array; others by binary search in the sorted list.
  struct PositionValues {
    std::vector<double> sorted;  // distinct values, ascending; local index = rank
    std::int64_t direct_lo = 0;  // direct[v - direct_lo] = local index or -1
    std::vector<std::int32_t> direct;
  };

  void build(std::span<const double> tuple_values, std::span<const double> costs);

  double default_cost_;
  double min_cost_ = 0;
  std::vector<PositionValues> positions_;
  std::vector<std::uint64_t> strides_;
  std::vector<std::int32_t> locals_;  // listed tuples as local indices, arity per tuple
  std::vector<double> costs_;         // listed tuples' costs
  std::vector<double> dense_;         // key -> cost, when dense
  std::unordered_map<std::uint64_t, double> sparse_;  // key -> cost, when sparse
  // Index for min_violation: tuples holding local value l at position p are
  // postings_[posting_start_[p][l] .. posting_start_[p][l + 1]).
  std::vector<std::vector<std::uint32_t>> posting_start_;
  std::vector<std::uint32_t> postings_;
};

// Registry entry "table": fields `tuples` (list; each item [v_1, .., v_k, cost] or
// {values: [v_1, .., v_k], cost: c}) and `default` (number >= 0, default 0). Every value
// must belong to its variable's (discrete) domain; a tuple listed twice is an error.
ConstraintKindInfo table_kind();

}  // namespace sightline::csp
