#include "apps/text_table.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace sightline::apps {

TextTable& TextTable::column(std::string header, Align align) {
  headers_.push_back(std::move(header));
  aligns_.push_back(align);
  return *this;
}

void TextTable::add_row(std::vector<std::string> cells) {
  if (cells.size() != headers_.size()) {
    throw std::invalid_argument("table row has " + std::to_string(cells.size()) + " cells for " +
                                std::to_string(headers_.size()) + " columns");
  }
  rows_.push_back(std::move(cells));
}

void TextTable::print(std::ostream& out) const {
  std::vector<std::size_t> widths(headers_.size());
  for (std::size_t c = 0; c < headers_.size(); ++c) {
    widths[c] = std::max<std::size_t>(3, headers_[c].size());
    for (const auto& row : rows_) widths[c] = std::max(widths[c], row[c].size());
  }
  const auto print_row = [&](const std::vector<std::string>& cells) {
    out << '|';
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string pad(widths[c] - cells[c].size(), ' ');
      out << ' ' << (aligns_[c] == Align::kRight ? pad + cells[c] : cells[c] + pad) << " |";
    }
    out << '\n';
  };
  print_row(headers_);
  out << '|';
  for (std::size_t c = 0; c < headers_.size(); ++c) {
    out << std::string(widths[c] + 1, '-') << (aligns_[c] == Align::kRight ? ":|" : "-|");
  }
  out << '\n';
  for (const auto& row : rows_) print_row(row);
}

std::string format_number(double value, int significant) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

std::string count_of(std::size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string format_seconds(double seconds) {
  if (seconds < 1e-3) return format_number(seconds * 1e6, 3) + " us";
  if (seconds < 1) return format_number(seconds * 1e3, 3) + " ms";
  return format_number(seconds, 3) + " s";
}

}  // namespace sightline::apps
