// The dynamic check of a sized design: the paper's travelling load (eqs 50-51) run on the
// bridge at service level. The permanent load and the payload stand (their weight in the
// loads, the deck's and the payload's mass at the deck nodes), the bridge starts at rest in
// its static equilibrium under them, and the deck node load f visits each inner deck node for
// 0.25 s. RK4 at a step of at most 1e-4 s that divides the 0.25 s: SDIRK3 under-reports the
// string peaks by up to 22 % (BENCHMARKS.md), so the check does not use it.
//
// A member's dynamic demand is gamma_G,sup F_G + gamma_Q (F_peak - F_G), F_G its force in the
// reference state and F_peak its peak in the run (the factors are 1 with the paper's
// switches); its utilisation is that over its resistance. A string that goes slack in the
// run fails with mode "slack".
#pragma once

#include "design/design.h"

namespace tbridge {

// Runs the check and raises the members' utilisations (mode "dynamic" or "slack", case
// "dynamic: paper_travelling"). Skips it, saying why in the result's note, when the run
// would take more than `max_member_steps` member-steps.
DynamicCheck CheckDynamics(Design& design, double max_member_steps = 5e7);

}  // namespace tbridge
