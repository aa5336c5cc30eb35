// The static model (statics/static_solve.h) of a sized design: its structure, each string's
// stiffness and rest length, and the reference state it starts from.
#pragma once

#include "design/design.h"
#include "statics/static_solve.h"

namespace tbridge {

StaticModel StaticModelOf(const Design& design);

// The drawn geometry with the reference state's bar forces, in equilibrium under design.loads.
StaticState ReferenceState(const StaticModel& model, const Design& design);

}  // namespace tbridge
