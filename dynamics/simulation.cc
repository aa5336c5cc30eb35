#include "dynamics/simulation.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/error.h"
#include "core/progress.h"
#include "core/string_law.h"
#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/coupling.h"
#include "dynamics/integrators.h"
#include "dynamics/run_monitor.h"
#include "dynamics/sdirk.h"
#include "dynamics/step_size.h"

namespace tbridge {

namespace {

constexpr double kSameLength = 1e-9;  // relative; bars this close share a length class

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A uniform output grid t_k = k * spacing and the rows filled so far.
struct Sampler {
  double spacing = 0;
  long next = 0;  // index of the next grid time
  long rows = 0;
};

}  // namespace

IntegratorChoice ResolveIntegrator(const std::string& requested, double dt, OdeSystem& ode, const Eigen::VectorXd& y) {
  if (requested != "auto") return {requested, 1};
  const double stable = kAutoRk4Fraction * Rk4StepLimit(HighestFrequency(ode, y).omega_max);
  const double m = std::ceil(dt / stable - 1e-12);
  if (m <= 1) return {"rk4", 1};
  if (m <= kSdirkStepInRk4Steps) return {"rk4", static_cast<int>(m)};
  return {"sdirk3", 1};
}

std::string EngineFor(const DynamicModel& model, const DynamicsConfig& config) {
  const int k = MaxBarsAtANode(model);
  if (config.engine == "classk") return "classk";
  if (config.engine == "class1") {
    if (k > 1) {
      throw ConfigError("dynamics.engine", "\"class1\"",
                        "this bridge is class " + std::to_string(k) +
                            " (a node carries several bars); use \"auto\" or \"classk\"");
    }
    return "class1";
  }
  return k > 1 ? "classk" : "class1";
}

ModelOptions ModelOptionsOf(const DynamicsConfig& c) {
  ModelOptions o;
  o.string_mass = c.string_mass == "nodes" ? StringMassMode::kAtNodes
                  : c.string_mass == "off" ? StringMassMode::kOff
                                           : StringMassMode::kOnBars;
  o.damping = c.damping_c;
  for (const PrestrainConfig& p : c.prestrain) o.prestrain.push_back({p.group, p.ratio});
  o.gravity_on_structure = c.gravity_on_structure;
  o.deck_inertia = c.deck_inertia;
  return o;
}

std::vector<std::vector<int>> BarLengthClasses(const DynamicModel& model) {
  std::vector<int> order(model.bars.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return model.bars[a].length > model.bars[b].length; });
  std::vector<std::vector<int>> classes;
  for (const int k : order) {
    const double l = model.bars[k].length;
    if (!classes.empty()) {
      const double ref = model.bars[classes.back().front()].length;
      if (std::abs(l - ref) <= kSameLength * ref) {
        classes.back().push_back(k);
        continue;
      }
    }
    classes.push_back({k});
  }
  return classes;
}

