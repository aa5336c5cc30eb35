// A dynamic scenario of a model: initial conditions, time-varying loads, integration (RK4 or
// DOPRI5) with the class-1 or the class-k engine, recording and a summary. Only what the
// config asks for is computed.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/dynamics_config.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/response.h"
#include "dynamics/run_summary.h"

namespace tbridge {

// Model options of a dynamics config (string mass, damping, prestrain, gravity). Throws
// nothing: the config was validated when parsed.
ModelOptions ModelOptionsOf(const DynamicsConfig& config);

// Bars grouped by length, longest first (the paper's Table 5 numbering: class 1 is the
// longest, central bar). Lengths equal within 1e-9 relative share a class. Entries are
// 0-based bar indices.
std::vector<std::vector<int>> BarLengthClasses(const DynamicModel& model);

// Initial state (2 x dim x n_n, see dynamics/class1.h): the model's positions, then the
// perturbation (both end nodes of every bar of the class move down, -y, by delta), then the
// per-node displacements and velocities. Throws ConfigError naming the key for a class or
// node out of range, a pinned node, a z component in a planar model, or an initial condition
// that changes a bar's length (> 1e-9 relative) or its length rate.
Eigen::VectorXd InitialState(const DynamicModel& model, const DynamicsConfig& config);

struct SimulationResult {
  SimulationSummary summary;
  // Recorded history: one row per record time: t, then dim coordinates of each recorded node.
  std::vector<int> recorded_nodes;  // 0-based
  int dim = 2;
  // Row-major, so a record is one contiguous write (column-major made each of its values a
  // cache miss a whole column away).
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> history;
  // The deck's vertical displacement, sampled every frequency.every steps from t = 0 [m]:
  // summed over model.deck_nodes (the paper's signal, DeckSignal), and weighted mirror-odd
  // about mid-span (+1 left, -1 right, 0 on it; it cancels in every symmetric mode, as the sum
  // cancels in every antisymmetric one). Two numbers a
  // sample, however long the deck; empty when frequency is off.
  Eigen::VectorXd deck_even, deck_odd;
  double deck_sample_dt = 0;  // [s]
};

// "auto" picks RK4 up to this fraction of its linear stability limit 2 sqrt(2)/omega_max. In
// the work-precision benchmark (BENCHMARKS.md) RK4 was stable at every step below the limit,
// up to 0.92 of it, on every scene, 0.1 m pushes with slack chatter included; and between
// half the limit and the limit it beat SDIRK3 (n = 8: 3.4 s against 43 s).
inline constexpr double kAutoRk4Fraction = 0.9;
// One SDIRK3 step costs about as much as this many RK4 steps (BENCHMARKS.md, Cost per step:
// ~12 right-hand sides plus sparse solves, 36-50 RK4 steps measured).
inline constexpr int kSdirkStepInRk4Steps = 40;

struct IntegratorChoice {
  std::string name;   // "rk4" | "dopri5" | "sdirk3"
  int substeps = 1;   // RK4 steps per step of dt (auto only)
};

// "auto" resolved (see DynamicsConfig::integrator), with L = kAutoRk4Fraction x RK4's
// stability limit at the state `y` (omega_max by power iteration, dynamics/step_size.h):
// - dt <= L: RK4 at dt;
// - else, while m = ceil(dt / L) RK4 sub-steps cost no more than one SDIRK3 step
//   (m <= kSdirkStepInRk4Steps): RK4 with m sub-steps per step, as accurate as RK4 gets;
// - else SDIRK3 at dt, which damps what it does not resolve.
// Any other request is returned as it is, with one sub-step.
IntegratorChoice ResolveIntegrator(const std::string& requested, double dt, OdeSystem& ode, const Eigen::VectorXd& y);

// What a run of `config` on `model` will take, known before it starts.
struct RunEstimate {
  long steps = 0;            // ceil(duration / dt): steps of dt (dopri5: output grid points)
  long records = 0;          // history rows (0 when no node is recorded)
  double history_bytes = 0;  // history.csv (about 20 bytes a value), or the rows held in memory
  double deck_bytes = 0;     // deck signals of the frequency measurement held in memory
  double extra_bytes = 0;    // records x the caller's bytes per record (e.g. the VTK export)
  double total_bytes() const { return history_bytes + deck_bytes + extra_bytes; }
};
RunEstimate EstimateRun(const DynamicModel& model, const DynamicsConfig& config, double extra_bytes_per_record = 0);

// Throws ConfigError naming dynamics.duration (with dt and the limit key) when the run needs
// more steps than config.limits.max_steps. Only the fixed-step integrators are checked here;
// dopri5's count is unknown and it stops at the limit as it runs. Needs no model, so a
// scenario checks it before the design.
void CheckStepLimit(const DynamicsConfig& config);

// CheckStepLimit, then a ConfigError naming dynamics.duration when the run writes or holds
// more bytes than config.limits.max_output_bytes (EstimateRun, with `extra_bytes_per_record`
// for outputs the caller writes per record).
void CheckRunLimits(const DynamicModel& model, const DynamicsConfig& config, double extra_bytes_per_record = 0);

// The largest RK4 step that is stable for a run of `config` on `model` at its start:
// kAutoRk4Fraction x 2 sqrt(2) / omega_max, omega_max by power iteration on the engine
// EngineFor picks, with the run's stabilisation [s]. What "auto" takes RK4 up to.
double Rk4StableStep(const DynamicModel& model, const DynamicsConfig& config);

class ProgressReporter;

// Takes the recorded rows as the run produces them, so that a long history goes to disk in
// memory bounded by one row (RunHooks::history).
class HistorySink {
 public:
  virtual ~HistorySink() = default;
  // Before the first step: the model and the recorded nodes (0-based). May throw ConfigError.
  virtual void Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) = 0;
  // One record at time t [s]: dim coordinates [m] of each recorded node, in their order.
  virtual void Row(double t, const double* coordinates) = 0;
};

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
// above guard.max_energy_growth, or (class k) a singular constraint matrix. The message names the step and time and suggests a smaller dt.
// `prestrain` reports are copied into the summary. Checks CheckRunLimits first; a dopri5 run
// that needs more than limits.max_steps accepted steps stops with a ConfigError naming
// dynamics.limits.max_steps.
SimulationResult Simulate(const DynamicModel& model, const DynamicsConfig& config,
                          const std::vector<PrestrainReport>& prestrain = {}, const RunHooks& hooks = {});

}  // namespace tbridge
