#include "sightline/csp/kinds/all_different.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

#include "sightline/csp/problem.h"

namespace sightline::csp {

namespace {

// Violation change when one variable leaves key a (count c_a before) for key b (count c_b
// before), a != b.
//   var: sum max(0, c-1) = arity - number of distinct keys. Leaving a removes a duplicate
//        when c_a >= 2; joining b adds one when c_b >= 1.
//   dec: sum c(c-1)/2. Leaving a drops the c_a - 1 pairs it formed there; joining b forms c_b.
inline double move_delta(AllDifferent::Measure measure, std::int64_t count_a,
                         std::int64_t count_b) {
  if (measure == AllDifferent::Measure::kVariables) {
    return static_cast<double>((count_b >= 1 ? 1 : 0) - (count_a >= 2 ? 1 : 0));
  }
  return static_cast<double>(count_b - (count_a - 1));
}

// Violation change when a variable joins key b (count c_b before) / leaves key a (count
// c_a before, the variable included): the partial-assignment halves of move_delta.
inline double join_delta(AllDifferent::Measure measure, std::int64_t count_b) {
  if (measure == AllDifferent::Measure::kVariables) return count_b >= 1 ? 1.0 : 0.0;
  return static_cast<double>(count_b);
}
inline double leave_delta(AllDifferent::Measure measure, std::int64_t count_a) {
  if (measure == AllDifferent::Measure::kVariables) return count_a >= 2 ? -1.0 : 0.0;
  return -static_cast<double>(count_a - 1);
}

// The variable's share of the violation at a key holding `count` variables.
inline double share(AllDifferent::Measure measure, std::int64_t count) {
  if (count < 2) return 0;
  if (measure == AllDifferent::Measure::kVariables) {
    return static_cast<double>(count - 1) / static_cast<double>(count);
  }
  return static_cast<double>(count - 1);
}

// Counts in a dense array indexed by key - lo, for integer keys in a known range. Each scope
// position keeps its current index and its shift (offset - lo) side by side, so a delta
// reads one slot and two counts and never the assignment: at 1,000,000 queens the memory
// traffic, not the arithmetic, is the cost, so slots are 8 bytes when the shifts fit in 32
// bits (Shift = std::int32_t) and 16 otherwise. Besides the counts, one bit per key says
// whether its count is above zero: placement tests only that (occupied_keys), and the bits,
// 32 times smaller than the counts, stay in cache.
template <class Shift>
class DenseState final : public IncrementalState {
 public:
  DenseState(const AllDifferent& c, AllDifferent::KeyRange range, std::span<const double> values)
      : measure_(c.measure()),
        counts_(static_cast<std::size_t>(range.hi - range.lo + 1), 0),
        occupied_((counts_.size() + 63) / 64, 0),
        slots_(c.scope().size()) {
    const auto scope = c.scope();
    for (std::size_t i = 0; i < scope.size(); ++i) {
      slots_[i].shift = static_cast<Shift>(static_cast<std::int64_t>(c.offset(i)) - range.lo);
      slots_[i].index = static_cast<Shift>(index(i, values[scope[i]]));
      violation_ += join(static_cast<std::size_t>(slots_[i].index));
    }
  }

  std::optional<double> current_violation() const override { return violation_; }

  double delta(std::span<const double>, std::size_t position, double new_value) override {
    settle();
    const auto a = static_cast<std::size_t>(slots_[position].index);
    const std::size_t b = index(position, new_value);
    if (a == b) return 0;
    return move_delta(measure_, counts_[a], counts_[b]);
  }

  void commit(std::span<const double>, std::size_t position, double new_value) override {
    settle();
    Slot& slot = slots_[position];
    const auto a = static_cast<std::size_t>(slot.index);
    const std::size_t b = index(position, new_value);
    if (a == b) return;
    violation_ += move_delta(measure_, counts_[a], counts_[b]);
    leave(a);
    join(b);
    slot.index = static_cast<Shift>(b);
  }

  double involvement(std::span<const double>, std::size_t position) override {
    settle();
    return share(measure_, counts_[static_cast<std::size_t>(slots_[position].index)]);
  }

