// A camera run's trace as a numpy structured array for Python (sightline.follow), one record
// per frame with every column of the trace CSV (experiments/runs/trace.h), in its order and
// under its names: frame, t, char_*, cam_*, target_*, cut, cost, solve_us, visible,
// desired_height, desired_distance, desired_orientation, cut_reason, fov, roll, shot. The
// word columns (cut_reason, shot) are unicode strings holding the CSV's text ("none" when
// empty); shot is there for every run, "none" where nothing is edited.
#pragma once

#include <pybind11/numpy.h>

#include <vector>

#include "sightline/experiments/runs/trace.h"

namespace sightline::python {

pybind11::array trace_array(const std::vector<experiments::TraceRow>& rows);

}  // namespace sightline::python
