#include "sightline/csp/files/wcsp_reader.h"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <numeric>
#include <sstream>
#include <string_view>

#include "sightline/csp/files/compressed_text.h"
#include "sightline/csp/input_error.h"
#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/table.h"

namespace sightline::csp {
namespace {

// Costs above 2^53 would not be exact as doubles.
constexpr std::int64_t kMaxExactCost = std::int64_t{1} << 53;

struct Token {
  std::string_view text;
  int line = 0;
  int column = 0;
};

// Whitespace-separated tokens with their line and column. `context` (for example "in cost
// function 3, which starts at line 40") is added to end-of-file errors, which have no token
// to point at.
class Scanner {
 public:
  Scanner(std::string text, std::string origin)
      : text_(std::move(text)), origin_(std::move(origin)) {}

  bool at_end() {
    skip_space();
    return pos_ >= text_.size();
  }
  Token next(const std::string& what) {
    if (at_end()) {
      // At the last line that holds anything, not past the final newline.
      throw InputError({origin_, last_line_, 0},
                       "unexpected end of file: expected " + what +
                           (context_.empty() ? "" : " (" + context_ + ")"));
    }
    Token t;
    t.line = line_;
    t.column = static_cast<int>(pos_ - line_start_) + 1;
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    t.text = std::string_view(text_).substr(begin, pos_ - begin);
    last_line_ = line_;
    return t;
  }
  // An integer token; `what` says what it is for the error message.
  std::int64_t integer(const std::string& what, Token* token_out = nullptr) {
    const Token t = next(what);
    if (token_out) *token_out = t;
    return to_integer(t, what);
  }
  std::int64_t to_integer(const Token& t, const std::string& what) const {
    std::int64_t value = 0;
    const char* first = t.text.data();
    const char* last = first + t.text.size();
    if (*first == '+') ++first;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last) {
      fail(t, "expected " + what + " (an integer), got '" + std::string(t.text) + "'");
    }
    return value;
  }
  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    throw InputError({origin_, t.line, t.column}, message);
  }
  SourceLocation where(const Token& t) const { return {origin_, t.line, t.column}; }
  void set_context(std::string context) { context_ = std::move(context); }
  const std::string& origin() const { return origin_; }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
  }
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') {
        ++line_;
        line_start_ = pos_ + 1;
      }
      ++pos_;
    }
  }

  std::string text_;
  std::string origin_;
  std::string context_;
  std::size_t pos_ = 0;
  std::size_t line_start_ = 0;
  int line_ = 1;
  int last_line_ = 1;  // line of the last token read
};

// A cost function in extension as the file gives it: value indices and integer costs.
struct CostTable {
  std::vector<VariableId> scope;
  std::int64_t default_cost = 0;
  std::vector<std::int64_t> tuples;  // value indices, arity per tuple
  std::vector<std::int64_t> costs;
  std::vector<Token> tuple_tokens;  // first token of each tuple, for error messages
};

struct SharedTable {
  std::vector<std::int64_t> domain_sizes;  // of the defining scope
  CostTable table;
  int line = 0;
};

class WcspReader {
 public:
  WcspReader(Scanner& scanner) : s_(scanner) {}

  std::unique_ptr<Problem> read() {
    const Token name = s_.next("the problem name");
    problem_ = std::make_unique<Problem>(std::string(name.text));
    Token t;
    const std::int64_t num_vars = s_.integer("the number of variables", &t);
    if (num_vars < 0)
      s_.fail(t, "the number of variables must be >= 0, got " + std::to_string(num_vars));
    const std::int64_t max_domain = s_.integer("the maximum domain size", &t);
    if (max_domain < 0)
      s_.fail(t, "the maximum domain size must be >= 0, got " + std::to_string(max_domain));
    const std::int64_t num_functions = s_.integer("the number of cost functions", &t);
    if (num_functions < 0) {
      s_.fail(t, "the number of cost functions must be >= 0, got " + std::to_string(num_functions));
    }
    ub_ = s_.integer("the upper bound (a positive integer)", &t);
    if (ub_ <= 0)
      s_.fail(t, "the upper bound must be a positive integer, got " + std::to_string(ub_));

    s_.set_context("reading the " + std::to_string(num_vars) + " domain sizes");
    for (std::int64_t i = 0; i < num_vars; ++i) {
      const std::int64_t d = s_.integer("the domain size of variable " + std::to_string(i), &t);
      if (d < 0) {
        s_.fail(t, "not supported: interval domain (negative domain size " + std::to_string(d) +
                       " for variable " + std::to_string(i) + ")");
      }
      if (d == 0) s_.fail(t, "variable " + std::to_string(i) + " has an empty domain (size 0)");
      if (d > max_domain) {
        s_.fail(t, "domain size " + std::to_string(d) + " of variable " + std::to_string(i) +
                       " exceeds the maximum domain size " + std::to_string(max_domain) +
                       " given in the header");
      }
      if (d > (std::int64_t{1} << 31)) s_.fail(t, "not supported: domain size above 2^31");
      domain_sizes_.push_back(d);
      problem_->add_variable("x" + std::to_string(i), Domain::integer_range(0, d - 1));
    }
    for (std::int64_t k = 0; k < num_functions; ++k) read_function(k, num_functions);
    s_.set_context("");
    if (!s_.at_end()) {
      const Token extra = s_.next("");
      s_.fail(extra, "unexpected '" + std::string(extra.text) + "' after the last of the " +
                         std::to_string(num_functions) + " cost functions the header announces");
    }
    return std::move(problem_);
  }

