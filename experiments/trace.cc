#include "experiments/trace.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "csp/input_error.h"

namespace sightline::experiments {
namespace {

constexpr const char* kPublicColumns =
    "frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,target_x,target_y,target_z,cut,"
    "cost,solve_us";
constexpr const char* kExtraColumns =
    "visible,desired_height,desired_distance,desired_orientation";
constexpr const char* kCutReasonColumn = "cut_reason";

// A cut reason as written: a word without commas, quotes or line breaks ("none" if empty).
std::string reason_cell(const std::string& reason) {
  if (reason.empty()) return "none";
  std::string cell = reason;
  for (char& c : cell) {
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = '-';
  }
  return cell;
}

}  // namespace

std::string trace_header() {
  return std::string(kPublicColumns) + "," + kExtraColumns + "," + kCutReasonColumn;
}

void write_trace_csv(const std::string& path, const std::vector<TraceRow>& rows) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write trace file '" + tmp + "'");
    out << trace_header() << "\n";
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
                    r.desired_orientation, reason_cell(r.cut_reason).c_str());
      out << line;
    }
    if (!out) throw std::runtime_error("error while writing trace file '" + tmp + "'");
  }
  std::filesystem::rename(tmp, path);
}

std::vector<TraceRow> read_trace_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw csp::InputError({path, 0, 0}, "cannot open trace file");
  std::string line;
  if (!std::getline(in, line) || line.rfind(kPublicColumns, 0) != 0) {
    throw csp::InputError({path, 1, 0}, std::string("expected the trace header '") +
                                            kPublicColumns + "'");
  }
  const bool has_extras = line.find(kExtraColumns) != std::string::npos;
  // The column holding the cut reason, if any (the only cell that is a word, not a number).
  std::size_t reason_column = std::string::npos;
  {
    std::stringstream names(line);
    std::string name;
    for (std::size_t i = 0; std::getline(names, name, ','); ++i) {
      if (!name.empty() && name.back() == '\r') name.pop_back();
      if (name == kCutReasonColumn && i >= 15) reason_column = i;
    }
  }
  std::vector<TraceRow> rows;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<double> v;
    std::string reason;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) {
      if (v.size() == reason_column) {
        if (cell.empty()) {
          throw csp::InputError({path, line_number, 0}, "expected a cut reason, got nothing");
        }
        reason = cell;
        v.push_back(0);  // keeps the column count
        continue;
      }
      char* end = nullptr;
      const double x = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0') {
        throw csp::InputError({path, line_number, 0}, "expected a number, got '" + cell + "'");
      }
      v.push_back(x);
    }
    const std::size_t need =
        reason_column != std::string::npos ? reason_column + 1 : has_extras ? 19 : 15;
    if (v.size() < need) {
      throw csp::InputError({path, line_number, 0}, "expected " + std::to_string(need) +
                                                        " columns, got " +
                                                        std::to_string(v.size()));
    }
    TraceRow r;
    r.frame = static_cast<int>(v[0]);
    r.t = v[1];
    r.character = {v[2], v[3], v[4]};
    r.character_yaw = v[5];
    r.camera = {v[6], v[7], v[8]};
    r.target = {v[9], v[10], v[11]};
    r.cut = v[12] != 0;
    r.cost = v[13];
    r.solve_us = v[14];
    if (has_extras) {
      r.controller_visible = v[15] != 0;
      r.desired_height = v[16];
      r.desired_distance = v[17];
      r.desired_orientation = v[18];
    }
    r.cut_reason = reason;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace sightline::experiments
