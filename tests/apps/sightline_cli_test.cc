// The `sightline` program end to end: it is run as a user would run it (through the shell)
// and judged on its exit status and what it prints. Bad input must give a non-zero status and
// a message naming the file and line or listing the valid names, never a crash.
#include <gtest/gtest.h>

#include "run_sightline.h"
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using sightline::test::Outcome;
using sightline::test::run;
using sightline::test::contains;

std::string example(const std::string& name) {
  return std::string(SIGHTLINE_SOURCE_DIR) + "/examples/graphs/" + name;
}


// The numbers on the last non-empty line of `output` (where --print-solution - writes).
std::vector<int> last_line_numbers(const std::string& output) {
  std::istringstream lines(output);
  std::string line, last;
  while (std::getline(lines, line)) {
    if (!line.empty()) last = line;
  }
  std::istringstream numbers(last);
  std::vector<int> out;
  for (int x; numbers >> x;) out.push_back(x);
  return out;
}

// A scratch file in the test's temporary directory, removed at the end of the test.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& text)
      : path_(std::filesystem::temp_directory_path() /
              ("sightline_cli_test_" + std::to_string(::getpid()) + "_" + name)) {
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

TEST(SightlineCli, ListsTheGridSlsAndSlidingOctreeSolversWithTheirOptions) {
  const Outcome r = run("solvers");
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* name : {"grid:", "sls:", "sliding-octree:", "max_points", "passes"}) {
    EXPECT_TRUE(contains(r.output, name)) << name << " missing from:\n" << r.output;
  }
}

TEST(SightlineCli, ListsTheConstraintKinds) {
  const Outcome r = run("kinds");
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* kind : {"not_equal", "all_different", "linear", "expression"}) {
    EXPECT_TRUE(contains(r.output, kind)) << kind;
  }
}

TEST(SightlineCli, SolvesEightQueensAndPrintsAValidPlacement) {
  const Outcome r = run("nqueens 8 --solver sls --seed 4 --print-solution -");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "independent check: 0 attacking pairs")) << r.output;
  // The solution is the last line: the row of each column's queen. Check it here, sharing
  // nothing with the program: a permutation with no two queens on a diagonal.
  const std::vector<int> rows = last_line_numbers(r.output);
  ASSERT_EQ(rows.size(), 8u) << r.output;
  EXPECT_EQ(std::set<int>(rows.begin(), rows.end()).size(), 8u);
  for (int i = 0; i < 8; ++i) {
    EXPECT_GE(rows[i], 0);
    EXPECT_LT(rows[i], 8);
    for (int j = i + 1; j < 8; ++j) EXPECT_NE(std::abs(rows[i] - rows[j]), j - i) << i << "," << j;
  }
}

TEST(SightlineCli, ColoursAustraliaAndWritesTheSolutionFile) {
  const TempFile out("australia.sol", "");
  const Outcome r = run("colour '" + example("australia.yaml") +
                        "' --colours 3 --solver grid --print-solution '" + out.path() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "0 conflicting edges")) << r.output;
  std::ifstream in(out.path());
  std::vector<int> colours;
  for (int c; in >> c;) colours.push_back(c);
  ASSERT_EQ(colours.size(), 7u);
  // WA NT SA Q NSW V T: the WA-NT-SA triangle takes three colours, Q = WA, NSW = NT, V = WA.
  EXPECT_NE(colours[0], colours[1]);
  EXPECT_NE(colours[0], colours[2]);
  EXPECT_NE(colours[1], colours[2]);
  EXPECT_EQ(colours[3], colours[0]);
  EXPECT_EQ(colours[4], colours[1]);
  EXPECT_EQ(colours[5], colours[0]);
}

TEST(SightlineCli, SolvesADimacsGraphGivenTheNumberOfColours) {
  const Outcome r = run("solve '" + example("myciel3.col") + "' --colours 3 --solver grid");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "grid: cost 1 feasible")) << r.output;
  EXPECT_TRUE(contains(r.output, "violated constraints: 1 of 20")) << r.output;
}

