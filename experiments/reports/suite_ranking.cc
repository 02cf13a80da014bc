#include "sightline/experiments/reports/suite_ranking.h"

#include "sightline/experiments/runs/output_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "sightline/experiments/reports/statistics.h"
#include "sightline/experiments/reports/time_profiles.h"
#include "sightline/experiments/suite/suite_comparisons.h"

namespace sightline::experiments {
namespace {

const double kInfinity = std::numeric_limits<double>::infinity();

bool contains(const std::vector<std::string>& labels, const std::string& label) {
  return std::find(labels.begin(), labels.end(), label) != labels.end();
}

std::string fixed(double v, int decimals) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}


struct MetricChoice {
  const char* name;
  bool higher_is_better;
  const char* words;  // for the summary
};

const std::vector<MetricChoice>& camera_metrics() {
  static const std::vector<MetricChoice> metrics = {
      {"visible_pct", true, "`visible_pct` (look-at point visible, % of frames; higher is better)"},
      {"cuts", false, "`cuts` (fewer is better)"},
      {"jerk_p99", false, "`jerk_p99` (m/s^3; lower is better)"}};
  return metrics;
}

const std::vector<MetricChoice>& problem_metrics() {
  static const std::vector<MetricChoice> metrics = {
      {"cost", false,
       "`cost` (of a feasible answer; infeasible, failed or skipped runs rank last)"},
      {"par2_s", false,
       "`par2_s` (time when solved within the time limit, else twice the limit, as in PAR-2)"}};
  return metrics;
}

// The family's subject of a result: the scene (with the profile when there are several), or
// the problem.
std::string subject_of(const Suite& suite, const RunResult& r) {
  if (r.kind == "camera" && suite.profiles.size() > 1) return r.subject + " / " + r.profile;
  return r.subject;
}

RankingTable make_table(const Suite& suite, const SuiteOutcome& outcome, const std::string& kind,
                        const MetricChoice& metric) {
  RankingTable t;
  t.kind = kind;
  t.metric = metric.name;
  t.higher_is_better = metric.higher_is_better;
  t.solvers = kind == "camera" ? camera_labels(suite) : problem_labels(suite);
  const std::vector<std::string> columns = metric_columns(suite);
  const double limit = kind == "toy" ? problem_time_limit(suite, outcome) : 0.0;
  std::map<std::pair<std::string, std::string>, std::vector<double>> losses;
  std::set<std::string> seen;  // subjects
  for (const RunResult& r : outcome.results) {
    if (r.kind != kind || !contains(t.solvers, r.solver)) continue;
    const std::string subject = subject_of(suite, r);
    if (seen.insert(subject).second) t.subjects.push_back(subject);
    double loss = kInfinity;
    if (t.metric == "par2_s") {
      const TimedRun timed = problem_timed_run(suite, outcome, columns, r);
      loss = timed.solved && timed.seconds <= limit ? timed.seconds : 2.0 * limit;
    } else if (r.status == "ok") {
      const double v = metric_value(columns, r, t.metric);
      const bool usable =
          std::isfinite(v) && (t.metric != "cost" || metric_value(columns, r, "feasible") == 1.0);
      if (usable) loss = t.higher_is_better ? -v : v;
    }
    losses[{subject, r.solver}].push_back(loss);
  }
  for (const std::string& subject : t.subjects) {
    std::vector<double>& row = t.loss.emplace_back();
    std::vector<char>& done = t.finished.emplace_back();
    for (const std::string& solver : t.solvers) {
      const auto it = losses.find({subject, solver});
      done.push_back(it != losses.end() ? 1 : 0);
      row.push_back(it != losses.end() ? median(it->second) : kInfinity);
    }
  }
  return t;
}

// Subjects where every solver has a finished run.
std::vector<std::size_t> complete_subjects(const RankingTable& t) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < t.subjects.size(); ++i)
    if (std::all_of(t.finished[i].begin(), t.finished[i].end(), [](char c) { return c != 0; }))
      out.push_back(i);
  return out;
}

struct PairOutcome {
  std::size_t subjects = 0;  // subjects where both have finished runs
  std::size_t a_better = 0, b_better = 0;
  WilcoxonResult test;
};

