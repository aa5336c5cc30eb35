// The design's dynamic check against a separate run of the same load through tbridge
// simulate's path (RunScenario with the verified design): the paper's travelling load on the
// design that tbridge design writes.

#include "checks/dynamic_check.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "app/scenario.h"
#include "bridge/design_model.h"
#include "checks/load_scenarios.h"
#include "checks/verdict.h"
#include "core/config.h"
#include "core/error.h"
#include "design/static_model.h"
#include "dynamics/simulation.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

// A run's largest member force in `group` (bar compression, string tension) [N], as the check
// groups its peaks.
double GroupPeak(const Structure& st, const SimulationSummary& s, MemberGroup group) {
  double peak = 0;
  for (int b = 0; b < st.num_bars(); ++b) {
    if (st.bars[b].group == group) peak = std::max(peak, s.peak_bar_compression[b]);
  }
  for (int k = 0; k < st.num_strings(); ++k) {
    if (st.strings[k].group == group) peak = std::max(peak, s.peak_string_tension[k]);
  }
  return peak;
}

TEST_CASE("the design's dynamic check is what a separate run of the paper's travelling load gives",
          "[verify][dynamics]") {
  // The three shipped engineering configs, each designed and then run separately.
  const std::string name =
      GENERATE(as<std::string>{}, "default", "footbridge_steel_40m", "footbridge_aluminium_20m");
  INFO("config " << name);
  Config config = LoadConfig(std::string(TBRIDGE_SOURCE_DIR) + "/configs/" + name + ".json");
  // The paper's travelling load is checked when a config asks for it, as this one now does.
  config.loads.cases.push_back(LoadFamily::kPaperTravelling);
  const Design d = DesignAndVerify(config);
  REQUIRE(d.dynamics.ran());
  const DynamicRun& check = d.dynamics.runs.front();
  REQUIRE(check.name == "paper_travelling");
  REQUIRE(check.done);
  REQUIRE(DesignVerdict(d).pass);

  // The paper's eqs 50-51 as a dynamics section a user would write: f on each inner deck
  // node in turn for 0.25 s, RK4 at the check's step, bar forces recorded.
  DynamicsConfig run;
  const int stations = static_cast<int>(d.topology.deck_nodes.size());
  run.duration = 0.25 * stations;
  run.dt = check.dt;
  run.integrator = IntegratorKind::kRk4;
  run.frequency.enabled = false;
  run.record.bar_forces = true;
  run.gravity_on_structure = true;   // follows design.self_weight, as the parse would set it
  run.stabilisation.enabled = true;  // the check's runs hold the bar lengths
  for (int k = 0; k < stations; ++k) {
    run.loads.push_back(
        {0.25 * k, 0.25 * (k + 1), d.topology.deck_nodes[k] + 1, {0, -d.deck.node_load, 0}});
  }
  config.dynamics = run;
  const ScenarioResult r =
      RunScenario(config, {}, {}, [](const Config& c) { return DesignAndVerify(c); });
  const SimulationSummary& s = r.simulation.summary;

  // The same design: the separate run designed it again, deterministically.
  REQUIRE(r.design.mass.structure == d.mass.structure);
  // Its peaks, grouped as the check groups them, are the check's: 1e-12 relative, the same
  // run done twice (rounding of nothing but identical operations).
  const Structure& st = d.topology.structure;
  for (const GroupAmplification& g : check.groups) {
    const double peak = GroupPeak(st, s, g.group);
    INFO("group " << NameOf(g.group));
    CHECK(peak == Approx(g.dynamic_peak).epsilon(1e-12));
  }
  // And the run confirms the design holds: no member past its resistance at service level
  // (the check's factored demand is the stricter one), and no string that must stay taut (the
  // deck chain) goes slack; others may, and the run carries the load without them.
  for (int k = 0; k < st.num_strings(); ++k) {
    INFO("string " << d.strings[k].name);
    if (MustStayTaut(d, k)) CHECK(s.min_string_strain[k] >= 0);
  }
  CHECK(s.max_string_stress <=
        d.config.material.yield_stress / d.config.design.yield_safety_factor);
  CHECK(DesignVerdict(r.design).utilisation_max <= 1.0 + 1e-9);
}

// The default config's first design at complexity n, its dynamic check (the walking load
// alone, done by the nonlinear run) and the model the check runs it on.
struct MovingLoadCheck {
  Config config;
  Design design;
  DynamicCheck check;
  DynamicModel model;
  const DynamicRun& run() const { return check.runs.front(); }
};

