// The dynamic loads a designed bridge is checked under, as dynamics scenarios (timed node
// loads on top of the model's standing loads): the paper's travelling load, a point load
// crossing the deck at walking speed, and a wind gust across the 3D deck.
#pragma once

#include <string>

#include "core/dynamics_config.h"
#include "design/design.h"

namespace tbridge {

// The paper's travelling load (eqs 50-51): `force_n` downward on deck station k (shared by its
// planes) for t in [k, k + 1) x duration / stations. The step is the largest one <= dt that
// puts a whole number of steps in each station, so the load switches on step boundaries.
// Bar-force peaks on, no frequency measurement, no node history. Throws ModelError when the
// design has no deck stations.
DynamicsConfig PaperTravellingScenario(const Design& design, double duration_s, double dt_s,
                                       IntegratorKind integrator, double force_n);

// A point load `force_n` crossing the deck at `speed_m_s`, from the support at x = 0 (t = 0)
// to the one at x = span (t = span / v). Between two deck points it is shared by the lever
// rule, so each station node carries a ramp up from the previous point and down to the next
// (LoadStepConfig rise_s / fall_s); the planes share it equally. RK4 at `dt_s`.
DynamicsConfig MovingLoadScenario(const Design& design, double force_n, double speed_m_s,
                                  double dt_s);

// The characteristic wind across the deck (the design's kWind action), rising linearly from
// zero over `rise_s`, then holding for as long again. RK4 at `dt_s`. Throws ModelError when
// the design has no wind action (a planar bridge).
DynamicsConfig WindGustScenario(const Design& design, double rise_s, double dt_s);

}  // namespace tbridge
