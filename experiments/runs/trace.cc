#include "sightline/experiments/runs/trace.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "sightline/csp/input_error.h"

namespace sightline::experiments {
namespace {

constexpr const char* kPublicColumns =
    "frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,target_x,target_y,target_z,cut,"
    "cost,solve_us";
constexpr const char* kExtraColumns =
    "visible,desired_height,desired_distance,desired_orientation";
constexpr const char* kCutReasonColumn = "cut_reason";

// One CSV cell: its text without surrounding blanks (and a Windows line end), and the
// 1-based character column where it starts, for messages.
struct Cell {
  std::string text;
  int column = 1;
};

std::vector<Cell> split_cells(const std::string& line) {
  std::vector<Cell> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t stop = comma == std::string::npos ? line.size() : comma;
    std::size_t a = start, b = stop;
    while (a < b && std::isspace(static_cast<unsigned char>(line[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(line[b - 1]))) --b;
    cells.push_back({line.substr(a, b - a), static_cast<int>(a + 1)});
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

std::vector<std::string> split_line(const std::string& line) {
  std::vector<std::string> names;
  for (const Cell& c : split_cells(line)) names.push_back(c.text);
  return names;
}

// Header names may be quoted ("frame","t",...), as many CSV writers do.
std::string unquote(const std::string& text) {
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"') {
    return text.substr(1, text.size() - 2);
  }
  return text;
}

}  // namespace

std::string trace_word(const std::string& text) {
  if (text.empty()) return "none";
  std::string cell = text;
  for (char& c : cell) {
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = '-';
  }
  return cell;
}

std::string trace_header() {
  return std::string(kPublicColumns) + "," + kExtraColumns + "," + kCutReasonColumn;
}

void write_trace_csv(const std::string& path, const std::vector<TraceRow>& rows) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write trace file '" + tmp + "'");
    const bool lens = std::any_of(rows.begin(), rows.end(), [](const TraceRow& r) { return r.fov > 0; });
    const bool shots = std::any_of(rows.begin(), rows.end(), [](const TraceRow& r) { return !r.shot.empty(); });
    out << trace_header() << (lens || shots ? ",fov,roll" : "") << (shots ? ",shot" : "") << "\n";
    char line[512];
    for (const TraceRow& r : rows) {
      // Fixed precision keeps traces byte-for-byte reproducible and diffable; camera positions
      // get micrometres so jerk (a third difference) is not swamped by rounding.
      std::snprintf(line, sizeof line,
                    "%d,%.4f,%.4f,%.4f,%.4f,%.3f,%.6f,%.6f,%.6f,%.4f,%.4f,%.4f,%d,%.6g,%.1f,"
                    "%d,%.3f,%.3f,%.3f,%s\n",
                    r.frame, r.t, r.character.x(), r.character.y(), r.character.z(),
                    r.character_yaw, r.camera.x(), r.camera.y(), r.camera.z(), r.target.x(),
                    r.target.y(), r.target.z(), r.cut ? 1 : 0, r.cost, r.solve_us,
                    r.controller_visible ? 1 : 0, r.desired_height, r.desired_distance,
                    r.desired_orientation, trace_word(r.cut_reason).c_str());
      if (lens || shots) {
        std::string text(line);
        text.pop_back();  // the newline
        char cells[64];
        std::snprintf(cells, sizeof cells, ",%.4f,%.4f", r.fov, r.roll);
        out << text << cells;
        if (shots) out << "," << trace_word(r.shot);
        out << "\n";
        continue;
      }
      out << line;
    }
    if (!out) throw std::runtime_error("error while writing trace file '" + tmp + "'");
  }
  std::filesystem::rename(tmp, path);
}

std::vector<TraceRow> read_trace_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw csp::InputError({path, 0, 0}, "cannot open trace file");
  const std::vector<std::string> public_columns = split_line(kPublicColumns);

