// Small pieces every writer of a suite's output folder shares: writing a file so that readers
// never see half of it, and the CSV and number text of results.csv, stats.csv and the
// statistics files (one spelling, so the files agree with each other).
#pragma once

#include <string>

namespace sightline::experiments {

// Writes `text` to path + ".tmp" and renames it over `path`, so a reader (another rank, a
// resumed suite) sees either the old file, no file, or the whole new one, never half of it.
// Throws std::runtime_error naming the file on failure.
void write_atomically(const std::string& path, const std::string& text);

// A CSV field: as is, or quoted (with doubled quotes) when it holds a comma, quote or newline.
std::string csv_field(const std::string& text);

// A statistic as text: printf's %.6g.
std::string statistic_text(double v);

}  // namespace sightline::experiments