 private:
  void read_function(std::int64_t k, std::int64_t num_functions) {
    Token start;
    s_.set_context("cost function " + std::to_string(k) + " of " + std::to_string(num_functions));
    std::int64_t arity = s_.integer("the arity of cost function " + std::to_string(k), &start);
    s_.set_context("in cost function " + std::to_string(k) + " of " +
                   std::to_string(num_functions) + ", which starts at line " +
                   std::to_string(start.line));
    const bool defines_shared = arity < 0;
    arity = std::abs(arity);
    if (arity > static_cast<std::int64_t>(domain_sizes_.size())) {
      s_.fail(start, "cost function " + std::to_string(k) + " has arity " + std::to_string(arity) +
                         " but the problem has only " + std::to_string(domain_sizes_.size()) +
                         " variables");
    }
    CostTable table;
    for (std::int64_t i = 0; i < arity; ++i) {
      Token v;
      const std::int64_t var =
          s_.integer("variable index " + std::to_string(i) + " of the scope", &v);
      if (var < 0 || var >= static_cast<std::int64_t>(domain_sizes_.size())) {
        s_.fail(v, "variable index " + std::to_string(var) + " is out of range (the problem has " +
                       std::to_string(domain_sizes_.size()) + " variables, 0.." +
                       std::to_string(domain_sizes_.size() - 1) + ")");
      }
      if (std::find(table.scope.begin(), table.scope.end(), static_cast<VariableId>(var)) !=
          table.scope.end()) {
        s_.fail(v, "variable " + std::to_string(var) + " appears twice in the scope");
      }
      table.scope.push_back(static_cast<VariableId>(var));
    }
    Token default_token;
    table.default_cost = s_.integer("the default cost", &default_token);
    if (table.default_cost == -1) {
      if (defines_shared)
        s_.fail(start, "a global cost function cannot be shared (negative arity)");
      read_global(k, table.scope);
      return;
    }
    check_cost(default_token, table.default_cost, "the default cost");
    Token count_token;
    const std::int64_t num_tuples = s_.integer("the number of tuples", &count_token);
    if (num_tuples < 0) {
      if (defines_shared) s_.fail(count_token, "a shared cost function must list its tuples");
      reuse_shared(count_token, -num_tuples, table);
    } else {
      read_tuples(num_tuples, table);
    }
    if (defines_shared) {
      SharedTable shared;
      for (VariableId v : table.scope) shared.domain_sizes.push_back(domain_sizes_[v]);
      shared.table = table;
      shared.line = start.line;
      shared_.push_back(std::move(shared));
    }
    add_table(k, start, table);
  }

  void read_tuples(std::int64_t num_tuples, CostTable& table) {
    const std::size_t arity = table.scope.size();
    if (arity == 0 && num_tuples > 1) {
      s_.fail(s_.next("a cost"), "a constant (arity 0) cost function has at most one tuple");
    }
    const auto reserve = static_cast<std::size_t>(std::min<std::int64_t>(num_tuples, 1 << 20));
    table.tuples.reserve(reserve * arity);
    table.costs.reserve(reserve);
    for (std::int64_t t = 0; t < num_tuples; ++t) {
      const std::string which = "tuple " + std::to_string(t) + " of " + std::to_string(num_tuples);
      Token first;
      for (std::size_t p = 0; p < arity; ++p) {
        Token v;
        const std::int64_t index =
            s_.integer("value index " + std::to_string(p) + " of " + which, &v);
        if (p == 0) first = v;
        const std::int64_t d = domain_sizes_[table.scope[p]];
        if (index < 0 || index >= d) {
          s_.fail(v, "value index " + std::to_string(index) + " is out of range for variable " +
                         std::to_string(table.scope[p]) + ", whose domain has " +
                         std::to_string(d) + " values (0.." + std::to_string(d - 1) + ")");
        }
        table.tuples.push_back(index);
      }
      Token c;
      const std::int64_t cost = s_.integer("the cost of " + which, &c);
      if (arity == 0) first = c;
      check_cost(c, cost, "a cost");
      table.costs.push_back(cost);
      table.tuple_tokens.push_back(first);
    }
    check_duplicates(table);
  }

