// StableHash: FNV-1a, 64 bits, for the hashes that end up in files (run ids, the output
// folder's manifest, the replay's level keys, the MPI ranks' agreement check).
//
// Why not std::hash: it is not promised to give the same value across builds, compilers or
// machines, and these hashes are compared between runs of different builds and between the
// ranks of a cluster. FNV-1a is tiny, byte-order free when fed bytes, and good enough for
// telling definitions apart (not for security).
//
// The default starting value is not FNV's published offset basis 14695981039346656037 but
// 1469598103934665603: the first version of the run ids lost the basis' last digit. Every
// run id, manifest and replay key written since hashes with it, and suites resume from
// those files, so it stays (any non-zero start hashes as well). `kFnvOffsetBasis` gives the
// published FNV-1a, which the tests check against the algorithm's reference values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace sightline::experiments {

class StableHash {
 public:
  static constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ULL;
  static constexpr std::uint64_t kSightlineBasis = 1469598103934665603ULL;

  explicit StableHash(std::uint64_t basis = kSightlineBasis) : value_(basis) {}
  StableHash& add(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) value_ = (value_ ^ bytes[i]) * kPrime;
    return *this;
  }
  StableHash& add(std::string_view text) { return add(text.data(), text.size()); }
  std::uint64_t value() const { return value_; }
  // All 16 hex digits.
  std::string hex() const;
  // The high 8 hex digits: short enough for a file name.
  std::string short_hex() const;

 private:
  static constexpr std::uint64_t kPrime = 1099511628211ULL;
  std::uint64_t value_;
};

inline std::uint64_t stable_hash(std::string_view text) { return StableHash().add(text).value(); }

}  // namespace sightline::experiments
