// What a run will take, known before it starts, and the config's limits on it: a typo in
// duration or dt fails at once, naming the key, instead of running for days or out of memory.
#pragma once

#include "core/dynamics_config.h"
#include "dynamics/model.h"

namespace tbridge {

// Steps of dt in the run: ceil(duration / dt), at least 1 (dt that divides the duration up to
// round-off gives the whole number). A double, since a typo can ask for more than a long holds.
double FixedStepCount(const DynamicsConfig& config);

// What a run of `config` on `model` will take.
struct RunEstimate {
  long steps = 0;            // ceil(duration / dt): steps of dt (dopri5: output grid points)
  long records = 0;          // history rows (0 when no node is recorded)
  double history_bytes = 0;  // history.csv (about 20 bytes a value), or the rows held in memory
  double deck_bytes = 0;     // deck signals of the frequency measurement held in memory
  double extra_bytes = 0;    // records x the caller's bytes per record (e.g. the VTK export)
  double total_bytes() const { return history_bytes + deck_bytes + extra_bytes; }
};
RunEstimate EstimateRun(const DynamicModel& model, const DynamicsConfig& config,
                        double extra_bytes_per_record = 0);

// Throws ConfigError naming dynamics.duration (with dt and the limit key) when the run needs
// more steps than config.limits.max_steps. Only the fixed-step integrators are checked here;
// dopri5's count is unknown and it stops at the limit as it runs. Needs no model, so a
// scenario checks it before the design.
void CheckStepLimit(const DynamicsConfig& config);

// CheckStepLimit, then a ConfigError naming dynamics.duration when the run writes or holds
// more bytes than config.limits.max_output_bytes (EstimateRun, with `extra_bytes_per_record`
// for outputs the caller writes per record).
void CheckRunLimits(const DynamicModel& model, const DynamicsConfig& config,
                    double extra_bytes_per_record = 0);

}  // namespace tbridge
