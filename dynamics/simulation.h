// A dynamic scenario of a model: initial conditions, time-varying loads, integration (RK4,
// DOPRI5 or SDIRK3) with the class-1 or the class-k engine, recording and a summary. Only what
// the config asks for is computed. The driver's parts: the initial state
// (dynamics/initial_state.h), the limits (dynamics/run_limits.h), the engine and integrator
// policy (dynamics/integrator_policy.h), the monitor (dynamics/run_monitor.h), the recorder
// (dynamics/run_recorder.h); this file holds the loops.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/dynamics_config.h"
#include "dynamics/initial_state.h"
#include "dynamics/integrator_policy.h"
#include "dynamics/model.h"
#include "dynamics/response.h"
#include "dynamics/run_limits.h"
#include "dynamics/run_recorder.h"
#include "dynamics/run_summary.h"

namespace tbridge {

// Model options of a dynamics config (string mass, damping, prestrain, gravity). Throws
// nothing: the config was validated when parsed.
ModelOptions ModelOptionsOf(const DynamicsConfig& config);

class ProgressReporter;

// Optional company of a run.
struct RunHooks {
  ProgressReporter* progress = nullptr;  // told the simulated time [s] against the duration
  std::string stage_prefix;              // put before RunScenario's stage names, e.g. "paper_n3: "
  // Bytes the caller will write per recorded sample besides history.csv (e.g. the VTK
  // export), counted against the output limit (CheckRunLimits); empty = none.
  std::function<double(const DynamicModel&)> extra_bytes_per_record;
  // Where the recorded rows go. Empty: SimulationResult::history holds them; else each row
  // goes to every sink as it is taken, and the history stays empty.
  std::vector<HistorySink*> history;
};

// Runs `config` on `model` with the engine EngineFor picks. Throws ConfigError for initial
// conditions, loads or an engine that do not fit the model, ModelError when the run blows up:
// NaN/Inf in the state, a bar-length error above guard.max_bar_length_error, energy growth
// above guard.max_energy_growth, or (class k) a singular constraint matrix. The message names the
// step and time and suggests a smaller dt. `prestrain` reports are copied into the summary. Checks
// CheckRunLimits first; a dopri5 run that needs more than limits.max_steps accepted steps stops
// with a ConfigError naming dynamics.limits.max_steps.
SimulationResult Simulate(const DynamicModel& model, const DynamicsConfig& config,
                          const std::vector<PrestrainReport>& prestrain = {},
                          const RunHooks& hooks = {});

}  // namespace tbridge
