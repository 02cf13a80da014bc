// Registration of the built-in constraint kinds: one line per kind.
#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/abs_deviation.h"
#include "sightline/csp/kinds/all_different.h"
#include "sightline/csp/kinds/expression.h"
#include "sightline/csp/kinds/linear.h"
#include "sightline/csp/kinds/not_equal.h"
#include "sightline/csp/kinds/stretch.h"
#include "sightline/csp/kinds/table.h"
#include "sightline/csp/kinds/value_set.h"

namespace sightline::csp {

void register_builtin_kinds(ConstraintKinds& kinds) {
  kinds.add(not_equal_kind());
  kinds.add(all_different_kind());
  kinds.add(linear_kind());
  kinds.add(abs_deviation_kind());
  kinds.add(expression_kind());
  kinds.add(table_kind());
  kinds.add(in_kind());
  kinds.add(not_in_kind());
  kinds.add(equals_kind());
  kinds.add(stretch_kind());
}

}  // namespace sightline::csp