Eigen::VectorXd InitialState(const DynamicModel& model, const DynamicsConfig& config) {
  const int dim = model.dim, n_n = model.num_nodes(), c = dim * n_n;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(2 * c);
  for (int a = 0; a < n_n; ++a) {
    for (int d = 0; d < dim; ++d) y(a * dim + d) = model.positions(d, a);
  }
  const PerturbationConfig& p = config.perturbation;
  if (p.bar_class > 0) {
    const auto classes = BarLengthClasses(model);
    if (p.bar_class > static_cast<int>(classes.size())) {
      throw ConfigError("dynamics.perturbation.bar_class", std::to_string(p.bar_class),
                        "this bridge has bar length classes 1.." + std::to_string(classes.size()) +
                            " (1 = longest)");
    }
    std::vector<bool> moved(n_n, false);
    for (const int k : classes[p.bar_class - 1]) {
      for (const int a : {model.bars[k].i, model.bars[k].j}) {
        if (model.fixed[a] || moved[a]) continue;
        moved[a] = true;
        y(a * dim + 1) -= p.delta;
      }
    }
  }
  for (size_t k = 0; k < config.initial.size(); ++k) {
    const NodeInitialConfig& in = config.initial[k];
    const std::string key = "dynamics.initial[" + std::to_string(k) + "]";
    if (in.node > n_n) {
      throw ConfigError(key + ".node", std::to_string(in.node), "must be in 1.." + std::to_string(n_n));
    }
    const int a = in.node - 1;
    if (model.fixed[a]) throw ConfigError(key + ".node", std::to_string(in.node), "is a support; supports do not move");
    if (dim == 2 && (in.displacement[2] != 0 || in.velocity[2] != 0)) {
      throw ConfigError(key, "z component", "must be 0: this bridge moves in the x-y plane");
    }
    for (int d = 0; d < dim; ++d) {
      y(a * dim + d) += in.displacement[d];
      y(c + a * dim + d) += in.velocity[d];
    }
  }
  // Rigid bars: the initial state must respect their lengths and length rates.
  for (const DynamicBar& b : model.bars) {
    double len2 = 0, rate = 0, speed2 = 0;
    for (int d = 0; d < dim; ++d) {
      const double db = y(b.j * dim + d) - y(b.i * dim + d);
      const double dv = y(c + b.j * dim + d) - y(c + b.i * dim + d);
      len2 += db * db;
      rate += db * dv;
      speed2 += dv * dv;
    }
    const double len = std::sqrt(len2);
    const std::string name = std::to_string(b.i + 1) + "-" + std::to_string(b.j + 1);
    if (std::abs(len - b.length) > 1e-9 * b.length) {
      throw ConfigError("dynamics.initial", "bar " + name + " length " + Num(len) + " m",
                        "initial displacements must keep every bar's length " + Num(b.length) +
                            " m (move both ends of a bar together)");
    }
    if (std::abs(rate) > 1e-9 * len * std::max(std::sqrt(speed2), 1e-300) && speed2 > 0) {
      throw ConfigError("dynamics.initial", "bar " + name + " length rate " + Num(rate / len) + " m/s",
                        "initial velocities must keep every bar's length (relative velocity "
                        "of its ends perpendicular to it)");
    }
  }
  return y;
}

RunEstimate EstimateRun(const DynamicModel& model, const DynamicsConfig& config, double extra_bytes_per_record) {
  RunEstimate e;
  // As the driver counts them; a double first, since a typo can ask for more than a long holds.
  const double steps = std::max(1.0, std::ceil(config.duration / config.dt - 1e-9));
  e.steps = steps > 9e18 ? std::numeric_limits<long>::max() : static_cast<long>(steps);
  const double records = config.record.nodes.empty() ? 0.0 : std::floor(steps / config.record.every) + 1;
  e.records = records > 9e18 ? std::numeric_limits<long>::max() : static_cast<long>(records);
  const double values = records * (1.0 + model.dim * static_cast<double>(config.record.nodes.size()));
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
  const double steps = std::max(1.0, std::ceil(config.duration / config.dt - 1e-9));
  if (config.integrator != "dopri5" && steps > static_cast<double>(config.limits.max_steps)) {
    throw ConfigError("dynamics.duration", Num(config.duration),
                      "with dynamics.dt = " + Num(config.dt) + " s the run takes " + Num(steps) +
                          " steps, more than dynamics.limits.max_steps = " +
                          Num(static_cast<double>(config.limits.max_steps)) +
                          " allows: shorten the duration, enlarge dt, or raise dynamics.limits.max_steps");
  }
}

void CheckRunLimits(const DynamicModel& model, const DynamicsConfig& config, double extra_bytes_per_record) {
  CheckStepLimit(config);
  const RunEstimate e = EstimateRun(model, config, extra_bytes_per_record);
  const std::string duration = Num(config.duration);
  if (e.total_bytes() > config.limits.max_output_bytes) {
    throw ConfigError("dynamics.duration", duration,
                      "with dynamics.dt = " + Num(config.dt) + " s the run writes or holds about " +
                          Num(e.total_bytes()) + " bytes (history " + Num(e.history_bytes) + ", deck samples " +
                          Num(e.deck_bytes) + ", export " + Num(e.extra_bytes) +
                          "), more than dynamics.limits.max_output_bytes = " + Num(config.limits.max_output_bytes) +
                          " allows: record fewer nodes or samples (dynamics.record.every, dynamics.frequency.every), "
                          "shorten the run, or raise dynamics.limits.max_output_bytes");
  }
}