  // Partial assignments: a retracted variable is simply not counted.
  bool supports_partial() const override { return true; }
  double retract(std::span<const double>, std::size_t position) override {
    settle();
    const auto a = static_cast<std::size_t>(slots_[position].index);
    const double change = leave(a);
    violation_ += change;
    return change;
  }
  double retract_all(std::span<const double>, std::size_t) override {
    unsettled_ = false;
    std::fill(counts_.begin(), counts_.end(), 0);
    std::fill(occupied_.begin(), occupied_.end(), 0);
    const double change = -violation_;
    violation_ = 0;
    return change;
  }
  double place_delta(std::span<const double>, std::size_t position, double new_value) override {
    settle();
    return join_delta(measure_, counts_[index(position, new_value)]);
  }
  void place(std::span<const double>, std::size_t position, double new_value) override {
    settle();
    const std::size_t b = index(position, new_value);
    violation_ += join(b);
    slots_[position].index = static_cast<Shift>(b);
  }
  // The key is free (count 0, both measures): only its bit is set now; settle() brings
  // the count to 1 when a count is next needed. A placement phase places most variables
  // this way, and a random write to the counts each time would cost about as much as the
  // rest of the phase.
  double place_free(std::span<const double>, std::size_t position, double new_value) override {
    const std::size_t b = index(position, new_value);
    assert(!(occupied_[b / 64] >> (b % 64) & 1));
    occupied_[b / 64] |= std::uint64_t{1} << (b % 64);
    slots_[position].index = static_cast<Shift>(b);
    unsettled_ = true;
    return 0;
  }

  // place_delta is join_delta of the count: > 0 exactly when the count is (both measures).
  OccupiedKeys occupied_keys() const override {
    if constexpr (std::is_same_v<Shift, std::int32_t>) {
      if (slots_.empty()) return {};
      const auto* slots = reinterpret_cast<const unsigned char*>(slots_.data());
      return {occupied_.data(), slots + offsetof(Slot, shift), sizeof(Slot)};
    } else {
      return {};
    }
  }

 private:
  struct Slot {
    Shift index;  // current key - lo (below the range size, which fits Shift)
    Shift shift;  // offset - lo
  };
  // After place_free: every occupied key whose count is still 0 was placed into free, and
  // holds exactly one variable. One pass over the bits, in key order: O(range / 64 + keys
  // occupied), cheap after placing many variables in a row (what place_free is for), not
  // after each of a few.
  void settle() {
    if (!unsettled_) return;
    unsettled_ = false;
    for (std::size_t w = 0; w < occupied_.size(); ++w) {
      for (std::uint64_t bits = occupied_[w]; bits != 0; bits &= bits - 1) {
        std::int32_t& count = counts_[w * 64 + static_cast<std::size_t>(std::countr_zero(bits))];
        if (count == 0) count = 1;
      }
    }
  }
  // A variable joins / leaves key k; returns the change in violation. The bit of k in
  // occupied_ says whether its count is above zero.
  double join(std::size_t k) {
    if (counts_[k] == 0) occupied_[k / 64] |= std::uint64_t{1} << (k % 64);
    return join_delta(measure_, counts_[k]++);
  }
  double leave(std::size_t k) {
    const double change = leave_delta(measure_, counts_[k]);
    if (--counts_[k] == 0) occupied_[k / 64] &= ~(std::uint64_t{1} << (k % 64));
    return change;
  }
  // Values of integer domains are integers, so the conversion is exact.
  std::size_t index(std::size_t position, double value) const {
    const std::int64_t i = static_cast<std::int64_t>(value) + slots_[position].shift;
    assert(i >= 0 && static_cast<std::size_t>(i) < counts_.size());
    return static_cast<std::size_t>(i);
  }