  void check_cost(const Token& t, std::int64_t cost, const std::string& what) const {
    if (cost < 0) s_.fail(t, what + " must be >= 0, got " + std::to_string(cost));
    if (cost < ub_ && cost > kMaxExactCost) {
      s_.fail(t, "not supported: cost " + std::to_string(cost) +
                     " below the upper bound but above 2^53 (not exact as a double)");
    }
  }

  // Tuples listed twice would make the cost ambiguous: sort them and compare neighbours.
  void check_duplicates(const CostTable& table) const {
    const std::size_t arity = table.scope.size();
    const std::size_t n = table.costs.size();
    if (arity == 0 || n < 2) return;
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    auto tuple = [&](std::size_t i) {
      return std::span<const std::int64_t>(table.tuples).subspan(i * arity, arity);
    };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const auto ta = tuple(a), tb = tuple(b);
      return std::lexicographical_compare(ta.begin(), ta.end(), tb.begin(), tb.end());
    });
    for (std::size_t i = 1; i < n; ++i) {
      const auto ta = tuple(order[i - 1]), tb = tuple(order[i]);
      if (std::equal(ta.begin(), ta.end(), tb.begin())) {
        std::string values;
        for (std::int64_t v : tb) values += (values.empty() ? "" : " ") + std::to_string(v);
        s_.fail(table.tuple_tokens[order[i]],
                "tuple (" + values + ") is listed twice (first at line " +
                    std::to_string(table.tuple_tokens[order[i - 1]].line) + ")");
      }
    }
  }

  // toulbar2 keeps the shared function's own table, default included (checked against
  // toulbar2 1.1.1's solution counts), so the reusing line's default is not used.
  void reuse_shared(const Token& t, std::int64_t occurrence, CostTable& table) const {
    if (occurrence > static_cast<std::int64_t>(shared_.size())) {
      s_.fail(t, "shared cost function " + std::to_string(occurrence) + " is used but only " +
                     std::to_string(shared_.size()) + " have been defined (by a negative arity)");
    }
    const SharedTable& shared = shared_[occurrence - 1];
    if (shared.domain_sizes.size() != table.scope.size()) {
      s_.fail(t, "shared cost function " + std::to_string(occurrence) + " (line " +
                     std::to_string(shared.line) + ") has arity " +
                     std::to_string(shared.domain_sizes.size()) + ", this scope has " +
                     std::to_string(table.scope.size()) + " variables");
    }
    for (std::size_t p = 0; p < table.scope.size(); ++p) {
      if (domain_sizes_[table.scope[p]] != shared.domain_sizes[p]) {
        s_.fail(t, "shared cost function " + std::to_string(occurrence) + " (line " +
                       std::to_string(shared.line) + ") expects a domain of size " +
                       std::to_string(shared.domain_sizes[p]) + " at scope position " +
                       std::to_string(p) + ", variable " + std::to_string(table.scope[p]) +
                       " has " + std::to_string(domain_sizes_[table.scope[p]]));
      }
    }
    std::vector<VariableId> scope = std::move(table.scope);
    table = shared.table;
    table.scope = std::move(scope);
  }

  void read_global(std::int64_t k, const std::vector<VariableId>& scope) {
    const Token keyword = s_.next("a global cost function keyword");
    if (keyword.text != "salldiff") {
      s_.fail(keyword, "not supported: " + std::string(keyword.text) +
                           " (the only global cost function read is salldiff)");
    }
    const Token semantics = s_.next("the salldiff semantics (var or dec)");
    const auto measure = AllDifferent::parse_measure(semantics.text);
    if (!measure) {
      if (semantics.text == "decbi") s_.fail(semantics, "not supported: salldiff decbi");
      s_.fail(semantics, "expected the salldiff semantics var or dec, got '" +
                             std::string(semantics.text) + "'");
    }
    Token cost_token;
    const std::int64_t cost = s_.integer("the salldiff cost per violation", &cost_token);
    check_cost(cost_token, cost, "the salldiff cost");
    if (scope.size() < 2) s_.fail(keyword, "salldiff needs at least 2 variables");
    if (cost == 0) return;  // never costs anything
    const bool hard = cost >= ub_;
    auto c = std::make_unique<AllDifferent>(scope, std::vector<double>{}, *measure,
                                            hard ? 1.0 : static_cast<double>(cost), hard,
                                            key_range_from_domains(*problem_, scope, {}));
    c->set_label("f" + std::to_string(k) + (hard ? "/hard" : ""));
    problem_->add_constraint(std::move(c));
  }

  // Adds the table as a hard part (forbidden tuples) and a soft part (the other costs).
  void add_table(std::int64_t k, const Token& start, const CostTable& table) {
    const std::string label = "f" + std::to_string(k);
    if (table.scope.empty()) {
      // A constant: its own tuple (if any) overrides the default.
      const std::int64_t c = table.costs.empty() ? table.default_cost : table.costs[0];
      if (c == 0) return;
      if (problem_->num_variables() == 0) {
        s_.fail(start, "not supported: a constant cost in a problem without variables");
      }
      const bool forbidden = c >= ub_;
      auto t = std::make_unique<Table>(std::vector<VariableId>{0}, std::vector<Table::Entry>{},
                                       forbidden ? 1.0 : static_cast<double>(c), 1.0, forbidden);
      t->set_label(label + (forbidden ? "/hard" : "") + " (constant)");
      problem_->add_constraint(std::move(t));
      return;
    }
    const std::size_t arity = table.scope.size();
    const std::size_t n = table.costs.size();
    auto forbidden = [&](std::int64_t c) { return c >= ub_; };
    const bool default_forbidden = forbidden(table.default_cost);
    const bool any_forbidden =
        default_forbidden || std::any_of(table.costs.begin(), table.costs.end(), forbidden);

    std::vector<double> values;
    std::vector<double> costs;
    auto push_tuple = [&](std::size_t i, double cost) {
      for (std::size_t p = 0; p < arity; ++p) {
        values.push_back(static_cast<double>(table.tuples[i * arity + p]));
      }
      costs.push_back(cost);
    };
    if (any_forbidden) {
      // Hard part: violation 1 on forbidden tuples; only the tuples whose status differs
      // from the default's are listed.
      for (std::size_t i = 0; i < n; ++i) {
        if (forbidden(table.costs[i]) != default_forbidden) {
          push_tuple(i, default_forbidden ? 0.0 : 1.0);
        }
      }
      auto t = make_table(start, table.scope, values, costs, default_forbidden ? 1.0 : 0.0, true);
      t->set_label(label + "/hard");
      problem_->add_constraint(std::move(t));
    }
    // Soft part over the allowed tuples. When the default is forbidden, the tuples it covers
    // never occur in a feasible assignment, so the soft default may be anything: the
    // cheapest allowed cost keeps the table small and bnb's bounds tight.
    double soft_default = static_cast<double>(table.default_cost);
    if (default_forbidden) {
      std::int64_t cheapest = -1;
      for (std::int64_t c : table.costs) {
        if (!forbidden(c) && (cheapest < 0 || c < cheapest)) cheapest = c;
      }
      soft_default = cheapest < 0 ? 0.0 : static_cast<double>(cheapest);
    }
    values.clear();
    costs.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (!forbidden(table.costs[i]) && static_cast<double>(table.costs[i]) != soft_default) {
        push_tuple(i, static_cast<double>(table.costs[i]));
      }
    }
    if (soft_default == 0 && costs.empty()) return;
    auto t = make_table(start, table.scope, values, costs, soft_default, false);
    t->set_label(label);
    problem_->add_constraint(std::move(t));
  }

  std::unique_ptr<Table> make_table(const Token& start, const std::vector<VariableId>& scope,
                                    const std::vector<double>& values,
                                    const std::vector<double>& costs, double default_cost,
                                    bool hard) const {
    try {
      return std::make_unique<Table>(scope, values, costs, default_cost, 1.0, hard);
    } catch (const TableError& e) {
      s_.fail(start, e.what());
    }
  }

  Scanner& s_;
  std::unique_ptr<Problem> problem_;
  std::int64_t ub_ = 0;
  std::vector<std::int64_t> domain_sizes_;
  std::vector<SharedTable> shared_;
};

std::unique_ptr<Problem> parse_text(std::string text, const std::string& origin) {
  Scanner scanner(std::move(text), origin);
  return WcspReader(scanner).read();
}

}  // namespace

std::unique_ptr<Problem> parse_wcsp(std::istream& in, const std::string& origin) {
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_text(std::move(text), origin);
}

std::unique_ptr<Problem> read_wcsp_file(const std::string& path) {
  return parse_text(read_possibly_compressed_file(path), path);
}

}  // namespace sightline::csp