TEST(SightlineCli, SolvesAToulbar2WcspFileAndPrintsValueIndices) {
  // Two variables of two values; the tuple (0, 0) costs 3, everything else is free. The
  // optimum is 0 at any of the other three tuples.
  const TempFile wcsp("tiny.wcsp", "tiny 2 2 1 10\n2 2\n2 0 1 0 1\n0 0 3\n");
  const Outcome r = run("solve '" + wcsp.path() + "' --solver grid --print-solution -");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "grid: cost 0 feasible")) << r.output;
  const std::vector<int> values = last_line_numbers(r.output);
  ASSERT_EQ(values.size(), 2u) << r.output;
  EXPECT_TRUE(values[0] == 0 || values[0] == 1);
  EXPECT_TRUE(values[1] == 0 || values[1] == 1);
  EXPECT_FALSE(values[0] == 0 && values[1] == 0) << "the costly tuple was printed";
}

TEST(SightlineCli, RefusesANumberOfColoursForAFileThatIsNotAGraph) {
  const TempFile wcsp("tiny.wcsp", "tiny 1 2 0 10\n2\n");
  const Outcome r = run("solve '" + wcsp.path() + "' --colours 3 --solver grid");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, wcsp.path() + ": --colours applies to DIMACS graphs")) << r.output;
}

TEST(SightlineCli, AsksForTheNumberOfColoursOfADimacsGraph) {
  const Outcome r = run("solve '" + example("myciel3.col") + "' --solver sls");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "myciel3.col")) << r.output;
  EXPECT_TRUE(contains(r.output, "--colours")) << r.output;
}

TEST(SightlineCli, NamesTheFileAndLineOfMalformedYaml) {
  const TempFile bad("bad.yaml", "name: broken\nvariables:\n  - {names: [a, b], range: [0, 3]\n");
  const Outcome r = run("solve '" + bad.path() + "' --solver grid");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "sightline: " + bad.path() + ":")) << r.output;
}

TEST(SightlineCli, NamesTheFileLineAndColumnOfABadDimacsEdge) {
  const TempFile bad("bad.col", "c comment\np edge 3 2\ne 1 2\ne 2 9\n");
  const Outcome r = run("colour '" + bad.path() + "' --colours 3 --solver sls");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, bad.path() + ":4:5: vertex 9 is out of range")) << r.output;
}

TEST(SightlineCli, NamesAMissingFile) {
  const Outcome r = run("solve /nonexistent/problem.yaml --solver sls");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "/nonexistent/problem.yaml")) << r.output;
  const Outcome g = run("colour /nonexistent/graph.col --colours 3 --solver sls");
  EXPECT_EQ(g.status, 2) << g.output;
  EXPECT_TRUE(contains(g.output, "/nonexistent/graph.col")) << g.output;
}

TEST(SightlineCli, RefusesAnUnknownFileType) {
  const Outcome r = run("solve problem.txt --solver sls");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "problem.txt")) << r.output;
  EXPECT_TRUE(contains(r.output, ".yaml")) << r.output;
}

TEST(SightlineCli, ListsTheKnownSolversForAnUnknownOne) {
  const Outcome r = run("nqueens 8 --solver simulated-annealing");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "simulated-annealing")) << r.output;
  for (const char* name : {"grid", "sls", "sliding-octree"}) {
    EXPECT_TRUE(contains(r.output, name)) << r.output;
  }
}

TEST(SightlineCli, ListsTheValidOptionsForAnUnknownOne) {
  const Outcome r = run("nqueens 8 --solver grid --set max_pionts=10");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "max_pionts")) << r.output;
  EXPECT_TRUE(contains(r.output, "max_points")) << r.output;
}