MovingLoadCheck CheckMovingLoad(int n) {
  MovingLoadCheck c;
  c.config.bridge.n = n;
  c.config.loads.dynamic_method = DynamicMethod::kRk4;
  c.design = RunDesign(c.config);
  c.check = CheckDynamics(c.design);
  REQUIRE(c.check.runs.size() == 1);
  REQUIRE(c.run().name == "moving_load");
  REQUIRE(c.run().done);
  ModelOptions options;
  options.gravity_on_structure = true;
  options.deck_inertia = true;
  c.model = BuildDynamicModel(c.design, options);
  return c;
}

TEST_CASE("the dynamic check's static counterparts are the load standing at each station in turn",
          "[verify][dynamics]") {
  // The moving load of the default config at n = 2, its run done; the check forms each
  // station's load in place. Against it: every station's full load matrix (Actions::
  // StationLoad) on the run's standing loads, solved one by one, and the standing loads alone.
  const MovingLoadCheck c = CheckMovingLoad(2);
  const Config& config = c.config;
  const Design& d = c.design;
  const DynamicRun& run = c.run();
  const DynamicModel& model = c.model;
  const StaticModel statics = StaticModelOf(d);
  const StaticState start = ReferenceState(statics, d);
  const Structure& st = d.topology.structure;
  std::vector<Eigen::Matrix3Xd> loads{model.loads};
  for (int k = 0; k < static_cast<int>(d.actions.station_nodes.size()); ++k) {
    loads.push_back(model.loads + d.actions.StationLoad(k, config.loads.travelling_load_n));
  }
  REQUIRE(loads.size() > 2);
  std::map<MemberGroup, double> peak;
  for (const Eigen::Matrix3Xd& l : loads) {
    const StaticResult r = SolveStatic(statics, start, d.loads, l);
    REQUIRE(r.converged);
    for (int b = 0; b < st.num_bars(); ++b)
      peak[st.bars[b].group] = std::max(peak[st.bars[b].group], r.state.bar_compression[b]);
    for (int k = 0; k < st.num_strings(); ++k) {
      peak[st.strings[k].group] = std::max(peak[st.strings[k].group], r.state.string_tension[k]);
    }
  }
  REQUIRE(run.groups.size() == peak.size());
  for (const GroupAmplification& g : run.groups) {
    INFO("group " << NameOf(g.group));
    REQUIRE(peak.count(g.group) == 1);
    REQUIRE(g.static_peak > 0);
    // 1e-10 relative: the same loads (a + (-f) and a - f round alike), solved here from the
    // reference state and by the check from the last station's equilibrium, both stopped where
    // the forces balance to 1e-10 of the largest force (a group's peak is among the largest;
    // 1.1e-12 found).
    CHECK(g.static_peak == Approx(peak[g.group]).epsilon(1e-10));
  }
}

TEST_CASE("a dynamic run over the budget at its asked step is skipped before its model is built",
          "[verify][dynamics]") {
  Config config;
  config.bridge.n = 2;
  config.loads.dynamic_method = DynamicMethod::kRk4;  // the budget is the nonlinear run's
  const Design d = RunDesign(config);
  const DynamicCheck full = CheckDynamics(d);
  REQUIRE(full.runs.size() == 1);
  REQUIRE(full.runs.front().done);
  // The run's member-steps at the asked step (the scenario's 1e-4 s), which here is stable; the
  // crossing, (span + contact length) / speed, is no whole number of steps: the last is short.
  const double members = static_cast<double>(d.bars.size() + d.strings.size());
  const double asked = full.runs.front().duration / 1e-4 * members;
  REQUIRE(full.runs.front().steps == static_cast<long>(std::ceil(asked / members)));
  // Below it: skipped up front, the note naming the asked step.
  const DynamicCheck early = CheckDynamics(d, 0.5 * asked);
  REQUIRE(early.runs.size() == 1);
  CHECK_FALSE(early.runs.front().done);
  CHECK(early.Status() == CheckStatus::kNotRun);
  CHECK(early.runs.front().note.find("the asked step") != std::string::npos);
  // At it (and a hair above, for the rounding of the step count): not skipped, done as with
  // the default budget, to the same peaks.
  const DynamicCheck exact = CheckDynamics(d, asked * (1 + 1e-9));
  REQUIRE(exact.runs.front().done);
  CHECK(exact.runs.front().steps == full.runs.front().steps);
  CHECK(exact.members.front().utilisation == full.members.front().utilisation);
}

