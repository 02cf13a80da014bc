#include "python/trace_array.h"

#include <algorithm>
#include <functional>
#include <string>

namespace py = pybind11;

namespace sightline::python {
namespace {

using experiments::TraceRow;

// A column of the trace: a number (with numpy's format: "<i4", "i1", "<f8") or a word.
struct Column {
  const char* name;
  const char* format;
  std::function<double(const TraceRow&)> number;
  std::string TraceRow::*word = nullptr;
};

// In the CSV's order.
const std::vector<Column>& columns() {
  static const std::vector<Column> all = {
      {"frame", "<i4", [](const TraceRow& r) { return r.frame; }},
      {"t", "<f8", [](const TraceRow& r) { return r.t; }},
      {"char_x", "<f8", [](const TraceRow& r) { return r.character.x(); }},
      {"char_y", "<f8", [](const TraceRow& r) { return r.character.y(); }},
      {"char_z", "<f8", [](const TraceRow& r) { return r.character.z(); }},
      {"char_yaw", "<f8", [](const TraceRow& r) { return r.character_yaw; }},
      {"cam_x", "<f8", [](const TraceRow& r) { return r.camera.x(); }},
      {"cam_y", "<f8", [](const TraceRow& r) { return r.camera.y(); }},
      {"cam_z", "<f8", [](const TraceRow& r) { return r.camera.z(); }},
      {"target_x", "<f8", [](const TraceRow& r) { return r.target.x(); }},
      {"target_y", "<f8", [](const TraceRow& r) { return r.target.y(); }},
      {"target_z", "<f8", [](const TraceRow& r) { return r.target.z(); }},
      {"cut", "i1", [](const TraceRow& r) { return r.cut ? 1 : 0; }},
      {"cost", "<f8", [](const TraceRow& r) { return r.cost; }},
      {"solve_us", "<f8", [](const TraceRow& r) { return r.solve_us; }},
      {"visible", "i1", [](const TraceRow& r) { return r.controller_visible ? 1 : 0; }},
      {"desired_height", "<f8", [](const TraceRow& r) { return r.desired_height; }},
      {"desired_distance", "<f8", [](const TraceRow& r) { return r.desired_distance; }},
      {"desired_orientation", "<f8", [](const TraceRow& r) { return r.desired_orientation; }},
      {"cut_reason", "", nullptr, &TraceRow::cut_reason},
      {"fov", "<f8", [](const TraceRow& r) { return r.fov; }},
      {"roll", "<f8", [](const TraceRow& r) { return r.roll; }},
      {"shot", "", nullptr, &TraceRow::shot},
  };
  return all;
}

}  // namespace

py::array trace_array(const std::vector<TraceRow>& rows) {
  const auto n = static_cast<py::ssize_t>(rows.size());
  // Each column's values; a word column's cells as the CSV writes them, its format as wide
  // as its widest cell.
  py::list fields;
  std::vector<py::object> values;
  for (const Column& c : columns()) {
    if (c.word) {
      py::list cells;
      std::size_t widest = 1;
      for (const TraceRow& r : rows) {
        const std::string cell = experiments::trace_word(r.*c.word);
        widest = std::max(widest, cell.size());
        cells.append(py::str(cell));
      }
      fields.append(py::make_tuple(c.name, "<U" + std::to_string(widest)));
      values.push_back(cells);
      continue;
    }
    py::array_t<double> numbers(n);
    for (py::ssize_t i = 0; i < n; ++i) numbers.mutable_at(i) = c.number(rows[static_cast<std::size_t>(i)]);
    fields.append(py::make_tuple(c.name, c.format));
    values.push_back(numbers);
  }
  const py::module_ numpy = py::module_::import("numpy");
  py::array out = numpy.attr("zeros")(n, numpy.attr("dtype")(fields));
  for (std::size_t i = 0; i < values.size(); ++i) out[py::str(columns()[i].name)] = values[i];
  return out;
}

}  // namespace sightline::python