TEST(SightlineCli, RefusesNotANumberWhereANumberIsExpected) {
  const Outcome limit = run("nqueens 8 --solver sls --time-limit nan");
  EXPECT_EQ(limit.status, 2) << limit.output;
  EXPECT_TRUE(contains(limit.output, "--time-limit")) << limit.output;
  const Outcome option = run("nqueens 8 --solver sls --set walk_probability=nan");
  EXPECT_EQ(option.status, 2) << option.output;
  EXPECT_TRUE(contains(option.output, "walk_probability")) << option.output;
  const TempFile bad("nan.yaml",
                     "name: nan\nvariables:\n  - {name: x, int: [0, 3]}\nconstraints:\n"
                     "  - {kind: linear, scope: [x], coefficients: [1], op: '<=', rhs: .nan}\n");
  const Outcome file = run("solve '" + bad.path() + "' --solver grid");
  EXPECT_EQ(file.status, 2) << file.output;
  EXPECT_TRUE(contains(file.output, bad.path() + ":5")) << file.output;
}

TEST(SightlineCli, RefusesASettingWithoutAnEqualsSign) {
  const Outcome r = run("nqueens 8 --solver sls --set restarts");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "key=value")) << r.output;
}

TEST(SightlineCli, RefusesANegativeSeedOrLimitInsteadOfWrappingIt) {
  for (const char* option : {"--seed -1", "--max-evaluations -5", "--seed 18446744073709551616"}) {
    const Outcome r = run(std::string("nqueens 8 --solver sls ") + option);
    EXPECT_EQ(r.status, 2) << option << ": " << r.output;
    EXPECT_TRUE(contains(r.output, "sightline: --")) << r.output;
  }
}

TEST(SightlineCli, TakesOneValuePerSetSoTheFileMayFollow) {
  const Outcome r =
      run("solve --set max_points=1000 '" + example("australia.yaml") + "' --solver grid");
  // australia.yaml is a graph, not a problem file: the error must name it, which shows it
  // reached the file argument rather than being swallowed by --set.
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(contains(r.output, "australia.yaml")) << r.output;
  const Outcome ok = run("solve --set max_points=1000000 '" + example("myciel3.col") +
                         "' --colours 3 --solver grid");
  EXPECT_EQ(ok.status, 0) << ok.output;
}

TEST(SightlineCli, ExplainsUsageErrors) {
  EXPECT_EQ(run("").status, 2);
  EXPECT_EQ(run("no-such-command").status, 2);
  EXPECT_EQ(run("nqueens").status, 2);
  EXPECT_EQ(run("nqueens 0 --solver sls").status, 2);
  EXPECT_EQ(run("--help").status, 0);
}

// Restricted to three solvers so the test's duration does not depend on every solver's.
TEST(SightlineCli, CompareRunsTheChosenSolversOnEveryProblem) {
  // sls is anytime: it runs the whole limit on myciel3 with 3 colours and shelf.yaml, whose
  // optima are above zero, so the limit is short.
  const Outcome r = run("compare --time-limit 1 --solvers grid,sls,sliding-octree");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* part : {"1000-queens", "australia, 3 colours", "myciel3, 3 colours", "| grid",
                           "| sls", "| sliding-octree", "skipped"}) {
    EXPECT_TRUE(contains(r.output, part)) << part << " missing from:\n" << r.output;
  }
  EXPECT_FALSE(contains(r.output, "MISMATCH")) << r.output;
  const Outcome bad = run("compare --solvers grid,no-such-solver");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_TRUE(contains(bad.output, "unknown solver 'no-such-solver'")) << bad.output;
}

// `follow` (a contract in /work/shared/FORMATS.md): the trace starts with the shared columns,
// in order, and has one row per frame with a number in every field; the summary names the
// frames and the visibility.
std::string scene(const std::string& name) {
  return std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/" + name + ".yaml";
}

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

