// Compound (pair) moves of tabu: every pair move's score change against re-scoring from
// scratch on random problems with hard binary constraints (duplex-like |x - y| = d pairs, a
// soft table on the same pair, a wider constraint on both, generic hard tables), and tabu
// with pair moves reaching bnb's proved optimum on random duplex-paired instances, where
// one-variable tabu with the same seeds and budget misses some.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sightline/csp/files/wcsp_reader.h"
#include "sightline/csp/kinds/table.h"
#include "sightline/solvers/detail/compound_moves.h"
#include "sightline/solvers/detail/move_table.h"
#include "sightline/solvers/registry.h"

namespace sightline::solvers {
namespace {

// Variables 2k and 2k + 1 are tied by a hard |x - y| = gap table (frequency assignment's
// duplex constraint); soft unary and binary tables with random costs on top; with `extras`,
// also a soft table on a tied pair, a soft ternary table over a tied pair and a third
// variable, and a generic hard binary table (a few forbidden tuples) between pairs.
std::unique_ptr<csp::Problem> duplex_problem(std::uint64_t seed, int pairs, int values,
                                             int soft_binaries, bool extras) {
  std::mt19937_64 rng(seed);
  auto cost = [&] { return static_cast<double>(rng() % 20); };
  auto p = std::make_unique<csp::Problem>("duplex");
  const int n = 2 * pairs;
  for (int v = 0; v < n; ++v) {
    p->add_variable("x" + std::to_string(v), csp::Domain::integer_range(0, values - 1));
  }
  using Entry = csp::Table::Entry;
  for (int k = 0; k < pairs; ++k) {
    const int gap = 1 + static_cast<int>(rng() % 2);
    std::vector<Entry> allowed;
    for (int a = 0; a < values; ++a) {
      for (int b = 0; b < values; ++b) {
        if (std::abs(a - b) == gap) allowed.push_back({{double(a), double(b)}, 0});
      }
    }
    const csp::VariableId x = 2 * k, y = 2 * k + 1;
    // Scope order alternates, so pairs are seen from both sides.
    p->add_constraint(std::make_unique<csp::Table>(
        k % 2 ? std::vector<csp::VariableId>{y, x} : std::vector<csp::VariableId>{x, y}, allowed,
        1.0, 1.0, true));
  }
  for (int v = 0; v < n; ++v) {
    std::vector<Entry> unary;
    for (int a = 0; a < values; ++a) unary.push_back({{double(a)}, cost()});
    p->add_constraint(std::make_unique<csp::Table>(std::vector<csp::VariableId>{csp::VariableId(v)},
                                                   unary, 0.0));
  }
  auto soft_binary = [&](csp::VariableId x, csp::VariableId y) {
    std::vector<Entry> entries;
    for (int a = 0; a < values; ++a) {
      for (int b = 0; b < values; ++b) {
        if (rng() % 3 == 0) entries.push_back({{double(a), double(b)}, cost()});
      }
    }
    p->add_constraint(std::make_unique<csp::Table>(std::vector<csp::VariableId>{x, y}, entries,
                                                   0.0, 1.0 + static_cast<double>(rng() % 3)));
  };
  for (int k = 0; k < soft_binaries; ++k) {
    const auto x = static_cast<csp::VariableId>(rng() % n);
    auto y = static_cast<csp::VariableId>(rng() % n);
    if (y == x) y = (x + 2) % n;
    soft_binary(x, y);
  }
  if (extras) {
    soft_binary(1, 0);  // on a tied pair: the pair's matrix sums it with the hard table
    std::vector<Entry> ternary;
    for (int a = 0; a < values; ++a) {
      for (int b = 0; b < values; ++b) {
        for (int c = 0; c < values; ++c) {
          if (rng() % 4 == 0) ternary.push_back({{double(a), double(b), double(c)}, cost()});
        }
      }
    }
    p->add_constraint(std::make_unique<csp::Table>(std::vector<csp::VariableId>{2, 4, 3},
                                                   ternary, 1.0));
    std::vector<Entry> forbidden = {{{0, 1}, 1}, {{1, 1}, 1}, {{2, 0}, 1}};
    p->add_constraint(std::make_unique<csp::Table>(std::vector<csp::VariableId>{1, 4}, forbidden,
                                                   0.0, 2.0, true));
  }
  return p;
}

TEST(CompoundMoves, EveryPairMoveScoresTheExactChangeOfBothVariables) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto p = duplex_problem(seed, 4, 5, 10, true);
    // Every pair, loose ones included (the generic table allows 22 of 25 value pairs).
    detail::CompoundMoves compound(*p, std::size_t{1} << 20, 1.0);
    ASSERT_EQ(compound.num_pairs(), 5u);  // four duplex pairs and the generic hard table
    // By default only the tight ones (duplex: at most 2 of 5 values per value).
    EXPECT_EQ(detail::CompoundMoves(*p).num_pairs(), 4u);
    detail::MoveTable table(*p);
    std::mt19937_64 rng(seed);
    csp::Assignment start(p->num_variables());
    for (double& x : start) x = static_cast<double>(rng() % 5);
    table.rebuild(start);
    for (int step = 0; step < 15; ++step) {
      csp::Assignment x = table.values();
      csp::Assignment scratch = x;
      const csp::Score here = p->score(x);
      for (csp::VariableId v = 0; v < p->num_variables(); ++v) {
        for (const auto& link : compound.links(v)) {
          const csp::VariableId u = compound.partner(link);
          for (std::uint32_t a = 0; a < 5; ++a) {
            for (std::uint32_t b = 0; b < 5; ++b) {
              csp::Assignment moved = x;
              moved[v] = a;
              moved[u] = b;
              const csp::Score truth = p->score(moved) - here;
              const csp::Score change = compound.change(table, v, link, a, b, scratch);
              ASSERT_NEAR(change.hard, truth.hard, 1e-9) << v << "=" << a << ", " << u << "=" << b;
              ASSERT_NEAR(change.soft, truth.soft, 1e-9) << v << "=" << a << ", " << u << "=" << b;
              ASSERT_EQ(scratch, x);  // restored
              // Supports are exactly the partner values that keep every hard pair table.
              bool hard_ok = true;
              for (csp::ConstraintId c = 0; c < p->num_constraints(); ++c) {
                const auto& con = p->constraint(c);
                const auto s = con.scope();
                if (con.is_hard() && s.size() == 2 && ((s[0] == v && s[1] == u) ||
                                                       (s[0] == u && s[1] == v))) {
                  hard_ok &= con.violation(moved) == 0;
                }
              }
              const auto sup = compound.supports(link, a);
              EXPECT_EQ(compound.allowed(link, a, b), hard_ok);
              EXPECT_EQ(std::find(sup.begin(), sup.end(), b) != sup.end(), hard_ok);
              // ... and self's conflicts with partner = b exactly the values that break them.
              const auto con = compound.conflicts(link, b);
              EXPECT_EQ(std::find(con.begin(), con.end(), a) != con.end(), !hard_ok);
            }
          }
        }
      }
      const auto v = static_cast<csp::VariableId>(rng() % p->num_variables());
      table.move(v, static_cast<std::uint32_t>(rng() % 5));
    }
  }
}