  std::string line;
  if (!std::getline(in, line)) {
    throw csp::InputError({path, 1, 0}, std::string("empty file: expected the trace header '") +
                                            kPublicColumns + "'");
  }
  std::vector<Cell> header = split_cells(line);
  for (Cell& c : header) c.text = unquote(c.text);
  for (std::size_t i = 0; i < public_columns.size(); ++i) {
    if (i >= header.size()) {
      throw csp::InputError(
          {path, 1, 0}, "missing column '" + public_columns[i] + "' (column " +
                            std::to_string(i + 1) + "): the header has " +
                            std::to_string(header.size()) + " columns; a trace starts with '" +
                            kPublicColumns + "'");
    }
    if (header[i].text != public_columns[i]) {
      throw csp::InputError({path, 1, header[i].column},
                            "column " + std::to_string(i + 1) + " is '" + header[i].text +
                                "', expected '" + public_columns[i] + "' (a trace starts with '" +
                                kPublicColumns + "')");
    }
  }
  // This project's extra columns, wherever they are after the public ones; other tools may
  // add columns of their own (any text), which are not read.
  const std::vector<std::string> extra_columns = split_line(kExtraColumns);
  std::vector<std::size_t> extra_at(extra_columns.size(), 0);  // 0: absent
  for (std::size_t e = 0; e < extra_columns.size(); ++e) {
    for (std::size_t i = public_columns.size(); i < header.size(); ++i) {
      if (header[i].text == extra_columns[e]) extra_at[e] = i;
    }
  }
  // The cut reason, if a later column names it (the one extra cell that is a word).
  std::size_t reason_at = 0;  // 0: absent
  for (std::size_t i = public_columns.size(); i < header.size(); ++i) {
    if (header[i].text == kCutReasonColumn) reason_at = i;
  }
  // The lens and the shot of a composing or edited run.
  std::size_t fov_at = 0, roll_at = 0, shot_at = 0;
  for (std::size_t i = public_columns.size(); i < header.size(); ++i) {
    if (header[i].text == "fov") fov_at = i;
    if (header[i].text == "roll") roll_at = i;
    if (header[i].text == "shot") shot_at = i;
  }

  std::vector<TraceRow> rows;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    std::vector<Cell> cells = split_cells(line);
    if (cells.size() == 1 && cells[0].text.empty()) continue;  // a blank line
    if (cells.size() < header.size()) {
      throw csp::InputError({path, line_number, 0},
                            "expected " + std::to_string(header.size()) + " cells as in the "
                            "header, got " + std::to_string(cells.size()) + ": missing '" +
                                header[cells.size()].text + "' (column " +
                                std::to_string(cells.size() + 1) + ")");
    }
    if (cells.size() > header.size()) {
      throw csp::InputError({path, line_number, cells[header.size()].column},
                            "expected " + std::to_string(header.size()) +
                                " cells as in the header, got " + std::to_string(cells.size()));
    }
    const auto number = [&](std::size_t i, const std::string& name) {
      const Cell& c = cells[i];
      char* end = nullptr;
      const double x = std::strtod(c.text.c_str(), &end);
      if (c.text.empty() || *end != '\0') {
        throw csp::InputError({path, line_number, c.column},
                              "column '" + name + "': expected a number, got '" + c.text + "'");
      }
      if (!std::isfinite(x)) {
        throw csp::InputError({path, line_number, c.column},
                              "column '" + name + "': expected a finite number, got '" + c.text +
                                  "'");
      }
      return x;
    };
    double v[15];
    for (std::size_t i = 0; i < public_columns.size(); ++i) v[i] = number(i, public_columns[i]);
    if (v[0] != std::floor(v[0]) || std::abs(v[0]) > 1e9) {
      throw csp::InputError({path, line_number, cells[0].column},
                            "column 'frame': expected a whole number, got '" + cells[0].text +
                                "'");
    }
    TraceRow r;
    r.line = line_number;
    r.frame = static_cast<int>(v[0]);
    r.t = v[1];
    r.character = {v[2], v[3], v[4]};
    r.character_yaw = v[5];
    r.camera = {v[6], v[7], v[8]};
    r.target = {v[9], v[10], v[11]};
    r.cut = v[12] != 0;
    r.cost = v[13];
    r.solve_us = v[14];
    if (extra_at[0]) r.controller_visible = number(extra_at[0], extra_columns[0]) != 0;
    if (extra_at[1]) r.desired_height = number(extra_at[1], extra_columns[1]);
    if (extra_at[2]) r.desired_distance = number(extra_at[2], extra_columns[2]);
    if (extra_at[3]) r.desired_orientation = number(extra_at[3], extra_columns[3]);
    if (reason_at) {
      const Cell& c = cells[reason_at];
      if (c.text.empty()) {
        throw csp::InputError({path, line_number, c.column},
                              "column 'cut_reason': expected a cut reason, got nothing");
      }
      r.cut_reason = c.text;
    }
    if (fov_at) r.fov = number(fov_at, "fov");
    if (roll_at) r.roll = number(roll_at, "roll");
    if (shot_at) {
      const Cell& c = cells[shot_at];
      if (c.text.empty()) {
        throw csp::InputError({path, line_number, c.column}, "column 'shot': expected a shot's name, got nothing");
      }
      r.shot = unquote(c.text);
    }
    rows.push_back(r);
  }
  return rows;
}

}  // namespace sightline::experiments
