// The .cfn reader: every instance written as .cfn (tests/csp/files/wcsp_to_cfn.h, with named values,
// dense and sparse tables, costs as strings) reads into a problem that scores random
// assignments as its .wcsp twin and as the independent evaluator of toulbar2's semantics do;
// a hand-written file using the format's other features scores every assignment as the
// format says, worked out here by hand; compressed files; and malformed files are refused
// with their line.
#include "sightline/csp/files/cfn_reader.h"

#include <gtest/gtest.h>

#include <boost/iostreams/copy.hpp>
#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filtering_stream.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/csp/input_error.h"
#include "reference_wcsp.h"
#include "wcsp_to_cfn.h"

namespace sightline::csp {
namespace {

const std::string kDataDir = std::string(SIGHTLINE_SHARED_DIR) + "/data/wcsp/";
const std::string kOwnData = std::string(SIGHTLINE_SOURCE_DIR) + "/tests/csp/files/data/";
const std::vector<std::string> kInstances = {
    "4queens", "base2",  "example", "golomb4", "magic3",    "oconnell",
    "sudoku",  "warehouse", "zebra", "latin4",  "zebre-ext", "geom40_6"};

std::filesystem::path scratch_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "sightline-cfn-test";
  std::filesystem::create_directories(dir);
  return dir;
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = (scratch_dir() / name).string();
  std::ofstream(path) << text;
  return path;
}

void expect_same_scores(const Problem& cfn, const Problem& wcsp,
                        const testing::ReferenceWcsp& reference, std::mt19937& rng) {
  ASSERT_EQ(cfn.num_variables(), wcsp.num_variables());
  for (std::size_t v = 0; v < cfn.num_variables(); ++v) {
    ASSERT_EQ(cfn.variable(v).name, "v" + std::to_string(v));
    ASSERT_EQ(cfn.variable(v).domain.size(), wcsp.variable(v).domain.size());
  }
  for (int round = 0; round < 300; ++round) {
    std::vector<double> values(cfn.num_variables());
    for (std::size_t v = 0; v < values.size(); ++v) {
      std::uniform_int_distribution<long long> value(0, reference.domains()[v] - 1);
      values[v] = static_cast<double>(value(rng));
    }
    const Score a = cfn.score(values), b = wcsp.score(values);
    ASSERT_EQ(a.hard, b.hard) << "round " << round;
    ASSERT_EQ(a.soft, b.soft) << "round " << round;
    const auto [cost, forbidden] = reference.evaluate(values);
    ASSERT_EQ(a.feasible(), !forbidden) << "round " << round;
    if (!forbidden) {
      ASSERT_EQ(a.soft, static_cast<double>(cost)) << "round " << round;
    }
  }
}

TEST(CfnReader, ReadsEveryInstanceLikeItsWcspTwin) {
  std::mt19937 rng(11);
  for (const std::string& name : kInstances) {
    SCOPED_TRACE(name);
    const std::string wcsp = kDataDir + name + ".wcsp";
    const std::string cfn = write_file(name + ".cfn", testing::wcsp_to_cfn(wcsp));
    const auto from_cfn = read_cfn_file(cfn);
    const auto from_wcsp = read_wcsp_file(wcsp);
    expect_same_scores(*from_cfn, *from_wcsp, testing::ReferenceWcsp(wcsp), rng);
  }
}

TEST(CfnReader, ReadsGzippedFiles) {
  const std::string wcsp = kDataDir + "example.wcsp";
  const std::string text = testing::wcsp_to_cfn(wcsp);
  const std::string gz = (scratch_dir() / "example.cfn.gz").string();
  {
    std::ofstream out(gz, std::ios::binary);
    boost::iostreams::filtering_ostream compressed;
    compressed.push(boost::iostreams::gzip_compressor());
    compressed.push(out);
    compressed << text;
  }
  std::mt19937 rng(3);
  expect_same_scores(*read_cfn_file(gz), *read_wcsp_file(wcsp), testing::ReferenceWcsp(wcsp),
                     rng);
}

// tests/csp/files/data/tiny.cfn, by the format's rules (UB 100: a cost >= 100 is forbidden):
//   likes(colour, size): default 1.5, (red, 0) 0, (blue, 1) 4.25
//   pairs(size, shape), dense: (0,0) 0, (0,1) 2, (1,0) 3, (1,1) 100 forbidden
//   echo(shape, size): pairs' table on (shape, size)
//   differ: salldiff var, 7 when size and shape have the same index
//   base: constant 0.5;  never(colour): green forbidden
TEST(CfnReader, ScoresEveryAssignmentOfAHandWrittenFileAsTheFormatSays) {
  const auto p = read_cfn_file(kOwnData + "tiny.cfn");
  ASSERT_EQ(p->name(), "tiny");
  ASSERT_EQ(p->num_variables(), 3u);
  EXPECT_EQ(p->variable(0).name, "colour");
  EXPECT_EQ(p->variable(1).name, "size");
  EXPECT_EQ(p->variable(2).name, "shape");
  const double pairs[2][2] = {{0, 2}, {3, 100}};
  int feasible = 0;
  for (int colour = 0; colour < 3; ++colour) {
    for (int size = 0; size < 2; ++size) {
      for (int shape = 0; shape < 2; ++shape) {
        double likes = 1.5;
        if (colour == 0 && size == 0) likes = 0;
        if (colour == 2 && size == 1) likes = 4.25;
        const bool forbidden = colour == 1 || pairs[size][shape] >= 100 || pairs[shape][size] >= 100;
        const double cost =
            likes + pairs[size][shape] + pairs[shape][size] + (size == shape ? 7 : 0) + 0.5;
        const Score s = p->score(std::vector<double>{double(colour), double(size), double(shape)});
        ASSERT_EQ(s.feasible(), !forbidden) << colour << size << shape;
        if (!forbidden) {
          EXPECT_DOUBLE_EQ(s.soft, cost) << colour << size << shape;
          ++feasible;
        }
      }
    }
  }
  EXPECT_EQ(feasible, 6);  // colour red or blue, (size, shape) not (1, 1)
}

TEST(CfnReader, AcceptsUnnamedVariablesAndFunctions) {
  const auto p = parse_cfn(R"({"problem": {"mustbe": "<10"}, "variables": [2, ["a", "b"]],
      "functions": [{"scope": [0, "x1"], "defaultcost": 1, "costs": [0, "b", 0]}]})",
                           "unnamed");
  EXPECT_EQ(p->variable(1).name, "x1");
  EXPECT_EQ(p->cost(std::vector<double>{0, 1}), 0);
  EXPECT_EQ(p->cost(std::vector<double>{1, 1}), 1);
}

