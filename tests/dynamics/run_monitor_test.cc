// The run monitor measures each string from the geometry an engine evaluation recorded at the
// accepted state (the next RK4 step's first stage) or, without it, from the state itself:
// two paths that must give one summary.

#include "dynamics/run_monitor.h"

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "core/config.h"
#include "dynamics/class1.h"
#include "dynamics/initial_state.h"
#include "dynamics/integrator_policy.h"
#include "dynamics/simulation.h"
#include "dynamics/structure_model.h"

namespace tbridge {
namespace {

// The largest relative difference between a and b, over all entries.
double Gap(double a, double b) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300});
}

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
  given.Finish();
  own.Finish();
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
  worst = std::max({worst, Gap(a.max_string_stress, b.max_string_stress),
                    Gap(a.energy.elastic_end, b.energy.elastic_end),
                    Gap(a.energy.max_drift, b.energy.max_drift),
                    Gap(a.max_bar_length_error, b.max_bar_length_error)});
  CHECK(worst <= tol);
  CHECK(a.slack.per_string == b.slack.per_string);  // counts: exactly
  CHECK(a.slack.total == b.slack.total);
  CHECK(a.slack.ever_slack == b.slack.ever_slack);
  CHECK(a.max_stress_string == b.max_stress_string);
  CHECK(a.max_stress_time == b.max_stress_time);
}

TEST_CASE(
    "run monitor: an engine's recorded string geometry gives the summary of the monitor's own "
    "pass") {
  CheckOneSummary("damped MOTES prism", 10.0, {});
  CheckOneSummary("undamped", 0.0, {});
  // Nodes 1 and 7 pinned: string 1-7 moves nothing, so no engine evaluates it; the monitor
  // keeps its geometry from the start.
  CheckOneSummary("damped, one string pinned at both ends", 10.0, {1, 7});
}

