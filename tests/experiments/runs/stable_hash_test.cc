#include "sightline/experiments/runs/stable_hash.h"

#include <gtest/gtest.h>

#include <string>

namespace sightline::experiments {
namespace {

// Reference values of 64-bit FNV-1a (the published test vectors of the algorithm's
// authors), with the published offset basis.
TEST(StableHash, WithFnvsOffsetBasisGivesThePublishedFnv1aValues) {
  using H = StableHash;
  EXPECT_EQ(H(H::kFnvOffsetBasis).value(), 0xcbf29ce484222325ULL);
  EXPECT_EQ(H(H::kFnvOffsetBasis).add("a").value(), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(H(H::kFnvOffsetBasis).add("foobar").value(), 0x85944171f73967e8ULL);
}

// The default basis is the one run ids and manifests have always used (stable_hash.h):
// these are the values the code before StableHash computed, so old output folders resume.
TEST(StableHash, ByDefaultGivesTheValuesEarlierVersionsWroteIntoRunIds) {
  EXPECT_EQ(StableHash().value(), 1469598103934665603ULL);
  EXPECT_EQ(stable_hash("a"), 4953267810257967366ULL);
  EXPECT_EQ(stable_hash("foobar"), 9870438755804841970ULL);
}

TEST(StableHash, FeedingInPiecesEqualsFeedingAtOnce) {
  EXPECT_EQ(StableHash().add("foo").add("bar").value(), stable_hash("foobar"));
  const std::string text = "camera;scene=a#1234;seed=7";
  EXPECT_EQ(StableHash().add(text.data(), text.size()).value(), stable_hash(text));
}

TEST(StableHash, HexIsSixteenDigitsAndShortHexItsFirstEight) {
  const StableHash h = StableHash(StableHash::kFnvOffsetBasis).add("foobar");
  EXPECT_EQ(h.hex(), "85944171f73967e8");
  EXPECT_EQ(h.short_hex(), "85944171");
  EXPECT_EQ(StableHash(StableHash::kFnvOffsetBasis).add("a").hex(), "af63dc4c8601ec8c");
  EXPECT_EQ(StableHash(1).hex(), "0000000000000001");
}

}  // namespace
}  // namespace sightline::experiments
