// Trace: one row per simulated frame of a camera run, and its CSV form (FORMATS.md).
//
// The first fifteen columns are the public format other tools read, in this order:
//   frame,t,char_x,char_y,char_z,char_yaw,cam_x,cam_y,cam_z,target_x,target_y,target_z,cut,cost,solve_us
// then the columns this project adds (the format allows more after those): the
// controller's own visibility flag and the profile's desired values that frame, so metrics
// can measure deviation from what the camera was asked to do, even inside areas; and last
// the cut's reason, a word ("none" on frames without a cut), so metrics can tell forced cuts
// from discretionary ones.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace sightline::experiments {

struct TraceRow {
  int frame = 0;
  double t = 0;                       // seconds
  Eigen::Vector3d character{0, 0, 0};  // feet position
  double character_yaw = 0;           // degrees
  Eigen::Vector3d camera{0, 0, 0};
  Eigen::Vector3d target{0, 0, 0};  // look-at point
  bool cut = false;                 // the camera jumped into this frame
  double cost = 0;                  // total weighted cost of the chosen position
  double solve_us = 0;              // microseconds the controller spent on the frame
  // Extras.
  bool controller_visible = true;   // the controller's own flag (metrics never trust it)
  double desired_height = 0;        // metres above the feet
  double desired_distance = 0;      // metres, horizontal
  double desired_orientation = 0;   // degrees
  // Why the camera cut: "none", "left-enclosed-area", "backed-up-to-obstacle",
  // "visibility-lost", "stuck", "too-fast" (camera_run.cc names them). Empty when the trace
  // does not say (a file without the cut_reason column).
  std::string cut_reason;
  // The lens of a composing camera (a shot: scene's tracking shot), degrees; 0 for the chase
  // camera. Written as the columns fov and roll when some row has a fov.
  double fov = 0, roll = 0;
  // The shot in use (an edited run, FORMATS.md "Script and named shots"); empty otherwise.
  // Written as the last column, `shot`, when some row has one (commas and quotes become
  // '-': the cell is one word of CSV).
  std::string shot;
  // The 1-based line this row was read from (read_trace_csv), for messages; 0 otherwise.
  int line = 0;
};

// The header line, without a trailing newline.
std::string trace_header();
// A word column's cell (cut_reason, shot) as the trace writes it: "none" when empty, commas,
// quotes and line breaks as '-', so it stays one CSV cell (and other views of a trace, the
// Python module's array, hold the same text).
std::string trace_word(const std::string& text);
// Writes the trace to `path` atomically enough for resumable suites: to path + ".tmp", then
// renamed. Throws std::runtime_error naming the path on failure.
void write_trace_csv(const std::string& path, const std::vector<TraceRow>& rows);
// Reads a trace written by write_trace_csv, or any CSV whose header starts with the fifteen
// public columns in order (names may be quoted; blanks around cells and Windows line ends are
// fine). Columns after those may hold anything; this project's extras (visible,
// desired_height, ...) are read by name wherever they are. Throws csp::InputError naming the
// file, line and column on malformed input (columns named cut_reason and shot are read as words; fov
// and roll as numbers): a missing or misnamed public column (which one),
// a row with fewer or more cells than the header, a cell of a read column that is not a
// finite number, a frame number that is not whole.
// Blank lines are skipped.
std::vector<TraceRow> read_trace_csv(const std::string& path);

}  // namespace sightline::experiments
