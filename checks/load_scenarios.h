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

// A load of `contact_m` along the deck crossing `span_m` at `speed_m_s`: at t = 0 it stands
// wholly before the first support, its centre reaches x at (x + c/2) / v, and it has left the
// deck at (span + c) / v. With no contact length, a point load from x = 0 at t = 0.
struct Crossing {
  double span_m = 0, speed_m_s = 0, contact_m = 0;

  double DurationS() const { return (span_m + contact_m) / speed_m_s; }
  double TimeAtS(double x_m) const { return (x_m + 0.5 * contact_m) / speed_m_s; }
  // The time its bearing takes to pass a point: each node's share is spread over it [s].
  double SpreadS() const { return contact_m / speed_m_s; }
};

// The design's walking load's crossing: loads.travelling_speed_m_s and
// loads.travelling_contact_length_m over the span.
Crossing TravellingCrossing(const Design& design);

// A load `force_n` crossing the deck as `crossing` says. Between two deck points it is shared
// by the lever rule, so each station node carries a ramp up from the previous point and down
// to the next (LoadStepConfig rise_s / fall_s), spread over the crossing's spread (spread_s);
// the planes share it equally. RK4 at `dt_s`.
DynamicsConfig MovingLoadScenario(const Design& design, double force_n, const Crossing& crossing,
                                  double dt_s);

// The characteristic wind across the deck (the design's kWind action), rising linearly from
// zero over `rise_s`, then holding for as long again. RK4 at `dt_s`. Throws ModelError when
// the design has no wind action (a planar bridge).
DynamicsConfig WindGustScenario(const Design& design, double rise_s, double dt_s);

}  // namespace tbridge
