// The static check of a sized design: each load case solved as a nonlinear static problem
// of the prestressed bridge (statics/static_solve.h: rigid bars, strings that go slack, large
// displacements) from its reference state, for deflections, support reactions and member
// forces. The members' utilisations take the nonlinear forces into account.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/design.h"
#include "design/verification.h"
#include "statics/static_solve.h"

namespace tbridge {

// Solves every case (travelling families at up to `max_stations` evenly spaced stations) and
// raises each member's utilisation where a nonlinear force exceeds the linear one: bars and
// strings under the ultimate cases, slack strings under the serviceability cases (mode
// "slack", utilisation 1 + the strain the string lacks to be taut over its working strain).
StaticCheck CheckStatics(Design& design, int max_stations = 16);

}  // namespace tbridge
