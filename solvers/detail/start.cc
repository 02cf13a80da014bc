#include "sightline/solvers/detail/start.h"

#include <stdexcept>
#include <string>

namespace sightline::solvers::detail {

void prepare_start(const csp::Problem& problem, std::span<const double> start,
                   csp::Assignment& out) {
  if (start.size() != problem.num_variables()) {
    throw std::invalid_argument("start assignment has " + std::to_string(start.size()) +
                                " values but problem '" + problem.name() + "' has " +
                                std::to_string(problem.num_variables()) + " variables");
  }
  out.resize(start.size());
  for (std::size_t i = 0; i < start.size(); ++i) {
    out[i] = problem.domain(static_cast<csp::VariableId>(i)).clamp(start[i]);
  }
}

}  // namespace sightline::solvers::detail
