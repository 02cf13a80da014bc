// The .wcsp reader: every instance of ../shared/data/wcsp read and scored like toulbar2 (an
// independent evaluator of the format written here, with no splitting into hard and soft
// parts, is the reference), hand-computed costs on 4queens, compressed files, and clear
// errors for malformed input.
#include "sightline/csp/files/wcsp_reader.h"

#include <gtest/gtest.h>

#include <boost/iostreams/copy.hpp>
#include <boost/iostreams/filter/bzip2.hpp>
#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filter/lzma.hpp>
#include <boost/iostreams/filtering_stream.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "tests/csp/brute_force.h"
#include "sightline/csp/input_error.h"
#include "reference_wcsp.h"

namespace sightline::csp {
namespace {

const std::string kDataDir = std::string(SIGHTLINE_SHARED_DIR) + "/data/wcsp/";
const std::vector<std::string> kInstances = {"4queens",  "base2",  "example",   "golomb4", "magic3",
                                             "oconnell", "sudoku", "warehouse", "zebra"};

TEST(WcspReader, ScoresEveryInstanceLikeToulbar2) {
  std::mt19937 rng(5);
  for (const std::string& name : kInstances) {
    SCOPED_TRACE(name);
    auto problem = read_wcsp_file(kDataDir + name + ".wcsp");
    testing::ReferenceWcsp reference(kDataDir + name + ".wcsp");
    ASSERT_EQ(problem->num_variables(), reference.domains().size());
    for (std::size_t v = 0; v < problem->num_variables(); ++v) {
      ASSERT_EQ(problem->variable(v).name, "x" + std::to_string(v));
      ASSERT_EQ(problem->variable(v).domain.size(),
                static_cast<std::size_t>(reference.domains()[v]));
      ASSERT_EQ(problem->variable(v).domain.value_at(0), 0.0);
    }
    // Random assignments (on the hard instances nearly all are forbidden, so there this
    // checks feasibility; instances_test.cc checks the optimal ones' costs).
    for (int round = 0; round < 300; ++round) {
      std::vector<double> values(problem->num_variables());
      for (std::size_t v = 0; v < values.size(); ++v) {
        std::uniform_int_distribution<long long> value(0, reference.domains()[v] - 1);
        values[v] = static_cast<double>(value(rng));
      }
      const auto [cost, forbidden] = reference.evaluate(values);
      const Score s = problem->score(values);
      ASSERT_EQ(s.feasible(), !forbidden) << "round " << round;
      if (!forbidden) {
        ASSERT_EQ(s.soft, static_cast<double>(cost)) << "round " << round;
      }
    }
  }
}

TEST(WcspReader, ScoresBase2ExhaustivelyLikeToulbar2) {
  // 4^10 assignments: every one, so feasible ones (and their costs) are checked too.
  auto problem = read_wcsp_file(kDataDir + "base2.wcsp");
  testing::ReferenceWcsp reference(kDataDir + "base2.wcsp");
  std::size_t feasible = 0;
  testing::for_each_assignment(*problem, [&](const std::vector<double>& values) {
    const auto [cost, forbidden] = reference.evaluate(values);
    const Score s = problem->score(values);
    ASSERT_EQ(s.feasible(), !forbidden);
    if (!forbidden) {
      ASSERT_EQ(s.soft, static_cast<double>(cost));
      ++feasible;
    }
  });
  EXPECT_GT(feasible, 0u);
}

TEST(WcspReader, FourQueensCostsMatchTheFileReadByHand) {
  // 4queens.wcsp: UB 1, three 4-ary tables of default cost 1 (forbidden) listing the
  // allowed tuples at cost 0: rows all different (line 3), and the two diagonal directions
  // (lines 28 and 119). So every allowed assignment costs 0, and the hard violation counts
  // the tables that do not list it (looked up by hand in the file).
  auto problem = read_wcsp_file(kDataDir + "4queens.wcsp");
  EXPECT_EQ(problem->name(), "4_QUEENS");
  EXPECT_EQ(problem->num_constraints(), 3u);  // hard parts only: no soft cost anywhere
  struct Known {
    std::vector<double> queens;
    double hard;
  };
  for (const Known& k : {Known{{1, 3, 0, 2}, 0},     // listed in all three: a solution
                         Known{{2, 0, 3, 1}, 0},     // the other solution
                         Known{{0, 1, 2, 3}, 1},     // one diagonal: not at line 119's table
                         Known{{3, 2, 1, 0}, 1},     // the other diagonal: not at line 28's
                         Known{{0, 0, 0, 0}, 1},     // one row: not a permutation (line 3)
                         Known{{0, 2, 0, 2}, 1}}) {  // rows repeat, diagonals fine
    const Score s = problem->score(k.queens);
    EXPECT_EQ(s.hard, k.hard) << k.queens[0] << k.queens[1] << k.queens[2] << k.queens[3];
    EXPECT_EQ(s.soft, 0.0);
  }
}

std::unique_ptr<Problem> parse_text(const std::string& text) {
  std::istringstream in(text);
  return parse_wcsp(in, "t.wcsp");
}

TEST(WcspReader, SplitsForbiddenTuplesIntoAHardTable) {
  // UB 10: tuple (0,1) costs 10 (forbidden), (1,1) costs 3, default 2; x1 has a unary
  // with default 10 (forbidden) allowing only value 1 at cost 4; a constant 1.
  auto p = parse_text("t 2 2 3 10\n2 2\n2 0 1 2 2\n0 1 10\n1 1 3\n1 1 10 1\n1 4\n0 1 0\n");
  auto score = [&](double a, double b) { return p->score(std::vector<double>{a, b}); };
  EXPECT_FALSE(score(0, 1).feasible());
  EXPECT_FALSE(score(0, 0).feasible());  // x1 = 0 is forbidden by the unary default
  EXPECT_EQ(score(1, 1).soft, 3 + 4 + 1);
  EXPECT_TRUE(score(1, 1).feasible());
  EXPECT_EQ(score(1, 0).hard, 1);
  // Labels say which function each part comes from.
  std::vector<std::string> labels;
  for (ConstraintId c = 0; c < p->num_constraints(); ++c)
    labels.push_back(p->constraint(c).label());
  EXPECT_EQ(labels, (std::vector<std::string>{"f0/hard", "f0", "f1/hard", "f1", "f2 (constant)"}));
}

TEST(WcspReader, ReusesASharedFunctionWithItsOwnDefault) {
  // -2 defines shared function 1 (default 5); "2 1 2 0 -1" reuses it on (x1, x2) with a
  // default of 0 that toulbar2 ignores (it keeps the shared table's).
  auto p = parse_text("s 3 2 2 100\n2 2 2\n-2 0 1 5 1\n0 0 1\n2 1 2 0 -1\n");
  EXPECT_EQ(p->cost(std::vector<double>{0, 0, 0}), 1 + 1);
  EXPECT_EQ(p->cost(std::vector<double>{0, 0, 1}), 1 + 5);
  EXPECT_EQ(p->cost(std::vector<double>{1, 1, 1}), 5 + 5);
}

TEST(WcspReader, ReadsSalldiffAsAllDifferent) {
  // Soft (cost 3 < UB) with the var measure, hard (cost >= UB) with dec.
  auto p = parse_text("a 3 3 2 10\n3 3 3\n3 0 1 2 -1 salldiff var 3\n2 0 1 -1 salldiff dec 10\n");
  ASSERT_EQ(p->num_constraints(), 2u);
  EXPECT_EQ(p->constraint(0).kind(), "all_different");
  EXPECT_EQ(p->cost(std::vector<double>{0, 1, 1}), 3);
  EXPECT_EQ(p->cost(std::vector<double>{2, 2, 2}), 6);
  EXPECT_TRUE(p->score(std::vector<double>{0, 1, 1}).feasible());
  EXPECT_FALSE(p->score(std::vector<double>{1, 1, 0}).feasible());
}

// The error of reading `text`, as "line: message".
std::string error_of(const std::string& text) {
  try {
    parse_text(text);
  } catch (const InputError& e) {
    return std::to_string(e.where().line) + ": " + e.detail();
  }
  return "no error";
}

void expect_error(const std::string& text, int line, const std::string& fragment) {
  const std::string error = error_of(text);
  EXPECT_EQ(error.substr(0, error.find(':')), std::to_string(line)) << error;
  EXPECT_NE(error.find(fragment), std::string::npos) << error;
}

TEST(WcspReader, ExplainsMalformedFilesWithTheirLine) {
  const std::string head = "p 2 3 1 5\n3 3\n";
  expect_error("p 2 x 1 5\n3 3\n", 1, "expected the maximum domain size (an integer), got 'x'");
  expect_error("p 2 3 1 0\n3 3\n", 1, "upper bound must be a positive integer");
  expect_error("p 2 3 1 5\n3\n", 2,
               "unexpected end of file: expected the domain size of variable 1");
  expect_error("p 2 3 1 5\n3 -4\n", 2, "not supported: interval domain");
  expect_error("p 2 3 1 5\n3 4\n", 2, "exceeds the maximum domain size 3");
  expect_error(head + "2 0 1 -1 sgcc var 1 1 0 0 1\n", 3, "not supported: sgcc");
  expect_error(head + "2 0 1 -1 salldiff decbi 1\n", 3, "not supported: salldiff decbi");
  expect_error(head + "2 0 1 0 2\n0 0 1\n3 1 1\n", 5,
               "value index 3 is out of range for variable 0");
  expect_error(head + "2 0 5 0 0\n", 3, "variable index 5 is out of range");
  expect_error(head + "2 1 1 0 0\n", 3, "variable 1 appears twice");
  expect_error(head + "2 0 1 0 3\n0 0 1\n1 1 1\n", 5,
               "unexpected end of file: expected value index 0 of tuple 2 of 3 (in cost function 0 "
               "of 1, which starts at line 3)");
  expect_error(head + "2 0 1 0 2\n0 0 1\n0 0 2\n", 5,
               "tuple (0 0) is listed twice (first at line 4)");
  expect_error(head + "2 0 1 0 -2\n", 3,
               "shared cost function 2 is used but only 0 have been defined");
  expect_error(head + "2 0 1 -3 1\n", 3, "default cost must be >= 0");
  expect_error(head + "1 0 0 1\n0 1\n1 1 0 0\n", 5,
               "unexpected '1' after the last of the 1 cost functions");
  expect_error(
      "p 2 3 2 5\n3 3\n1 0 0 1\n0 1\n", 4,
      "unexpected end of file: expected the arity of cost function 1 (cost function 1 of 2)");
  expect_error(head + "1 0 0 1\n0 1.5\n", 4,
               "expected the cost of tuple 0 of 1 (an integer), got '1.5'");
}

TEST(WcspReader, ReportsAMissingFile) {
  try {
    read_wcsp_file(kDataDir + "no-such-file.wcsp");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open file"), std::string::npos);
    EXPECT_NE(e.where().file.find("no-such-file.wcsp"), std::string::npos);
  }
}

// Writes `source` compressed with `filter` to `target`.
template <class Filter>
void compress(const std::string& source, const std::string& target, Filter filter) {
  std::ifstream in(source, std::ios::binary);
  std::ofstream out(target, std::ios::binary);
  boost::iostreams::filtering_ostream compressed;
  compressed.push(filter);
  compressed.push(out);
  boost::iostreams::copy(in, compressed);
}

TEST(WcspReader, ReadsCompressedFilesWhateverTheirName) {
  const auto dir = std::filesystem::temp_directory_path() / "sightline-wcsp-test";
  std::filesystem::create_directories(dir);
  const std::string source = kDataDir + "example.wcsp";
  const std::string gz = (dir / "example.wcsp.gz").string();
  const std::string bz2 = (dir / "example.wcsp.bz2").string();
  const std::string xz = (dir / "example-xz.wcsp").string();
  compress(source, gz, boost::iostreams::gzip_compressor());
  compress(source, bz2, boost::iostreams::bzip2_compressor());
  compress(source, xz, boost::iostreams::lzma_compressor());
  auto plain = read_wcsp_file(source);
  std::mt19937 rng(2);
  std::uniform_int_distribution<int> value(0, 4);
  for (const std::string& path : {gz, bz2, xz}) {
    SCOPED_TRACE(path);
    auto p = read_wcsp_file(path);
    ASSERT_EQ(p->num_variables(), plain->num_variables());
    ASSERT_EQ(p->num_constraints(), plain->num_constraints());
    for (int round = 0; round < 50; ++round) {
      std::vector<double> values(p->num_variables());
      for (double& v : values) v = value(rng);
      ASSERT_EQ(p->cost(values), plain->cost(values));
    }
  }
  // A truncated gzip file is an error, not a silently shorter problem.
  const std::string broken = (dir / "broken.wcsp.gz").string();
  {
    std::ifstream in(gz, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(broken, std::ios::binary);
    out << bytes.substr(0, bytes.size() / 2);
  }
  try {
    read_wcsp_file(broken);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, broken);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sightline::csp