TEST(SightlineCli, FollowWritesTheSharedTraceFormatOneRowPerFrame) {
  const TempFile trace("follow.csv", "");
  const Outcome r = run("follow '" + scene("crammed-doorway") +
                        "' --solver occlusion-octree --trace '" + trace.path() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "765 frames")) << r.output;
  EXPECT_TRUE(contains(r.output, "visible")) << r.output;
  const auto rows = read_csv(trace.path());
  ASSERT_EQ(rows.size(), 766u);  // header + 765 frames
  const std::vector<std::string> shared = {"frame",    "t",        "char_x", "char_y", "char_z",
                                           "char_yaw", "cam_x",    "cam_y",  "cam_z",  "target_x",
                                           "target_y", "target_z", "cut",    "cost",   "solve_us"};
  ASSERT_GE(rows[0].size(), shared.size());
  for (std::size_t i = 0; i < shared.size(); ++i) EXPECT_EQ(rows[0][i], shared[i]) << i;
  for (std::size_t f = 1; f < rows.size(); ++f) {
    ASSERT_EQ(rows[f].size(), rows[0].size()) << "row " << f;
    EXPECT_EQ(rows[f][0], std::to_string(f - 1));
    EXPECT_TRUE(rows[f][12] == "0" || rows[f][12] == "1") << rows[f][12];
    for (std::size_t c = 0; c < rows[f].size(); ++c) {
      const std::string& cell = rows[f][c];
      if (rows[0][c] == "cut_reason") {  // the one word column (FORMATS allows more columns)
        EXPECT_TRUE(cell == "none" || rows[f][12] == "1") << "row " << f << ": " << cell;
        continue;
      }
      std::size_t used = 0;
      EXPECT_NO_THROW((void)std::stod(cell, &used)) << "row " << f << ": " << cell;
      EXPECT_EQ(used, cell.size()) << "row " << f << ": " << cell;
    }
  }
}

TEST(SightlineCli, FollowSmoothingStagesChangeThePathAndBadCountsAreRefused) {
  const TempFile one("one.csv", ""), two("two.csv", "");
  const std::string base = "follow '" + scene("into-corner") + "' --solver occlusion-octree";
  ASSERT_EQ(run(base + " --trace '" + one.path() + "'").status, 0);
  ASSERT_EQ(run(base + " --smoothing-stages 2 --trace '" + two.path() + "'").status, 0);
  const auto a = read_csv(one.path()), b = read_csv(two.path());
  ASSERT_EQ(a.size(), b.size());
  std::size_t differing = 0;
  for (std::size_t f = 1; f < a.size(); ++f) differing += a[f][6] != b[f][6];  // cam_x
  EXPECT_GT(differing, a.size() / 2);
  for (const char* bad : {"0", "5", "x"}) {
    const Outcome r = run(base + " --smoothing-stages " + bad);
    EXPECT_EQ(r.status, 2) << bad << ": " << r.output;
    EXPECT_TRUE(contains(r.output, "smoothing-stages")) << r.output;
  }
}

TEST(SightlineCli, FollowNamesAMissingSceneAndListsTheSolversForAnUnknownOne) {
  const Outcome missing = run("follow /no/such/scene.yaml --solver occlusion-octree");
  EXPECT_EQ(missing.status, 2) << missing.output;
  EXPECT_TRUE(contains(missing.output, "/no/such/scene.yaml")) << missing.output;
  const Outcome unknown = run("follow '" + scene("crammed-doorway") + "' --solver nope");
  EXPECT_EQ(unknown.status, 2) << unknown.output;
  for (const char* name : {"nope", "occlusion-octree", "bourne-octree"}) {
    EXPECT_TRUE(contains(unknown.output, name)) << unknown.output;
  }
}

}  // namespace

namespace sightline::apps {
namespace {

// FORMATS.md "The follow command": --solver is optional; without it the recommended camera
// solver films the scene, the same run as naming it.
TEST(SightlineCli, FollowWithoutASolverUsesTheRecommendedOne) {
  const TempFile named("named.csv", ""), implicit("implicit.csv", "");
  const std::string base = "follow '" + scene("into-corner") + "'";
  ASSERT_EQ(run(base + " --solver occlusion-octree --trace '" + named.path() + "'").status, 0);
  const Outcome r = run(base + " --trace '" + implicit.path() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "occlusion-octree")) << r.output;
  const auto a = read_csv(named.path()), b = read_csv(implicit.path());
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t f = 1; f < a.size(); ++f) EXPECT_EQ(a[f][6], b[f][6]) << "frame " << f;
}

}  // namespace
}  // namespace sightline::apps

