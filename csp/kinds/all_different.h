// AllDifferent: the values x_i + offset_i of a set of variables must all differ.
//
// With zero offsets it is the classic alldifferent; with offsets +i and -i it states that no
// two queens share a diagonal, which is how N-queens is three of these. Two violation
// measures, named as toulbar2's `salldiff` names them, so .wcsp files read through this class
// keep their meaning:
//   var: the least number of variables that must change  = sum over keys k of max(0, c_k - 1)
//   dec: the number of equal pairs (the binary decomposition) = sum over keys of c_k(c_k-1)/2
// where c_k is how many variables have key x_i + offset_i == k.
//
// Local search moves one variable at a time, so the incremental state keeps c_k for every
// key: moving one variable from key a to key b changes only c_a and c_b, which makes delta,
// commit and involvement O(1) whatever the arity (1,000,000-queens). The counts live in a
// dense array when the keys are integers in a known range (integer domains plus integer
// offsets; see key_range_from_domains), and in a hash map otherwise.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sightline/csp/constraint.h"
#include "sightline/csp/kinds/constraint_kinds.h"

namespace sightline::csp {

class Problem;

class AllDifferent : public Constraint {
 public:
  enum class Measure {
    kVariables,      // "var": variables that would have to change
    kDecomposition,  // "dec": pairs of variables with equal keys
  };

  // Every key x_i + offset_i is an integer in [lo, hi]: counts fit a dense array.
  struct KeyRange {
    std::int64_t lo = 0;
    std::int64_t hi = -1;
  };

  // `offsets` is empty (all zero) or has one entry per scope variable. All-zero offsets are
  // not kept (a million-variable alldifferent would hold 8 MB of zeros, read at every
  // evaluation). `key_range`, when
  // given, must contain every key the scope's domains can produce (key_range_from_domains
  // computes it); without it the incremental state counts in a hash map.
  AllDifferent(std::vector<VariableId> scope, std::vector<double> offsets = {},
               Measure measure = Measure::kVariables, double weight = 1.0, bool hard = false,
               std::optional<KeyRange> key_range = std::nullopt);

  std::string_view kind() const override { return "all_different"; }
  double violation(std::span<const double> values) const override;
  // The repeats among the assigned variables alone, in the same measure: whatever the
  // others take, those keys stay repeated (a valid bound for bnb, growing with the assigned
  // part).
  double min_violation(std::span<const double> values,
                       std::span<const std::uint8_t> assigned) const override;
  std::unique_ptr<IncrementalState> make_incremental_state(
      std::span<const double> values) const override;

  std::optional<Distinctness> distinctness() const override {
    return Distinctness{has_zero_offsets(), measure_ == Measure::kVariables,
                        measure_name(measure_)};
  }

  Measure measure() const { return measure_; }
  // One offset per scope position, or none at all when every offset is zero; offset()
  // reads either.
  std::span<const double> offsets() const { return offsets_; }
  double offset(std::size_t position) const {
    return offsets_.empty() ? 0.0 : offsets_[position];
  }
  bool has_zero_offsets() const { return offsets_.empty(); }
  const std::optional<KeyRange>& key_range() const { return key_range_; }

  // "var" / "dec"; parse_measure returns nullopt for anything else.
  static const char* measure_name(Measure measure);
  static std::optional<Measure> parse_measure(std::string_view text);

 private:
  std::vector<double> offsets_;
  Measure measure_;
  std::optional<KeyRange> key_range_;
};

// The range of keys x_i + offset_i when every domain of `scope` holds integers only and every
// offset is an integer, and the range is small enough for a dense count array (at most
// max(2^20, 16 x arity) keys); nullopt otherwise.
std::optional<AllDifferent::KeyRange> key_range_from_domains(const Problem& problem,
                                                             std::span<const VariableId> scope,
                                                             std::span<const double> offsets);

// Registry entry "all_different": fields `offsets` (optional list, one number per scope
// variable, default all 0) and `measure` ("var", the default, or "dec"). The dense key range
// is computed from the scope's domains.
//   {kind: all_different, scope: [q0, q1, q2], offsets: [0, 1, 2], measure: dec}
ConstraintKindInfo all_different_kind();

}  // namespace sightline::csp
