#include "dynamics/simulation.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <numbers>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/progress.h"
#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/coupling.h"
#include "dynamics/integrators.h"
#include "dynamics/run_monitor.h"
#include "dynamics/sdirk.h"
#include "dynamics/step_size.h"

namespace tbridge {

ModelOptions ModelOptionsOf(const DynamicsConfig& c) {
  ModelOptions o;
  o.string_mass = c.string_mass;
  o.damping = c.damping_c;
  for (const PrestrainConfig& p : c.prestrain) o.prestrain.push_back({p.group, p.ratio});
  o.gravity_on_structure = c.gravity_on_structure;
  o.deck_inertia = c.deck_inertia;
  return o;
}

namespace {

// Progress is told every 1024 steps: a lock and two stores, far below the cost of the steps.
constexpr long kProgressEvery = 1024;

// The fixed-step loop: RK4 (with `choice.substeps` sub-steps per step) or SDIRK3 (`sdirk`).
template <class System, class Ode>
void RunFixedSteps(const DynamicsConfig& config, const System& system, Ode& ode,
                   const IntegratorChoice& choice, Sdirk3* sdirk, long total_steps,
                   Eigen::VectorXd& y, RunMonitor& monitor, RunRecorder& recorder,
                   ProgressReporter* progress) {
  Rk4Workspace ws(sdirk == nullptr ? system.state_size() : 0);
  const auto step_end = [&](long step) {
    return step == total_steps ? config.duration : step * config.dt;
  };
  const auto hold_loads = [&](long step) {
    if (system.has_timed_loads()) ode.HoldLoadsAt(0.5 * ((step - 1) * config.dt + step_end(step)));
  };
  // RK4 evaluates each step's first stage as soon as the step before it ends, recording the
  // strings' geometry for the monitor, which measures that same state (the stages and the
  // state are exactly those of Rk4Step).
  const bool rk4 = sdirk == nullptr;
  if (rk4 && total_steps > 0) {
    hold_loads(1);
    Rk4FirstStage(ode, 0.0, y, ws);
  }
  for (long step = 1; step <= total_steps; ++step) {
    const double t_old = (step - 1) * config.dt;
    const double t = step_end(step);
    hold_loads(step);
    double dissipated = 0;
    bool strings_recorded = false;
    if (!rk4) {
      sdirk->Step(ode, t_old, t - t_old, y);
      dissipated = sdirk->last_dissipated();
    } else {
      // Sub-steps share the step's held loads; the monitor sees the step's end state.
      const double h = (t - t_old) / choice.substeps;
      dissipated += Rk4FinishStep(ode, t_old, h, y, ws);
      for (int k = 1; k < choice.substeps; ++k) dissipated += Rk4Step(ode, t_old + k * h, h, y, ws);
      if (step < total_steps) {
        hold_loads(step + 1);
        ode.RecordStringsInNextEvaluation(monitor.string_geometry());
        try {
          Rk4FirstStage(ode, t, y, ws);
        } catch (...) {
          // A state the engine cannot evaluate (the class-k constraint matrix no longer
          // positive definite) is most often a blown-up one: the monitor's verdict on it comes
          // first, as it did when this evaluation began the next step.
          monitor.Accept(step, t_old, t, y.data(), dissipated);
          throw;
        }
        strings_recorded = true;
      }
    }
    monitor.Accept(step, t_old, t, y.data(), dissipated, strings_recorded);
    if (progress != nullptr && step % kProgressEvery == 0) progress->Update(t, config.duration);
    recorder.AfterStep(t, y.data());
  }
  SimulationSummary& s = monitor.summary();
  s.steps = static_cast<int>(total_steps);
  s.evaluations =
      sdirk != nullptr ? sdirk->stats().evaluations : 4L * choice.substeps * total_steps;
}

// The adaptive loop: DOPRI5 with dense output onto the recorder's grids.
template <class Ode>
void RunAdaptive(const DynamicsConfig& config, Ode& ode, int state_size, Eigen::VectorXd& y,
                 RunMonitor& monitor, RunRecorder& recorder, ProgressReporter* progress) {
  Dopri5Options o;
  o.rtol = config.rtol;
  o.atol = config.atol;
  Dopri5 dp(o);
  Dopri5Workspace ws(state_size);
  Eigen::VectorXd out(state_size);
  const auto interpolate = [&](double t_grid, Eigen::VectorXd& state) {
    dp.Interpolate(t_grid, ws, state);
  };
  double t = 0, h = config.dt;
  dp.Start(ode, t, y, ws);
  long step = 0;
  while (t < config.duration) {
    const double t_old = t;
    if (step >= config.limits.max_steps) {
      throw ConfigError("dynamics.limits.max_steps",
                        NumberText(static_cast<double>(config.limits.max_steps)),
                        "dopri5 used them all before t = " + NumberText(t) +
                            " s of dynamics.duration = " + NumberText(config.duration) +
                            " s: raise the limit, or loosen dynamics.rtol and atol");
    }
    dp.Step(ode, t, y, h, config.duration, ws);
    monitor.Accept(++step, t_old, t, y.data(), dp.last_dissipated());
    if (progress != nullptr && step % kProgressEvery == 0) progress->Update(t, config.duration);
    recorder.UpTo(t, out, interpolate);
  }
  SimulationSummary& s = monitor.summary();
  s.steps = dp.accepted();
  s.rejected = dp.rejected();
  s.evaluations = dp.evaluations();
}

// Integrates `config` with the engine `system` (Class1System or ClassKSystem, its adapter
// `Ode`) and fills `result`, whose recorded nodes are set.
template <class System, class Ode>
SimulationResult RunScenario(const DynamicModel& model, const DynamicsConfig& config,
                             const std::vector<PrestrainReport>& prestrain, const System& system,
                             SimulationResult result,
                             std::chrono::steady_clock::time_point wall_start,
                             const RunHooks& hooks) {
  Ode ode(system);
  Eigen::VectorXd y = InitialState(model, config);
  // Bar forces from the run's own engine, in a workspace of their own (the integrator's holds
  // its stages).
  RunMonitor::BarForceProbe probe;
  if (config.record.bar_forces) {
    auto probe_ws =
        std::shared_ptr<decltype(MakeWorkspace(system))>(new auto(MakeWorkspace(system)));
    auto probe_dy = std::make_shared<Eigen::VectorXd>(system.state_size());
    probe = [&system, probe_ws, probe_dy](double t, const double* state, Eigen::VectorXd& lambda) {
      system.Derivative(t, state, probe_dy->data(), *probe_ws);
      system.BarForceDensities(*probe_ws, lambda);
    };
  }
  RunMonitor monitor(model, system, config, y, probe);
  const Eigen::VectorXd y_start = y;
  monitor.SetOmegaMax([&] { return HighestFrequency(ode, y_start).omega_max; });

  // dopri5's count is not bounded by CheckRunLimits (its grid only sizes the records).
  const long total_steps = static_cast<long>(std::min(FixedStepCount(config), 9e18));
  RunRecorder recorder(model, config, total_steps, hooks.history, result);
  recorder.Start(y.data());

  // SDIRK3's Newton matrix is analysed when "auto" needs its counts, and kept if it runs.
  std::unique_ptr<Sdirk3> sdirk;
  const auto make_sdirk = [&] {
    if (!sdirk) sdirk = std::make_unique<Sdirk3>(CouplingOf(model), system.state_size());
  };
  const IntegratorChoice choice = ResolveIntegrator(config.integrator, config.dt, ode, y, [&] {
    make_sdirk();
    const int members = static_cast<int>(model.bars.size() + model.strings.size());
    return EstimateStepCosts(members, system.coordinates(), sdirk->counts());
  });
  SimulationSummary& s = monitor.summary();
  s.engine = result.summary.engine;
  s.integrator = NameOf(choice.kind);
  s.substeps = choice.substeps;
  if (choice.kind == IntegratorKind::kDopri5) {
    RunAdaptive(config, ode, system.state_size(), y, monitor, recorder, hooks.progress);
  } else {
    if (choice.kind == IntegratorKind::kSdirk3) make_sdirk();
    Sdirk3* implicit = choice.kind == IntegratorKind::kSdirk3 ? sdirk.get() : nullptr;
    RunFixedSteps(config, system, ode, choice, implicit, total_steps, y, monitor, recorder,
                  hooks.progress);
  }
  if (hooks.progress != nullptr) hooks.progress->Update(config.duration, config.duration);
  recorder.Finish(config.duration);

  monitor.Finish();
  s.duration = config.duration;
  s.prestrain = prestrain;
  if (config.frequency.enabled) MeasureDeckFrequency(model, result, s);
  s.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.summary = s;
  return result;
}

}  // namespace

SimulationResult Simulate(const DynamicModel& model, const DynamicsConfig& config,
                          const std::vector<PrestrainReport>& prestrain, const RunHooks& hooks) {
  CheckRunLimits(model, config,
                 hooks.extra_bytes_per_record ? hooks.extra_bytes_per_record(model) : 0.0);
  const auto wall_start = std::chrono::steady_clock::now();
  const int dim = model.dim, n_n = model.num_nodes();

  std::vector<TimedLoad> timed;
  for (size_t k = 0; k < config.loads.size(); ++k) {
    const LoadStepConfig& l = config.loads[k];
    const std::string key = "dynamics.loads[" + std::to_string(k) + "]";
    if (l.node > n_n)
      throw ConfigError(key + ".node", std::to_string(l.node),
                        "must be in 1.." + std::to_string(n_n));
    if (dim == 2 && l.force[2] != 0) {
      throw ConfigError(key + ".force", NumberText(l.force[2]), "z must be 0 for a planar bridge");
    }
    timed.push_back({l.t_start, l.t_end, l.node - 1,
                     Eigen::Vector3d(l.force[0], l.force[1], l.force[2]), l.rise_s, l.fall_s,
                     2.0 * std::numbers::pi * l.frequency_hz, l.spread_s});
  }
  SimulationResult result;
  result.dim = dim;
  for (const int node : config.record.nodes) {
    if (node > n_n)
      throw ConfigError("dynamics.record.nodes", std::to_string(node),
                        "must be in 1.." + std::to_string(n_n));
    result.recorded_nodes.push_back(node - 1);
  }

  const EngineKind engine = EngineFor(model, config);
  result.summary.engine = NameOf(engine);
  const EngineOptions options = EngineOptionsOf(config);
  if (engine == EngineKind::kClass1) {
    const Class1System system(model, options, timed);
    return RunScenario<Class1System, Class1Ode>(model, config, prestrain, system, std::move(result),
                                                wall_start, hooks);
  }
  const ClassKSystem system(model, options, timed);
  return RunScenario<ClassKSystem, ClassKOde>(model, config, prestrain, system, std::move(result),
                                              wall_start, hooks);
}

}  // namespace tbridge