  AllDifferent::Measure measure_;
  std::vector<std::int32_t> counts_;
  std::vector<std::uint64_t> occupied_;  // bit k: counts_[k] > 0 (once settled)
  bool unsettled_ = false;               // place_free has left counts behind the bits
  std::vector<Slot> slots_;
  double violation_ = 0;  // of the variables present, kept up to date
};

// True when every offset - lo, and the range size, fit in 32 bits.
bool fits_32_bits(const AllDifferent& c, AllDifferent::KeyRange range) {
  constexpr std::int64_t kMax = INT32_MAX;
  if (range.hi - range.lo >= kMax) return false;
  const auto fits = [&](double o) {
    const std::int64_t shift = static_cast<std::int64_t>(o) - range.lo;
    return shift <= kMax && shift >= -kMax;
  };
  if (c.has_zero_offsets()) return fits(0);
  return std::all_of(c.offsets().begin(), c.offsets().end(), fits);
}

// Counts in a hash map keyed by the (real) key itself.
class HashCounts {
 public:
  explicit HashCounts(std::size_t arity) { counts_.reserve(2 * arity); }
  using Key = double;
  Key key(double shifted) const { return shifted == 0 ? 0.0 : shifted; }  // -0 == +0
  std::int32_t count(Key k) const {
    auto it = counts_.find(k);
    return it == counts_.end() ? 0 : it->second;
  }
  void add(Key k, std::int32_t n) { counts_[k] += n; }

 private:
  std::unordered_map<double, std::int32_t> counts_;
};

template <class Counts>
class CountingState final : public IncrementalState {
 public:
  CountingState(const AllDifferent& c, Counts counts, std::span<const double> values)
      : scope_(c.scope()),
        offsets_(c.offsets()),  // empty: all zero
        measure_(c.measure()),
        counts_(std::move(counts)) {
    for (std::size_t i = 0; i < scope_.size(); ++i) counts_.add(key_at(values, i), 1);
  }

  double delta(std::span<const double> values, std::size_t position, double new_value) override {
    const auto a = key_at(values, position);
    const auto b = counts_.key(new_value + offset(position));
    if (a == b) return 0;
    return move_delta(measure_, counts_.count(a), counts_.count(b));
  }

  void commit(std::span<const double> values, std::size_t position, double new_value) override {
    const auto a = key_at(values, position);
    const auto b = counts_.key(new_value + offset(position));
    if (a == b) return;
    counts_.add(a, -1);
    counts_.add(b, 1);
  }

  double involvement(std::span<const double> values, std::size_t position) override {
    return share(measure_, counts_.count(key_at(values, position)));
  }

  bool supports_partial() const override { return true; }
  double retract(std::span<const double> values, std::size_t position) override {
    const auto a = key_at(values, position);
    const double change = leave_delta(measure_, counts_.count(a));
    counts_.add(a, -1);
    return change;
  }
  double place_delta(std::span<const double>, std::size_t position, double new_value) override {
    return join_delta(measure_, counts_.count(counts_.key(new_value + offset(position))));
  }
  void place(std::span<const double>, std::size_t position, double new_value) override {
    counts_.add(counts_.key(new_value + offset(position)), 1);
  }

 private:
  typename Counts::Key key_at(std::span<const double> values, std::size_t position) const {
    return counts_.key(values[scope_[position]] + offset(position));
  }
  double offset(std::size_t position) const {
    return offsets_.empty() ? 0.0 : offsets_[position];
  }

  std::span<const VariableId> scope_;
  std::span<const double> offsets_;
  AllDifferent::Measure measure_;
  Counts counts_;
};

}  // namespace

AllDifferent::AllDifferent(std::vector<VariableId> scope, std::vector<double> offsets,
                           Measure measure, double weight, bool hard,
                           std::optional<KeyRange> key_range)
    : Constraint(std::move(scope), weight, hard),
      offsets_(std::move(offsets)),
      measure_(measure),
      key_range_(key_range) {
  if (!offsets_.empty() && offsets_.size() != this->scope().size()) {
    throw std::invalid_argument("all_different: " + std::to_string(offsets_.size()) +
                                " offsets for " + std::to_string(this->scope().size()) +
                                " variables");
  }
  for (double o : offsets_) {
    if (!std::isfinite(o)) throw std::invalid_argument("all_different: offsets must be finite");
  }
  if (std::all_of(offsets_.begin(), offsets_.end(), [](double o) { return o == 0; })) {
    std::vector<double>().swap(offsets_);  // all zero: kept as none (see the header)
  }
  if (key_range_ && key_range_->hi < key_range_->lo) {
    throw std::invalid_argument("all_different: empty key range");
  }
}


namespace {
// violation and min_violation work in these per-thread buffers, which grow to the largest
// arity seen and are then reused: no allocation per call, and constraints stay safe to
// evaluate from several threads at once (a mutable member would not be).
std::vector<double>& key_scratch() {
  thread_local std::vector<double> keys;
  return keys;
}
std::vector<std::int32_t>& count_scratch() {
  thread_local std::vector<std::int32_t> counts;
  return counts;
}
std::vector<std::uint64_t>& bit_scratch() {
  thread_local std::vector<std::uint64_t> bits;
  return bits;
}

// Sum over the distinct keys of the measure's cost of c equal keys; `keys` gets sorted.
double repeats(std::vector<double>& keys, AllDifferent::Measure measure) {
  std::sort(keys.begin(), keys.end());
  double total = 0;
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    const double c = static_cast<double>(j - i);
    total += measure == AllDifferent::Measure::kVariables ? c - 1 : c * (c - 1) / 2;
    i = j;
  }
  return total;
}
}  // namespace

