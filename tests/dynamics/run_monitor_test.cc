// The run monitor measures each string from the geometry an engine evaluation recorded at the
// accepted state (the next RK4 step's first stage) or, without it, from the state itself:
// two paths that must give one summary.

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/config.h"
#include "dynamics/class1.h"
#include "dynamics/initial_state.h"
#include "dynamics/integrator_policy.h"
#include "dynamics/run_monitor.h"
#include "dynamics/simulation.h"
#include "dynamics/structure_model.h"

namespace tbridge {
namespace {

// The largest relative difference between a and b, over all entries.
double Gap(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300}); }

void CheckOneSummary(const std::string& label, double damping, const std::vector<int>& pinned) {
  INFO(label);
  Config c = LoadConfig(TBRIDGE_SOURCE_DIR "/configs/motes_prism.json");
  for (StructureStringConfig& s : c.structure->strings) s.damping_n_s_m = damping;
  c.structure->pinned = pinned;
  const DynamicsConfig& config = *c.dynamics;
  const DynamicModel model = BuildStructureModel(*c.structure, ModelOptionsOf(config));
  const Class1System engine(model, EngineOptionsOf(config));
  Class1Ode ode(engine);
  Eigen::VectorXd y = InitialState(model, config);
  RunMonitor given(model, engine, config, y), own(model, engine, config, y);
  Rk4Workspace ws(engine.state_size());
  Eigen::VectorXd scratch(engine.state_size());
  const double dt = config.dt;
  for (long step = 1; step <= 3000; ++step) {
    const double t_old = (step - 1) * dt, t = step * dt;
    const double dissipated = Rk4Step(ode, t_old, dt, y, ws);
    ode.RecordStringsInNextEvaluation(given.string_geometry());
    ode.Derivative(t, y.data(), scratch.data());
    given.Accept(step, t_old, t, y.data(), dissipated, true);
    own.Accept(step, t_old, t, y.data(), dissipated);
  }
  given.Finish(y.data());
  own.Finish(y.data());
  const SimulationSummary& a = given.summary();
  const SimulationSummary& b = own.summary();
  REQUIRE(b.slack.total > 0);  // the strings went slack and taut again: both branches ran
  // Both paths evaluate the same expressions on the same state (the engine's s . s, 1/|s| and
  // s . s_dot are the monitor's own), so they agree to the last bits; 1e-14 leaves room for a
  // compiler that contracts a product and a sum into one rounding in one place only.
  const double tol = 1e-14;
  double worst = 0;
  for (size_t k = 0; k < b.peak_string_tension.size(); ++k) {
    worst = std::max({worst, Gap(a.peak_string_tension[k], b.peak_string_tension[k]),
                      Gap(a.min_string_strain[k], b.min_string_strain[k])});
  }
  worst = std::max({worst, Gap(a.max_string_stress, b.max_string_stress), Gap(a.energy.elastic_end, b.energy.elastic_end),
                    Gap(a.energy.max_drift, b.energy.max_drift), Gap(a.max_bar_length_error, b.max_bar_length_error)});
  CHECK(worst <= tol);
  CHECK(a.slack.per_string == b.slack.per_string);  // counts: exactly
  CHECK(a.slack.total == b.slack.total);
  CHECK(a.slack.ever_slack == b.slack.ever_slack);
  CHECK(a.max_stress_string == b.max_stress_string);
  CHECK(a.max_stress_time == b.max_stress_time);
}

TEST_CASE("run monitor: an engine's recorded string geometry gives the summary of the monitor's own pass") {
  CheckOneSummary("damped MOTES prism", 10.0, {});
  CheckOneSummary("undamped", 0.0, {});
  // Nodes 1 and 7 pinned: string 1-7 moves nothing, so no engine evaluates it; the monitor
  // keeps its geometry from the start.
  CheckOneSummary("damped, one string pinned at both ends", 10.0, {1, 7});
}

}  // namespace
}  // namespace tbridge