PairOutcome compare_pair(const RankingTable& t, const std::string& a, const std::string& b) {
  const std::size_t ia = static_cast<std::size_t>(std::find(t.solvers.begin(), t.solvers.end(), a) -
                                                  t.solvers.begin());
  const std::size_t ib = static_cast<std::size_t>(std::find(t.solvers.begin(), t.solvers.end(), b) -
                                                  t.solvers.begin());
  PairOutcome out;
  // Losses of B and of A: a positive difference B - A means A did better, so the test's W+
  // sums the ranks of the subjects where A is better. Equal losses (both worst included)
  // become a zero difference, which the test drops.
  std::vector<double> loss_b, loss_a;
  for (std::size_t s = 0; s < t.subjects.size(); ++s) {
    if (!t.finished[s][ia] || !t.finished[s][ib]) continue;
    ++out.subjects;
    const double la = t.loss[s][ia], lb = t.loss[s][ib];
    if (la == lb) {
      loss_a.push_back(0.0);
      loss_b.push_back(0.0);
      continue;
    }
    (la < lb ? out.a_better : out.b_better) += 1;
    loss_a.push_back(la);
    loss_b.push_back(lb);
  }
  out.test = wilcoxon_signed_rank(loss_b, loss_a);
  return out;
}

std::string direction(const PairOutcome& p, const std::string& a, const std::string& b) {
  if (p.test.n == 0) return "no difference";
  const std::string ahead = p.test.w_plus > p.test.w_minus   ? "`" + a + "` ahead"
                            : p.test.w_plus < p.test.w_minus ? "`" + b + "` ahead"
                                                             : "even";
  if (p.test.p_value < 0.05 && ahead != "even")
    return ahead.substr(0, ahead.size() - 6) + " better (p < 0.05)";
  return "not significant at 5% (" + ahead + ")";
}

// The comparisons that concern a family: both names among its solvers.
std::vector<const SuiteComparison*> comparisons_of(const Suite& suite, const RankingTable& t) {
  std::vector<const SuiteComparison*> out;
  for (const SuiteComparison& c : suite.comparisons)
    if (contains(t.solvers, c.a) && contains(t.solvers, c.b)) out.push_back(&c);
  return out;
}

}  // namespace


std::vector<RankingTable> ranking_tables(const Suite& suite, const SuiteOutcome& outcome) {
  std::vector<RankingTable> tables;
  bool camera = false, toy = false;
  for (const RunResult& r : outcome.results) (r.kind == "camera" ? camera : toy) = true;
  if (camera)
    for (const MetricChoice& m : camera_metrics())
      tables.push_back(make_table(suite, outcome, "camera", m));
  if (toy)
    for (const MetricChoice& m : problem_metrics())
      tables.push_back(make_table(suite, outcome, "toy", m));
  return tables;
}

