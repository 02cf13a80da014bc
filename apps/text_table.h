// TextTable: a Markdown-style table with aligned columns, for the command line's reports.
//
//   | problem   | solver | cost |
//   |-----------|--------|-----:|
//   | 8-queens  | sls    |    0 |
//
// Readable in a terminal as it is, and pasteable into Markdown documents unchanged. Numbers
// are right-aligned (columns declared kRight), text left-aligned.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace sightline::apps {

class TextTable {
 public:
  enum class Align { kLeft, kRight };

  TextTable& column(std::string header, Align align = Align::kLeft);
  // Adds a row; it must have one cell per column (std::invalid_argument otherwise).
  void add_row(std::vector<std::string> cells);
  std::size_t num_rows() const { return rows_.size(); }
  void print(std::ostream& out) const;

 private:
  std::vector<std::string> headers_;
  std::vector<Align> aligns_;
  std::vector<std::vector<std::string>> rows_;
};

// Number formatting shared by the commands: up to `significant` digits, no trailing zeros
// ("0", "12.5", "0.000123").
std::string format_number(double value, int significant = 6);
// "1 conflict", "3 conflicts": a count with its noun, plural by adding 's'.
std::string count_of(std::size_t count, const std::string& noun);
// Seconds with a sensible unit for reading ("850 us", "12.3 ms", "1.52 s").
std::string format_seconds(double seconds);

}  // namespace sightline::apps