// The summary recomputed from the run's history of every node at every step, string by string
// and step by step in plain scalar loops (|s| by a square root, where the monitor multiplies
// s . s by the engine's 1/|s|): a second algorithm for what the monitor's vector pass finds.
// Undamped, so that a tension is a function of the positions alone.
TEST_CASE("run monitor: the summary is the one recomputed from the run's every-step history") {
  Config c = LoadConfig(TBRIDGE_SOURCE_DIR "/configs/motes_prism.json");
  for (StructureStringConfig& s : c.structure->strings) {
    s.damping_n_s_m = 0.0;
    s.area_m2 = 1e-6;  // a stress to find
  }
  c.structure->allowed_stress_pa = 1e9;
  c.structure->deck_nodes = {1, 5, 11, 18};
  DynamicsConfig config = *c.dynamics;
  config.duration = 2.0;
  config.record.every = 1;
  config.record.nodes.clear();
  for (int a = 1; a <= static_cast<int>(c.structure->nodes.size()); ++a)
    config.record.nodes.push_back(a);
  const DynamicModel model = BuildStructureModel(*c.structure, ModelOptionsOf(config));
  const SimulationResult result = Simulate(model, config);
  const SimulationSummary& s = result.summary;
  const auto& h = result.history;
  REQUIRE(h.rows() == s.steps + 1);  // the start and every step
  const int dim = model.dim;
  const auto x = [&](Eigen::Index row, int node, int d) { return h(row, 1 + dim * node + d); };

  const size_t n_s = model.strings.size();
  std::vector<double> peak(n_s, 0.0), min_ratio(n_s, 1e300);
  std::vector<int> transitions(n_s, 0);
  std::vector<char> taut_before(n_s, 0), ever_slack(n_s, 0);
  double max_stress = 0, elastic_end = 0;
  int slack_at_start = 0, slack_at_end = 0;
  std::array<double, 3> deck_peak{0, 0, 0};
  for (Eigen::Index row = 0; row < h.rows(); ++row) {
    double elastic = 0;
    for (size_t k = 0; k < n_s; ++k) {
      const DynamicString& st = model.strings[k];
      double len2 = 0;
      for (int d = 0; d < dim; ++d) {
        const double dx = x(row, st.j, d) - x(row, st.i, d);
        len2 += dx * dx;
      }
      const bool taut = len2 >= st.rest_length * st.rest_length;  // the contract's slack test
      const double len = std::sqrt(len2);
      const double tension = taut ? st.stiffness * std::max(len - st.rest_length, 0.0) : 0.0;
      if (taut) elastic += 0.5 * tension * (len - st.rest_length);
      peak[k] = std::max(peak[k], tension);
      max_stress = std::max(max_stress, tension / model.strings.area[k]);
      min_ratio[k] = std::min(min_ratio[k], len / st.rest_length);
      if (row > 0 && static_cast<char>(taut) != taut_before[k]) ++transitions[k];
      taut_before[k] = taut;
      if (!taut) ever_slack[k] = 1;
      if (!taut && row == 0) ++slack_at_start;
      if (!taut && row == h.rows() - 1) ++slack_at_end;
    }
    elastic_end = elastic;
    for (const int a : model.deck_nodes) {
      for (int d = 0; d < dim; ++d) {
        deck_peak[d] = std::max(deck_peak[d], std::abs(x(row, a, d) - model.positions(d, a)));
      }
    }
  }
  // Counts: exactly (both sides compare the same s . s, summed in the same order, with L0^2).
  REQUIRE(s.slack.total > 0);  // the premise: strings do go slack and taut again
  CHECK(s.slack.per_string == transitions);
  CHECK(s.slack.ever_slack == std::count(ever_slack.begin(), ever_slack.end(), 1));
  CHECK(s.slack.slack_at_start == slack_at_start);
  CHECK(s.slack.slack_at_end == slack_at_end);
  // Values: |s| here by a square root, in the monitor as s . s times 1/|s|: a few ulps of |s|
  // (1e-16 m), and |s| - L0 is at least 1e-3 m where a peak is taken, so 1e-12 relative.
  const double tol = 1e-12;
  for (size_t k = 0; k < n_s; ++k) {
    CHECK(s.peak_string_tension[k] == Approx(peak[k]).epsilon(tol).margin(1e-12));
    CHECK(s.min_string_strain[k] == Approx(min_ratio[k] - 1.0).margin(1e-12));
  }
  CHECK(s.max_string_stress == Approx(max_stress).epsilon(tol));
  CHECK(s.energy.elastic_end == Approx(elastic_end).epsilon(tol));
  // The named string and time: the prism is three-fold symmetric, so which of equal strings is
  // named rests on rounding; what must hold is that the named one reaches the peak then.
  {
    size_t k = 0;
    while (k < n_s && model.names.string_name[k] != s.max_stress_string) ++k;
    REQUIRE(k < n_s);
    const Eigen::Index row = std::lround(s.max_stress_time / config.dt);
    const DynamicString& st = model.strings[k];
    double len2 = 0;
    for (int d = 0; d < dim; ++d) len2 += std::pow(x(row, st.j, d) - x(row, st.i, d), 2);
    CHECK(st.stiffness * (std::sqrt(len2) - st.rest_length) / model.strings.area[k] ==
          Approx(max_stress).epsilon(tol));
  }
  for (int d = 0; d < dim; ++d) {
    INFO("axis " << d);
    CHECK(s.peak_deck_displacement[d] == Approx(deck_peak[d]).epsilon(tol));
    const int a = s.peak_deck_node[d];
    REQUIRE(std::find(model.deck_nodes.begin(), model.deck_nodes.end(), a) !=
            model.deck_nodes.end());
    const Eigen::Index row = std::lround(s.peak_deck_time[d] / config.dt);
    CHECK(std::abs(x(row, a, d) - model.positions(d, a)) == Approx(deck_peak[d]).epsilon(tol));
  }
}

}  // namespace
}  // namespace tbridge
