#include "dynamics/run_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

double FixedStepCount(const DynamicsConfig& config) {
  return std::max(1.0, std::ceil(config.duration / config.dt - 1e-9));
}

RunEstimate EstimateRun(const DynamicModel& model, const DynamicsConfig& config,
                        double extra_bytes_per_record) {
  RunEstimate e;
  const double steps = FixedStepCount(config);
  e.steps = steps > 9e18 ? std::numeric_limits<long>::max() : static_cast<long>(steps);
  const double records =
      config.record.nodes.empty() ? 0.0 : std::floor(steps / config.record.every) + 1;
  e.records = records > 9e18 ? std::numeric_limits<long>::max() : static_cast<long>(records);
  const double values =
      records * (1.0 + model.dim * static_cast<double>(config.record.nodes.size()));
  // history.csv prints 12 significant digits: up to about 20 characters a value with its sign,
  // exponent and separator; without the CSV the rows are still held (8 bytes a value).
  e.history_bytes = values * (config.record.csv ? 20.0 : 8.0);
  if (config.frequency.enabled && !model.deck_nodes.empty()) {
    e.deck_bytes = (std::floor(steps / config.frequency.every) + 1) * 16.0;  // two signals
  }
  e.extra_bytes = records * extra_bytes_per_record;
  return e;
}

void CheckStepLimit(const DynamicsConfig& config) {
  const double steps = FixedStepCount(config);
  if (config.integrator != IntegratorKind::kDopri5 &&
      steps > static_cast<double>(config.limits.max_steps)) {
    throw ConfigError(
        "dynamics.duration", NumberText(config.duration),
        "with dynamics.dt = " + NumberText(config.dt) + " s the run takes " + NumberText(steps) +
            " steps, more than dynamics.limits.max_steps = " +
            NumberText(static_cast<double>(config.limits.max_steps)) +
            " allows: shorten the duration, enlarge dt, or raise dynamics.limits.max_steps");
  }
}

void CheckRunLimits(const DynamicModel& model, const DynamicsConfig& config,
                    double extra_bytes_per_record) {
  CheckStepLimit(config);
  const RunEstimate e = EstimateRun(model, config, extra_bytes_per_record);
  const std::string duration = NumberText(config.duration);
  if (e.total_bytes() > config.limits.max_output_bytes) {
    throw ConfigError("dynamics.duration", duration,
                      "with dynamics.dt = " + NumberText(config.dt) +
                          " s the run writes or holds about " + NumberText(e.total_bytes()) +
                          " bytes (history " + NumberText(e.history_bytes) + ", deck samples " +
                          NumberText(e.deck_bytes) + ", export " + NumberText(e.extra_bytes) +
                          "), more than dynamics.limits.max_output_bytes = " +
                          NumberText(config.limits.max_output_bytes) +
                          " allows: record fewer nodes or samples (dynamics.record.every, "
                          "dynamics.frequency.every), "
                          "shorten the run, or raise dynamics.limits.max_output_bytes");
  }
}

}  // namespace tbridge