TEST(CompoundMoves, AProblemWithoutHardBinaryConstraintsHasNoPairs) {
  const auto p = duplex_problem(3, 0, 4, 0, false);
  EXPECT_EQ(detail::CompoundMoves(*p).num_pairs(), 0u);
}

SolverResult run_tabu(const csp::Problem& p, std::uint64_t seed, std::uint64_t moves,
                      bool compound, const std::string& stall = "300") {
  SolveContext context;
  context.seed = seed;
  context.limits.max_iterations = moves;
  context.want_breakdown = false;
  return SolverRegistry::global()
      .create("tabu", {{"compound_moves", compound ? "true" : "false"}, {"stall_moves", stall}})
      ->solve(p, p.default_assignment(), context);
}

// Every variable is in a duplex pair, so each one-variable move from a feasible assignment
// breaks a hard constraint; with pair moves, tabu reaches bnb's proved optimum on every
// instance within the budget; without them it misses some (the test would not tell the two
// apart otherwise).
TEST(CompoundMoves, TabuWithPairMovesReachesTheOptimaOneVariableTabuMisses) {
  auto bnb = SolverRegistry::global().create("bnb");
  int one_variable_misses = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto p = duplex_problem(100 + seed, 8, 8, 40, false);
    SolveContext context;
    context.want_breakdown = false;
    const SolverResult exact = bnb->solve(*p, p->default_assignment(), context);
    ASSERT_EQ(exact.stop, StopReason::kProvenOptimal) << exact.brief_report("bnb");
    const SolverResult pairs = run_tabu(*p, seed, 3000, true);
    EXPECT_TRUE(pairs.feasible()) << "seed " << seed;
    EXPECT_EQ(pairs.cost(), exact.cost()) << "seed " << seed << ": " << pairs.brief_report("tabu");
    const SolverResult single = run_tabu(*p, seed, 3000, false);
    if (!single.feasible() || single.cost() > exact.cost()) ++one_variable_misses;
  }
  EXPECT_GT(one_variable_misses, 0);
}

// warehouse.wcsp's hard binary constraints ("a store's warehouse is open") allow all value
// pairs but one: loose, so no pair moves, and the search is move for move the one-variable
// search (same seed, same budget, same result and work).
TEST(CompoundMoves, LooseHardPairsLeaveTheSearchAsItWas) {
  const auto p = csp::read_wcsp_file(std::string(SIGHTLINE_SHARED_DIR) + "/data/wcsp/warehouse.wcsp");
  EXPECT_EQ(detail::CompoundMoves(*p).num_pairs(), 0u);
  EXPECT_GT(detail::CompoundMoves(*p, std::size_t{1} << 21, 1.0).num_pairs(), 0u);
  const SolverResult with = run_tabu(*p, 4, 20000, true, "0");
  const SolverResult without = run_tabu(*p, 4, 20000, false, "0");
  EXPECT_EQ(with.best, without.best);
  EXPECT_EQ(with.evaluations, without.evaluations);
}

}  // namespace
}  // namespace sightline::solvers
