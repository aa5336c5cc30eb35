// The static check of a sized design: each load case solved as a nonlinear static problem
// of the prestressed bridge (statics/static_solve.h: rigid bars, strings that go slack, large
// displacements) from its reference state, for deflections, support reactions and member
// forces. What it finds is a report; the design records it (verify/verified_design.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/design.h"
#include "design/verification.h"
#include "statics/static_solve.h"

namespace tbridge {

// Solves every case (travelling families at up to `max_stations` evenly spaced stations) and
// reports each member's largest utilisation under them (StaticCheck::members): bars and
// strings under the ultimate cases, slack strings that must stay taut under the
// serviceability cases (mode "slack"). Changes nothing in `design`.
StaticCheck CheckStatics(const Design& design, int max_stations = 16);

}  // namespace tbridge