namespace {

// --format json: one JSON object each, parsed by Python's json module here (the format a
// researcher's tools read), with the assignment by variable name and labels.
std::string json_field(const std::string& json, const std::string& expression) {
  TempFile file("out.json", json);
  const std::string command = "python3 -c \"import json,sys; d=json.load(open(sys.argv[1])); print(" +
                              expression + ")\" " + file.path() + " 2>&1";
  std::string output;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    EXPECT_EQ(::pclose(pipe), 0) << output << "\n" << json;
  }
  return output.substr(0, output.find_last_not_of('\n') + 1);
}

// The costliest-constraints table and --format json name a constraint the same way: its
// label (with its scope when one label covers several scopes), else its kind over its
// variables' names, never by variable ids.
TEST(SightlineCli, TextAndJsonNameViolatedConstraintsByTheirVariablesNames) {
  const TempFile file("names.yaml", R"(name: names
variables:
  - {name: r, count: 6, int: [0, 1]}
constraints:
  - {kind: not_equal, label: no clash, scopes: [[r0, r1], [r1, r2], [r0, r2]], weight: 3}
  - {kind: equals, scope: [r5], value: 1}
  - {kind: equals, scope: [r5], value: 0, weight: 2, label: r5 off}
)");
  const Outcome text = run("solve " + file.path() + " --solver bnb");
  ASSERT_EQ(text.status, 0) << text.output;
  EXPECT_TRUE(contains(text.output, "equals(r5)")) << text.output;
  EXPECT_TRUE(contains(text.output, "no clash(r")) << text.output;
  EXPECT_FALSE(contains(text.output, "x5")) << text.output;
  const Outcome json = run("solve " + file.path() + " --solver bnb --format json");
  ASSERT_EQ(json.status, 0) << json.output;
  const std::string names = json_field(json.output, "sorted(c['constraint'] for c in d['violated'])");
  EXPECT_TRUE(contains(names, "'equals(r5)'")) << names;
  const std::string clash =
      json_field(json.output, "[c['constraint'] for c in d['violated'] if c['constraint'].startswith('no clash')][0]");
  EXPECT_TRUE(contains(clash, "no clash(r")) << names;
  EXPECT_TRUE(contains(text.output, clash)) << clash << " in\n" << text.output;
}

TEST(SightlineCli, FormatJsonOnSolveFollowAndCompose) {
  const std::string problems = std::string(SIGHTLINE_SOURCE_DIR) + "/examples/problems/";
  Outcome o = run("solve " + problems + "australia.yaml --solver bnb --format json");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(json_field(o.output, "d['stop']"), "proven optimal");
  EXPECT_EQ(json_field(o.output, "d['feasible']"), "True");
  // Labelled values come back as their labels.
  const std::string wa = json_field(o.output, "d['assignment']['WA']");
  EXPECT_TRUE(wa == "red" || wa == "green" || wa == "blue") << wa;

  const std::string scene = std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/shots/walk-and-talk.yaml";
  o = run("follow " + scene + " --format json");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(json_field(o.output, "d['scene']"), "walk-and-talk");
  EXPECT_EQ(json_field(o.output, "sorted(d['shot']['shown_percent'])"), "['alice', 'bob']");
  EXPECT_EQ(json_field(o.output, "'unflagged_jumps' in d['metrics']"), "True");

  o = run("compose " + scene + " --format json");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(json_field(o.output, "len(d['position'])"), "3");
  EXPECT_EQ(json_field(o.output, "d['feasible']"), "True");

  o = run("compare --solvers sls,grid --time-limit 0.05 --format json");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(json_field(o.output, "sorted({r['solver'] for r in d})"), "['grid', 'sls']");
  EXPECT_EQ(json_field(o.output, "all(r['status'] in ('ok', 'skipped') for r in d)"), "True");
  EXPECT_EQ(json_field(o.output, "any('why' in r for r in d)"), "True");  // grid skips some
}