double AllDifferent::min_violation(std::span<const double> values,
                                   std::span<const std::uint8_t> assigned) const {
  const auto scope = this->scope();
  std::vector<double>& keys = key_scratch();
  keys.clear();
  for (std::size_t i = 0; i < scope.size(); ++i) {
    if (assigned[scope[i]]) keys.push_back(values[scope[i]] + offset(i));
  }
  return repeats(keys, measure_);
}

namespace {
// Visits the dense key index (key - lo) of every scope position in order, calling
// `count(index)`; returns false, having stopped, at the first key outside [0, size) or not
// an integer (the caller then falls back to sorting).
template <class Count>
bool for_each_dense_key(std::span<const VariableId> scope, std::span<const double> offsets,
                        std::span<const double> values, AllDifferent::KeyRange range,
                        std::size_t size, Count&& count) {
  const auto lo = static_cast<double>(range.lo);
  const auto limit = static_cast<double>(size);
  const bool zero = offsets.empty();  // all offsets zero
  for (std::size_t i = 0; i < scope.size(); ++i) {
    const double key = values[scope[i]] + (zero ? 0.0 : offsets[i]) - lo;
    if (!(key >= 0 && key < limit)) return false;  // also false for NaN
    const auto k = static_cast<std::int64_t>(key);
    if (static_cast<double>(k) != key) return false;  // not an integer
    count(static_cast<std::size_t>(k));
  }
  return true;
}
}  // namespace

double AllDifferent::violation(std::span<const double> values) const {
  const auto scope = this->scope();
  if (key_range_) {
    // O(arity + range) by counting, as long as every key falls in the range. The violation
    // is summed as the keys are counted (each variable joining a key adds join_delta),
    // which saves a second pass. The var measure needs only "seen before?", one bit per key:
    // the bit array is 32x smaller than counts (256 KiB for 2,000,000 keys), so it stays in
    // cache where random increments of a count array would not.
    const auto size = static_cast<std::size_t>(key_range_->hi - key_range_->lo + 1);
    double total = 0;
    bool in_range;
    if (measure_ == Measure::kVariables) {
      std::vector<std::uint64_t>& seen = bit_scratch();
      seen.assign((size + 63) / 64, 0);
      std::size_t repeats_seen = 0;
      in_range = for_each_dense_key(scope, offsets_, values, *key_range_, size, [&](std::size_t k) {
        std::uint64_t& word = seen[k / 64];
        const std::uint64_t bit = std::uint64_t{1} << (k % 64);
        repeats_seen += (word & bit) != 0;
        word |= bit;
      });
      total = static_cast<double>(repeats_seen);
    } else {
      std::vector<std::int32_t>& counts = count_scratch();
      counts.assign(size, 0);
      in_range = for_each_dense_key(scope, offsets_, values, *key_range_, size, [&](std::size_t k) {
        total += join_delta(measure_, counts[k]++);
      });
    }
    if (in_range) return total;
  }
  std::vector<double>& keys = key_scratch();
  keys.resize(scope.size());
  for (std::size_t i = 0; i < scope.size(); ++i) keys[i] = values[scope[i]] + offset(i);
  return repeats(keys, measure_);
}

std::unique_ptr<IncrementalState> AllDifferent::make_incremental_state(
    std::span<const double> values) const {
  if (key_range_) {
    if (fits_32_bits(*this, *key_range_)) {
      return std::make_unique<DenseState<std::int32_t>>(*this, *key_range_, values);
    }
    return std::make_unique<DenseState<std::int64_t>>(*this, *key_range_, values);
  }
  return std::make_unique<CountingState<HashCounts>>(*this, HashCounts(scope().size()), values);
}

