// The outer loop's nonlinear service run: a load travelling across the deck of a designed
// bridge (sweep.travelling_load in configs/README.md), with the peaks the dynamic constraints
// need. It is a dynamics scenario like any other: Simulate (dynamics/simulation.h) runs it with
// the engine the bridge needs (class 1 or class k) and the integrator "auto" picks.
#pragma once

#include <string>

#include "core/dynamics_config.h"
#include "design/design.h"
#include "dynamics/model.h"
#include "sweep/sweep_config.h"

namespace tbridge {

struct TravellingLoadResult {
  double peak_deck_displacement = 0;  // max over steps and free deck nodes of |y - y_0| [m]
  double peak_string_stress = 0;      // max tension / area over strings and steps [Pa]
  double peak_stress_ratio = 0;       // peak_string_stress / sigma_w [-]
  int slack_strings = 0;              // strings that were slack (s < L0) at some step
  int slack_taut_strings = 0;         // of those, the ones that must stay taut (MustStayTaut)
  // max over bars and steps of |bar force| / capacity: the design's bar resistance
  // (BarRuleOf: yield and buckling) in compression, its yield resistance in tension [-]
  double peak_bar_capacity_ratio = 0;
  long steps = 0;
  double dt = 0;           // the step taken [s]: the largest <= config.dt that divides a station
  std::string integrator;  // "rk4" | "rk4xM" (M sub-steps per step) | "sdirk3", as resolved
  std::string engine;      // "class1" | "classk"
};

// The scenario of the run: the paper's travelling load (verify/load_scenarios.h) of
// load_factor x f per deck node (every plane), on top of the design loads.
DynamicsConfig TravellingLoadScenario(const Design& design, const TravellingLoadConfig& config);

// Runs the scenario on `model` (built from `design`; bars in design order). Throws ModelError
// when the run blows up (non-finite state, a bar-length error above 1e-3 relative, or energy
// growth; the message names the step and time and proposes a step).
TravellingLoadResult RunTravellingLoad(const DynamicModel& model, const Design& design,
                                       const TravellingLoadConfig& config);

}  // namespace tbridge