// compose --evaluate judges a pose file's pose on the shot: compose's own pose, read back,
// gets compose's verdict; another tool's infeasible pose exits 1 saying why; a malformed
// pose file exits 2 naming its line.
TEST(SightlineCli, ComposeEvaluatesAPoseFile) {
  const std::string scene =
      std::string(SIGHTLINE_SOURCE_DIR) + "/experiments/scenes/shots/walk-and-talk.yaml";
  const TempFile pose("compose_pose.json", "");
  Outcome o = run("compose " + scene + " --format json --pose " + pose.path());
  ASSERT_EQ(o.status, 0) << o.output;
  const std::string solved = json_field(o.output, "(d['satisfaction'], d['feasible'])");
  o = run("compose " + scene + " --format json --evaluate " + pose.path());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(json_field(o.output, "(d['satisfaction'], d['feasible'])"), solved);
  EXPECT_EQ(json_field(o.output, "d['solver']"), "evaluated");

  // Far outside the shot's region (a pose another tool might write): infeasible, exit 1.
  const TempFile far("far_pose.json",
                     "{\"position\": [500, 2, 500], \"look_at\": [0, 1.5, 0], \"roll\": 0, "
                     "\"fov\": 50, \"aspect\": 1.7778, \"by\": \"another tool\"}");
  o = run("compose " + scene + " --evaluate " + far.path());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_TRUE(contains(o.output, "the pose is infeasible")) << o.output;
  EXPECT_TRUE(contains(o.output, "aspect 1.7778 replaced by the shot's")) << o.output;

  const TempFile bad("bad_pose.json", "{\n\"position\": [0, 2],\n\"look_at\": [0, 1.5, 0]}");
  o = run("compose " + scene + " --evaluate " + bad.path());
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_TRUE(contains(o.output, bad.path() + ":2:")) << o.output;
  EXPECT_TRUE(contains(o.output, "expected a point [x, y, z]")) << o.output;
  o = run("compose " + scene + " --evaluate " + bad.path() + " --solver grid");
  EXPECT_EQ(o.status, 2) << o.output;
}

}  // namespace

namespace {

TEST(SightlineCli, ConvertsAModelOfAnyKindsToWcspCfnAndYamlThatReadBackWithTheSameOptimum) {
  const std::string problems = std::string(SIGHTLINE_SOURCE_DIR) + "/examples/problems/";
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("sightline_convert_" + std::to_string(::getpid()) + ".wcsp")).string();
  Outcome o = run("convert " + problems + "seating.yaml --to wcsp --out " + out);
  ASSERT_EQ(o.status, 0) << o.output;
  const Outcome original = run("solve " + problems + "seating.yaml --solver bnb --format json");
  const Outcome converted = run("solve " + out + " --solver bnb --format json");
  ASSERT_EQ(converted.status, 0) << converted.output;
  EXPECT_EQ(json_field(original.output, "d['cost']"), json_field(converted.output, "d['cost']"));
  std::filesystem::remove(out);
  // Through .cfn and a problem file too: the same optimum.
  for (const char* to : {"cfn", "yaml"}) {
    const std::string file = out + "." + to;
    o = run("convert " + problems + "seating.yaml --to " + to + " --out " + file);
    ASSERT_EQ(o.status, 0) << o.output;
    const Outcome back = run("solve " + file + " --solver bnb --format json");
    ASSERT_EQ(back.status, 0) << back.output;
    EXPECT_EQ(json_field(original.output, "d['cost']"), json_field(back.output, "d['cost']")) << to;
    std::filesystem::remove(file);
  }
  o = run("convert " + problems + "seating.yaml --to xml");
  EXPECT_EQ(o.status, 2);
  EXPECT_TRUE(contains(o.output, "xml")) << o.output;
  o = run("convert " + problems + "shelf.yaml --to wcsp");  // continuous
  EXPECT_EQ(o.status, 2);
  EXPECT_TRUE(contains(o.output, "not discrete")) << o.output;
}

}  // namespace