namespace {

// Integrates `config` with the engine `system` (Class1System or ClassKSystem, its adapter
// `Ode`) and fills `result`, whose recorded nodes are set.
template <class System, class Ode>
SimulationResult RunScenario(const DynamicModel& model, const DynamicsConfig& config,
                             const std::vector<PrestrainReport>& prestrain, const System& system,
                             SimulationResult result, std::chrono::steady_clock::time_point wall_start,
                             const RunHooks& hooks) {
  ProgressReporter* progress = hooks.progress;
  const int dim = model.dim;
  Ode ode(system);
  Eigen::VectorXd y = InitialState(model, config);
  // Bar forces from the run's own engine, in a workspace of their own (the integrator's holds
  // its stages).
  RunMonitor::BarForceProbe probe;
  if (config.record.bar_forces) {
    auto probe_ws = std::shared_ptr<decltype(MakeWorkspace(system))>(new auto(MakeWorkspace(system)));
    auto probe_dy = std::make_shared<Eigen::VectorXd>(system.state_size());
    probe = [&system, probe_ws, probe_dy](double t, const double* state, Eigen::VectorXd& lambda) {
      system.Derivative(t, state, probe_dy->data(), *probe_ws);
      system.BarForceDensities(*probe_ws, lambda);
    };
  }
  RunMonitor monitor(model, system, config, y, probe);
  const Eigen::VectorXd y_start = y;
  monitor.SetOmegaMax([&] { return HighestFrequency(ode, y_start).omega_max; });

  // Output grids: history every record.every steps, deck samples every frequency.every steps.
  const long total_steps = std::max<long>(1, std::lround(std::ceil(config.duration / config.dt - 1e-9)));
  const bool deck = config.frequency.enabled && !model.deck_nodes.empty();
  const int n_cols = 1 + dim * static_cast<int>(result.recorded_nodes.size());
  const bool recording = !result.recorded_nodes.empty();
  Sampler hist{config.dt * config.record.every, 0, 0};
  Sampler deck_s{config.dt * config.frequency.every, 0, 0};
  const bool streaming = !hooks.history.empty();
  Eigen::VectorXd row(n_cols);  // the row being taken, streamed
  if (recording && streaming) {
    for (HistorySink* sink : hooks.history) sink->Begin(model, result.recorded_nodes);
  }
  if (recording && !streaming) result.history.resize(total_steps / config.record.every + 2, n_cols);
  // Mirror-odd weights about mid-span (halfway between the outermost nodes).
  std::vector<double> odd_sign;
  if (deck) {
    const double mid = 0.5 * (model.positions.row(0).minCoeff() + model.positions.row(0).maxCoeff());
    const double span = model.positions.row(0).maxCoeff() - model.positions.row(0).minCoeff();
    for (const int a : model.deck_nodes) {
      const double x = model.positions(0, a) - mid;
      odd_sign.push_back(std::abs(x) <= 1e-9 * span ? 0.0 : (x > 0 ? -1.0 : 1.0));
    }
    const Eigen::Index samples = total_steps / config.frequency.every + 2;
    result.deck_even.resize(samples);
    result.deck_odd.resize(samples);
    result.deck_sample_dt = deck_s.spacing;
  }
  auto take_history = [&](double t, const Eigen::VectorXd& state) {
    if (!streaming && hist.rows >= result.history.rows()) return;
    row(0) = t;
    for (size_t k = 0; k < result.recorded_nodes.size(); ++k) {
      for (int d = 0; d < dim; ++d) row(1 + dim * k + d) = state(result.recorded_nodes[k] * dim + d);
    }
    if (streaming) {
      for (HistorySink* sink : hooks.history) sink->Row(t, row.data() + 1);
    } else {
      result.history.row(hist.rows) = row.transpose();
    }
    ++hist.rows;
  };
  auto take_deck = [&](const Eigen::VectorXd& state) {
    if (deck_s.rows >= result.deck_even.size()) return;
    double even = 0, odd = 0;
    for (size_t k = 0; k < model.deck_nodes.size(); ++k) {
      const int a = model.deck_nodes[k];
      const double u = state(a * dim + 1) - model.positions(1, a);
      even += u;
      odd += odd_sign[k] * u;
    }
    result.deck_even(deck_s.rows) = even;
    result.deck_odd(deck_s.rows) = odd;
    ++deck_s.rows;
  };
  if (recording) take_history(0.0, y);
  if (deck) take_deck(y);

  SimulationSummary& s = monitor.summary();
  s.engine = result.summary.engine;
  const IntegratorChoice choice = ResolveIntegrator(config.integrator, config.dt, ode, y);
  const std::string& integrator = choice.name;
  s.integrator = integrator;
  s.substeps = choice.substeps;
  if (integrator == "rk4" || integrator == "sdirk3") {
    Rk4Workspace ws(integrator == "rk4" ? system.state_size() : 0);
    std::unique_ptr<Sdirk3> sdirk;
    if (integrator == "sdirk3") sdirk = std::make_unique<Sdirk3>(CouplingOf(model), system.state_size());
    for (long step = 1; step <= total_steps; ++step) {
      const double t_old = (step - 1) * config.dt;
      const double t = step == total_steps ? config.duration : step * config.dt;
      if (system.has_timed_loads()) ode.HoldLoadsAt(0.5 * (t_old + t));
      double dissipated = std::numeric_limits<double>::quiet_NaN();  // SDIRK3: by the trapezoidal rule
      if (sdirk) {
        sdirk->Step(ode, t_old, t - t_old, y);
      } else {
        // Sub-steps share the step's held loads; the monitor sees the step's end state.
        const double h = (t - t_old) / choice.substeps;
        dissipated = 0;
        for (int k = 0; k < choice.substeps; ++k) dissipated += Rk4Step(ode, t_old + k * h, h, y, ws);
      }
      monitor.Accept(step, t_old, t, y.data(), dissipated);
      // A lock and two stores every 1024 steps: far below the cost of the steps.
      if (progress != nullptr && (step & 1023) == 0) progress->Update(t, config.duration);
      if (recording && step % config.record.every == 0) take_history(t, y);
      if (deck && step % config.frequency.every == 0) take_deck(y);
    }
    s.steps = static_cast<int>(total_steps);
    s.evaluations = sdirk ? sdirk->stats().evaluations : 4L * choice.substeps * total_steps;
  } else {
    Dopri5Options o;
    o.rtol = config.rtol;
    o.atol = config.atol;
    Dopri5 dp(o);
    Dopri5Workspace ws(system.state_size());
    Eigen::VectorXd out(system.state_size());
    double t = 0, h = config.dt;
    dp.Start(ode, t, y, ws);
    hist.next = deck_s.next = 1;
    int step = 0;
    while (t < config.duration) {
      const double t_old = t;
      if (step >= config.limits.max_steps) {
        throw ConfigError("dynamics.limits.max_steps", Num(static_cast<double>(config.limits.max_steps)),
                          "dopri5 used them all before t = " + Num(t) + " s of dynamics.duration = " +
                              Num(config.duration) + " s: raise the limit, or loosen dynamics.rtol and atol");
      }
      dp.Step(ode, t, y, h, config.duration, ws);
      monitor.Accept(++step, t_old, t, y.data(), dp.last_dissipated());
      if (progress != nullptr && (step & 1023) == 0) progress->Update(t, config.duration);
      // Dense output onto the uniform grids (within rounding of the end time).
      if (recording) {
        for (; hist.next * hist.spacing <= t * (1 + 1e-12); ++hist.next) {
          dp.Interpolate(hist.next * hist.spacing, ws, out);
          take_history(hist.next * hist.spacing, out);
        }
      }
      if (deck) {
        for (; deck_s.next * deck_s.spacing <= t * (1 + 1e-12); ++deck_s.next) {
          dp.Interpolate(deck_s.next * deck_s.spacing, ws, out);
          take_deck(out);
        }
      }
    }
    s.steps = dp.accepted();
    s.rejected = dp.rejected();
    s.evaluations = dp.evaluations();
  }
  if (progress != nullptr) progress->Update(config.duration, config.duration);
  if (recording && !streaming) result.history.conservativeResize(hist.rows, n_cols);
  if (deck) {
    // The samples with t <= duration, for the frequency and the summary alike.
    const Eigen::Index rows = SamplesWithin(deck_s.rows, deck_s.spacing, config.duration);
    result.deck_even.conservativeResize(rows);
    result.deck_odd.conservativeResize(rows);
  }

  monitor.Finish(y.data());
  s.duration = config.duration;
  s.prestrain = prestrain;
  if (config.frequency.enabled) {
    if (!deck) {
      s.frequency_note = "the model has no deck nodes";
    } else {
      try {
        const Eigen::VectorXd& even = result.deck_even;
        const Eigen::VectorXd& odd = result.deck_odd;
        s.frequency = DominantFrequency(even, result.deck_sample_dt);
        s.has_frequency = true;
        try {
          s.crossing_frequency = MeanPeriodFromCrossings(even, result.deck_sample_dt);
        } catch (const std::invalid_argument&) {
          // fewer than three crossings: a record shorter than a period; the spectral estimate stands alone
        }
        const auto spread = [](const Eigen::VectorXd& v) { return (v.array() - v.mean()).abs().maxCoeff(); };
        if (spread(odd) > 1e-6 * spread(even)) {
          try {
            s.antisymmetric_frequency = DominantFrequency(odd, result.deck_sample_dt);
          } catch (const std::invalid_argument&) {
            // no dominant peak in a record this short
          }
        }
      } catch (const std::invalid_argument& e) {
        s.frequency_note = std::string("no deck frequency: ") + e.what();
      }
    }
  }
  s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.summary = s;
  return result;
}

}  // namespace

