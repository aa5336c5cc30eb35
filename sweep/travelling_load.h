// The outer loop's nonlinear service run: a load travelling across the deck of a class-1
// model (sweep.travelling_load in configs/README.md), with the peaks the dynamic constraints
// need. Fixed-step RK4 on Class1System; loads held constant within each step.
#pragma once

#include <vector>

#include "design/design.h"
#include "dynamics/model.h"
#include "sweep/sweep_config.h"

namespace tbridge {

struct TravellingLoadResult {
  double peak_deck_displacement = 0;  // max over steps and free deck nodes of |y - y_0| [m]
  double peak_string_stress = 0;      // max tension / area over strings and steps [Pa]
  double peak_stress_ratio = 0;       // peak_string_stress / sigma_w [-]
  int slack_strings = 0;              // strings that were slack (s < L0) at some step
  // max over bars and steps of |bar force| / capacity, capacity = min(sigma_w A, Euler
  // pi E A^2 / (4 l^2 SF_buckling)) for compression and sigma_w A for tension [-]
  double peak_bar_capacity_ratio = 0;
  long steps = 0;
};

// Runs the travelling load on `model` (built from `design`; bars in design order). The
// moving force is load_factor x design.deck.node_load, downward, on deck station k (every
// plane) for t in [k, k + 1) x duration / stations. Every step is checked.
// Throws ModelError when the model is not class 1, has no deck nodes, or the run blows up
// (non-finite state or a bar-length error above 1e-3 relative: the message suggests a smaller
// sweep.travelling_load.dt).
TravellingLoadResult RunTravellingLoad(const DynamicModel& model, const Design& design,
                                       const TravellingLoadConfig& config);

}  // namespace tbridge