const char* AllDifferent::measure_name(Measure measure) {
  return measure == Measure::kVariables ? "var" : "dec";
}

std::optional<AllDifferent::Measure> AllDifferent::parse_measure(std::string_view text) {
  if (text == "var") return Measure::kVariables;
  if (text == "dec") return Measure::kDecomposition;
  return std::nullopt;
}

std::optional<AllDifferent::KeyRange> key_range_from_domains(const Problem& problem,
                                                             std::span<const VariableId> scope,
                                                             std::span<const double> offsets) {
  constexpr double kMaxKeyMagnitude = 1e15;  // far inside the exactly representable integers
  double lo = 0, hi = 0;
  const Domain* checked = nullptr;  // the last domain whose values were checked
  const Domain* last = nullptr;     // the previous variable's domain
  for (std::size_t i = 0; i < scope.size(); ++i) {
    const Domain& d = problem.domain(scope[i]);
    const double offset = offsets.empty() ? 0.0 : offsets[i];
    // An integer offset: within the key magnitude (NaN is not) and equal to its truncation,
    // which is two inline conversions where std::floor is a library call (per variable, on
    // millions of variables).
    if (!(std::abs(offset) <= kMaxKeyMagnitude) ||
        offset != static_cast<double>(static_cast<std::int64_t>(offset))) {
      return std::nullopt;
    }
    // Variables of an add_variables batch share one Domain: it is looked at once per run
    // of variables, and a value set's values once, not once per variable (a value set of n
    // values on n variables would be n^2).
    if (&d != last) {
      if (!d.is_discrete()) return std::nullopt;
      if (&d != checked && d.kind() == DomainKind::kValueSet) {
        checked = &d;
        for (std::size_t k = 0; k < d.size(); ++k) {
          const double v = d.value_at(k);
          if (v != std::floor(v)) return std::nullopt;
        }
      }
      last = &d;
    }
    const double key_lo = d.lower() + offset, key_hi = d.upper() + offset;
    if (std::abs(key_lo) > kMaxKeyMagnitude || std::abs(key_hi) > kMaxKeyMagnitude) {
      return std::nullopt;
    }
    lo = i == 0 ? key_lo : std::min(lo, key_lo);
    hi = i == 0 ? key_hi : std::max(hi, key_hi);
  }
  const double limit = std::max(double(1 << 20), 16.0 * static_cast<double>(scope.size()));
  if (scope.empty() || hi - lo + 1 > limit) return std::nullopt;
  return AllDifferent::KeyRange{static_cast<std::int64_t>(lo), static_cast<std::int64_t>(hi)};
}

ConstraintKindInfo all_different_kind() {
  ConstraintKindInfo info;
  info.name = "all_different";
  info.description =
      "values x_i + offset_i pairwise different; measure var (variables to change) or dec "
      "(equal pairs)";
  info.fields = {"offsets", "measure"};
  info.example_arity = 3;
  info.example = "measure: dec";
  info.factory = [](const ConstraintRequest& request) -> std::unique_ptr<Constraint> {
    std::vector<double> offsets;
    if (const Spec* spec = request.params.find("offsets")) {
      offsets = spec->as_numbers("a list of numbers (one offset per variable)");
      if (offsets.size() != request.scope.size()) {
        spec->fail("expected " + std::to_string(request.scope.size()) +
                   " offsets (one per variable), got " + std::to_string(offsets.size()));
      }
    }
    auto measure = AllDifferent::Measure::kVariables;
    if (const Spec* spec = request.params.find("measure")) {
      const std::string& text = spec->as_string("a measure name (var or dec)");
      const auto parsed = AllDifferent::parse_measure(text);
      if (!parsed) spec->fail("expected measure 'var' or 'dec', got '" + text + "'");
      measure = *parsed;
    }
    const auto range = key_range_from_domains(request.problem, request.scope, offsets);
    return std::make_unique<AllDifferent>(request.scope, std::move(offsets), measure,
                                          request.weight, request.hard, range);
  };
  return info;
}

}  // namespace sightline::csp