namespace {

// Both engines take the same stabilisation settings.
EngineOptions EngineOptionsOf(const DynamicsConfig& config) {
  EngineOptions options;
  options.stabilisation = config.stabilisation.enabled;
  options.omega_rad_s = config.stabilisation.omega_rad_s;
  options.zeta = config.stabilisation.zeta;
  return options;
}

}  // namespace

double Rk4StableStep(const DynamicModel& model, const DynamicsConfig& config) {
  const EngineOptions options = EngineOptionsOf(config);
  const Eigen::VectorXd y = InitialState(model, config);
  if (EngineFor(model, config) == "class1") {
    const Class1System system(model, options);
    Class1Ode ode(system);
    return kAutoRk4Fraction * Rk4StepLimit(HighestFrequency(ode, y).omega_max);
  }
  const ClassKSystem system(model, options);
  ClassKOde ode(system);
  return kAutoRk4Fraction * Rk4StepLimit(HighestFrequency(ode, y).omega_max);
}

SimulationResult Simulate(const DynamicModel& model, const DynamicsConfig& config,
                          const std::vector<PrestrainReport>& prestrain, const RunHooks& hooks) {
  CheckRunLimits(model, config, hooks.extra_bytes_per_record ? hooks.extra_bytes_per_record(model) : 0.0);
  const auto wall_start = std::chrono::steady_clock::now();
  const int dim = model.dim, n_n = model.num_nodes();

  std::vector<TimedLoad> timed;
  for (size_t k = 0; k < config.loads.size(); ++k) {
    const LoadStepConfig& l = config.loads[k];
    const std::string key = "dynamics.loads[" + std::to_string(k) + "]";
    if (l.node > n_n) throw ConfigError(key + ".node", std::to_string(l.node), "must be in 1.." + std::to_string(n_n));
    if (dim == 2 && l.force[2] != 0) throw ConfigError(key + ".force", Num(l.force[2]), "z must be 0 for a planar bridge");
    timed.push_back({l.t_start, l.t_end, l.node - 1, Eigen::Vector3d(l.force[0], l.force[1], l.force[2]), l.rise_s,
                     l.fall_s});
  }
  SimulationResult result;
  result.dim = dim;
  for (const int node : config.record.nodes) {
    if (node > n_n) throw ConfigError("dynamics.record.nodes", std::to_string(node), "must be in 1.." + std::to_string(n_n));
    result.recorded_nodes.push_back(node - 1);
  }

  const std::string engine = EngineFor(model, config);
  result.summary.engine = engine;
  const EngineOptions options = EngineOptionsOf(config);
  if (engine == "class1") {
    const Class1System system(model, options, timed);
    return RunScenario<Class1System, Class1Ode>(model, config, prestrain, system, std::move(result),
                                                wall_start, hooks);
  }
  const ClassKSystem system(model, options, timed);
  return RunScenario<ClassKSystem, ClassKOde>(model, config, prestrain, system, std::move(result),
                                              wall_start, hooks);
}

}  // namespace tbridge