std::string ranking_markdown(const Suite& suite, const SuiteOutcome& outcome) {
  const std::vector<RankingTable> tables = ranking_tables(suite, outcome);
  std::ostringstream out;
  for (const std::string kind : {"camera", "toy"}) {
    std::vector<const RankingTable*> family;
    for (const RankingTable& t : tables)
      if (t.kind == kind) family.push_back(&t);
    if (family.empty()) continue;
    const RankingTable& first = *family.front();
    const std::vector<std::size_t> complete = complete_subjects(first);
    const bool camera = kind == "camera";
    const std::string subjects_word =
        camera ? (suite.profiles.size() > 1 ? "scene x profile" : "scene") : "instance";

    if (first.solvers.size() >= 2 && complete.size() >= 2) {
      out << "### Ranking" << (camera ? " of camera solvers" : " of problem solvers") << "\n\n"
          << "Average ranks (1 = best) over " << complete.size() << " subjects (each "
          << subjects_word << ") by ";
      const auto& metrics = camera ? camera_metrics() : problem_metrics();
      for (std::size_t m = 0; m < metrics.size(); ++m)
        out << (m == 0 ? "" : m + 1 == metrics.size() ? " and " : ", ") << metrics[m].words;
      out << ". Repetitions over seeds are reduced to their median per subject and solver "
             "before ranking; ties share the average of their ranks; a failed, skipped or "
             "valueless run ranks last. Friedman's test (chi-square with k - 1 = "
          << first.solvers.size() - 1
          << " degrees of freedom, corrected for ties) asks whether the solvers differ at all.";
      if (complete.size() < first.subjects.size())
        out << " Left out (some solver has no finished run there yet): "
            << first.subjects.size() - complete.size() << " of " << first.subjects.size()
            << " subjects.";
      out << "\n\n| solver |";
      for (const RankingTable* t : family) out << ' ' << t->metric << " |";
      out << "\n| --- |";
      for (std::size_t i = 0; i < family.size(); ++i) out << " ---: |";
      out << '\n';
      std::vector<FriedmanResult> friedman;
      for (const RankingTable* t : family) {
        std::vector<std::vector<double>> rows;
        for (std::size_t s : complete) rows.push_back(t->loss[s]);
        friedman.push_back(friedman_test(rows));
      }
      for (std::size_t j = 0; j < first.solvers.size(); ++j) {
        out << "| " << first.solvers[j] << " |";
        for (const FriedmanResult& f : friedman) out << ' ' << fixed(f.average_ranks[j], 2) << " |";
        out << '\n';
      }
      out << "| Friedman chi-square |";
      for (const FriedmanResult& f : friedman) out << ' ' << statistic_text(f.chi_square) << " |";
      out << "\n| Friedman p |";
      for (const FriedmanResult& f : friedman) out << ' ' << statistic_text(f.p_value) << " |";
      out << "\n\n";
    }

    for (const SuiteComparison* c : comparisons_of(suite, first)) {
      out << "### Wilcoxon signed-rank test: `" << c->a << "` vs `" << c->b << "`\n\n"
          << "Paired by " << subjects_word
          << " on the medians over seeds (as in the ranking); subjects where the two are equal "
             "are dropped (n counts the others); two-sided p, exact for n <= 25, else the "
             "normal approximation. W("
          << c->a
          << " better) sums the ranks of |difference| "
             "over the subjects where `"
          << c->a << "` did better, W(" << c->b << " better) the others.\n\n"
          << "| metric | subjects | n | `" << c->a << "` better | `" << c->b << "` better | W("
          << c->a << " better) | W(" << c->b << " better) | p | direction |\n"
          << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
      for (const RankingTable* t : family) {
        const PairOutcome p = compare_pair(*t, c->a, c->b);
        out << "| " << t->metric << " | " << p.subjects << " | " << p.test.n << " | " << p.a_better
            << " | " << p.b_better << " | " << statistic_text(p.test.w_plus) << " | "
            << statistic_text(p.test.w_minus) << " | " << statistic_text(p.test.p_value)
            << (p.test.n > 0 ? (p.test.exact ? " (exact)" : " (normal)") : "") << " | "
            << direction(p, c->a, c->b) << " |\n";
      }
      out << '\n';
    }
  }
  return out.str();
}

std::string ranking_csv_rows(const Suite& suite, const SuiteOutcome& outcome) {
  std::ostringstream out;
  for (const RankingTable& t : ranking_tables(suite, outcome)) {
    const std::vector<std::size_t> complete = complete_subjects(t);
    const std::string tail = ",-," + t.metric + ',';
    if (t.solvers.size() >= 2 && complete.size() >= 2) {
      std::vector<std::vector<double>> rows;
      for (std::size_t s : complete) rows.push_back(t.loss[s]);
      const FriedmanResult f = friedman_test(rows);
      for (std::size_t j = 0; j < t.solvers.size(); ++j)
        out << t.kind << ",*," << csv_field(t.solvers[j]) << tail << "average_rank,"
            << statistic_text(f.average_ranks[j]) << '\n';
      out << t.kind << ",*,*" << tail << "friedman_chi_square," << statistic_text(f.chi_square)
          << '\n'
          << t.kind << ",*,*" << tail << "friedman_p," << statistic_text(f.p_value) << '\n'
          << t.kind << ",*,*" << tail << "friedman_subjects," << f.blocks << '\n';
    }
    for (const SuiteComparison* c : comparisons_of(suite, t)) {
      const PairOutcome p = compare_pair(t, c->a, c->b);
      const std::string head = t.kind + ",*," + csv_field(c->a + " vs " + c->b) + tail;
      out << head << "wilcoxon_n," << p.test.n << '\n'
          << head << "wilcoxon_w_a_better," << statistic_text(p.test.w_plus) << '\n'
          << head << "wilcoxon_w_b_better," << statistic_text(p.test.w_minus) << '\n'
          << head << "wilcoxon_p," << statistic_text(p.test.p_value) << '\n';
    }
  }
  return out.str();
}

}  // namespace sightline::experiments