TEST_CASE("a dynamic check whose bridge has no standing equilibrium says so for each run",
          "[verify][dynamics]") {
  // Every string half again as long as designed: slack under the run's standing loads, the
  // bridge a mechanism, so the runs have no equilibrium to start from. The check says so for
  // each run and is not complete (the verdict reads INCOMPLETE); it does not stop the design.
  Config config;
  config.bridge.n = 2;
  Design d = RunDesign(config);
  for (MemberSizing& s : d.strings) s.rest_length *= 1.5;
  // The premise: the run's model itself finds no equilibrium.
  REQUIRE_THROWS_AS(BuildDynamicModel(d, DynamicCheckModelOptions(d, {})), ModelError);
  DynamicCheck check;
  REQUIRE_NOTHROW(check = CheckDynamics(d));
  REQUIRE(check.runs.size() == 1);
  CHECK_FALSE(check.runs.front().done);
  CHECK(check.runs.front().note.find("initial static equilibrium") != std::string::npos);
  CHECK(check.Status() == CheckStatus::kNotRun);
}

TEST_CASE("a dynamic check not run says so for each run and its design never passes",
          "[verify][dynamics]") {
  // The sizing's record of a design whose static check fails by far (sizing/verified_design.cc):
  // every run the check would do, not done, with the reason; every member without a finding.
  Config config;
  config.bridge.n = 2;
  Design d = RunDesign(config);
  const DynamicCheck full = CheckDynamics(d);
  REQUIRE(full.runs.size() == 1);
  REQUIRE(full.runs.front().done);
  const DynamicCheck skipped =
      DynamicCheckNotRun(d, "not run: the static check fails by more than 10 %");
  REQUIRE(skipped.runs.size() == full.runs.size());
  CHECK(skipped.runs.front().name == full.runs.front().name);
  CHECK_FALSE(skipped.runs.front().done);
  CHECK(skipped.runs.front().note == "not run: the static check fails by more than 10 %");
  CHECK(skipped.Status() == CheckStatus::kNotRun);
  REQUIRE(skipped.members.size() == d.bars.size() + d.strings.size());
  for (const MemberFinding& f : skipped.members) CHECK(f.utilisation == 0);
  // Recorded on a design: its verdict names the run not done. The equilibrium design passes
  // its other checks here, so it is INCOMPLETE; with a member over its resistance, FAIL.
  d.dynamics = skipped;
  const Verdict incomplete = DesignVerdict(d);
  CHECK(incomplete.outcome == VerdictOutcome::kIncomplete);
  CHECK(incomplete.summary.find("moving_load not run") != std::string::npos);
  d.bars.front().utilisation = 1.2;
  CHECK(DesignVerdict(d).outcome == VerdictOutcome::kFail);
}

TEST_CASE("the dynamic check's stabilised bar lengths leave the peaks of a run that needs none",
          "[verify][dynamics]") {
  // The default bridge's walking load at n = 3 (RK4 at 1e-4 s, stable; the bar lengths drift
  // by far less than the guard allows over its 8 s), run unstabilised as a user's dynamics
  // section would: the stabilisation's force acts on the length error alone, so the check's
  // peaks are this run's.
  const MovingLoadCheck c = CheckMovingLoad(3);
  const Design& d = c.design;
  const DynamicRun& done = c.run();
  const LoadsConfig& l = c.config.loads;
  DynamicsConfig run = MovingLoadScenario(d, l.travelling_load_n, TravellingCrossing(d), done.dt);
  REQUIRE_FALSE(run.stabilisation.enabled);
  const SimulationSummary s = Simulate(c.model, run).summary;
  // 1e-9 relative: what the stabilisation changes is of the order of the unstabilised run's
  // bar-length drift (the peaks differ by 5e-11 here); a stabilisation that moved the motion
  // itself (a force on the exact trajectory) shows at 1e-4 and above.
  CHECK(s.peak_deck_displacement[1] == Approx(done.peak_deck_displacement).epsilon(1e-9));
  const Structure& st = d.topology.structure;
  for (const GroupAmplification& g : done.groups) {
    const double peak = GroupPeak(st, s, g.group);
    INFO("group " << NameOf(g.group) << ": " << peak << " against " << g.dynamic_peak);
    CHECK(peak == Approx(g.dynamic_peak).epsilon(1e-9));
  }
}

}  // namespace
}  // namespace tbridge