struct BadCase {
  std::string text;
  std::string message;  // a part of the error message
  int line;             // expected line (0: no line)
};

TEST(CfnReader, RefusesMalformedFilesWithTheirPosition) {
  const std::string head = "{\"problem\": {\"name\": \"t\", \"mustbe\": \"<10\"},\n";
  const std::string vars = "\"variables\": {\"a\": 2, \"b\": [\"u\", \"v\"]},\n";
  auto with_function = [&](const std::string& f) {
    return head + vars + "\"functions\": {\n\"f\": " + f + "\n}}";
  };
  const std::vector<BadCase> cases = {
      {head + vars + "\"functions\": {\n  \"f\": {\"scope\": [\"a\"] \"costs\": []}}}",
       "not valid JSON", 4},
      {"{problem: {name: t, mustbe: <10}}", "relaxed CFN syntax", 1},
      {"{\"problem\": {\"mustbe\": \">10\"}, \"variables\": {}}", "maximisation", 1},
      {"{\"problem\": {\"mustbe\": \"<0\"}, \"variables\": {}}", "upper bound <= 0", 1},
      {"{\"problem\": {\"mustbe\": \"10\"}, \"variables\": {}}", "expected mustbe", 1},
      {head + "\"variables\": {\"a\": -5}}", "interval domain", 2},
      {head + "\"variables\": {\"a\": 2,\n \"a\": 3}}", "given twice", 3},
      {head + vars + "\"extra\": 1}", "unknown key 'extra'", 3},
      {with_function("{\"scope\": [\"a\"], \"defaultcost\": 0, \"costs\": [0, -1]}"),
       "negative cost", 4},
      {with_function("{\"scope\": [\"b\"], \"defaultcost\": 0, \"costs\": [\"w\", 1]}"),
       "unknown value \"w\"", 4},
      {with_function("{\"scope\": [\"a\"], \"defaultcost\": 0, \"costs\": [2, 1]}"),
       "out of range", 4},
      {with_function("{\"scope\": [\"c\"], \"defaultcost\": 0, \"costs\": []}"),
       "unknown variable \"c\"", 4},
      {with_function("{\"scope\": [\"a\", \"a\"], \"defaultcost\": 0, \"costs\": []}"),
       "appears twice", 4},
      {with_function("{\"scope\": [\"a\", \"b\"], \"costs\": [1, 2, 3]}"),
       "must list every tuple", 4},
      {with_function("{\"scope\": [\"a\"], \"defaultcost\": 0, \"costs\": [0, 1, 0, 2]}"),
       "listed twice", 4},
      {with_function("{\"scope\": [\"a\"], \"defaultcost\": 0, \"costs\": [0]}"),
       "not a multiple", 4},
      {with_function("{\"scope\": [\"a\", \"b\"], \"type\": \"sgcc\", \"params\": {}}"),
       "not supported: sgcc", 4},
      {with_function("{\"scope\": [\"a\"], \"costs\": \"g\"}"), "not defined", 4},
      {with_function("{\"scope\": [\"a\"], \"defaultcost\": \"cheap\", \"costs\": []}"),
       "expected the default cost", 4},
      {"[1, 2]", "expected a JSON object", 0},
      // Found by fuzz/cfn_fuzz: an empty variable name escaped as std::invalid_argument.
      {head + "\"variables\": {\"\": 2}}", "needs a name", 2},
  };
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      parse_cfn(c.text, "bad.cfn");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
      EXPECT_EQ(e.where().file, "bad.cfn");
      EXPECT_EQ(e.where().line, c.line) << e.what();
    }
  }
}

TEST(CfnReader, ReportsAMissingFile) {
  EXPECT_THROW(read_cfn_file("/nonexistent/x.cfn"), InputError);
}

}  // namespace
}  // namespace sightline::csp
