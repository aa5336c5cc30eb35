// Numerical stress: long runs, slack chatter, extreme prestrain, geometry and loads, the largest
// bridge, and steps too large to be stable. Tagged [stress]: ctest runs them as one entry
// labelled `stress` (tests/CMakeLists.txt), outside the quick per-test discovery.

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "bridge/design_model.h"
#include "core/config.h"
#include "core/error.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "dynamics/step_size.h"

namespace tbridge {
namespace {

DynamicsConfig Run(double duration, double dt, double delta,
                   IntegratorKind integrator = IntegratorKind::kRk4) {
  DynamicsConfig c;
  c.duration = duration;
  c.dt = dt;
  c.integrator = integrator;
  c.perturbation = {1, delta};
  c.frequency.enabled = false;
  c.deck_inertia = false;  // the paper's runs, whose behaviour the bounds below were measured on
  return c;
}

// RK4's stability limit of `model` at rest.
double Rk4Limit(const DynamicModel& model) {
  const Class1System system(model);
  Class1Ode ode(system);
  return Rk4StepLimit(HighestFrequency(ode, system.RestState()).omega_max);
}

void Describe(const std::string& what, const SimulationSummary& s) {
  UNSCOPED_INFO(what << ": " << s.steps << " steps, bar-length error " << s.max_bar_length_error
                     << ", energy drift " << s.energy.max_drift << " (final "
                     << s.energy.final_drift << "), slack transitions " << s.slack.total
                     << ", wall " << s.wall_seconds << " s");
}

TEST_CASE("1e6 RK4 steps: bar lengths and energy stay bounded", "[stress]") {
  Config c;
  ApplyPaperSwitches(c);
  c.bridge.n = 1;
  const DynamicModel m = BuildDynamicModel(RunDesign(c));
  // The paper's n = 1 run (periodic slack bouncing) for 10 s at dt = 1e-5: 1e6 steps, 85
  // periods.
  const SimulationSummary plain = Simulate(m, Run(10.0, 1e-5, 0.1)).summary;
  DynamicsConfig stab = Run(10.0, 1e-5, 0.1);
  stab.stabilisation.enabled = true;
  const SimulationSummary stabilised = Simulate(m, stab).summary;
  Describe("plain", plain);
  Describe("stabilised", stabilised);
  CHECK(plain.steps == 1000000);
  // Without stabilisation the bar length drifts with the per-step truncation error: measured
  // 1.6e-11 relative after 1e6 steps; the bound 1e-9 (12 nm on the 12 m bar) leaves 60x.
  CHECK(plain.max_bar_length_error < 1e-9);
  // Stabilisation holds h = b.b - l0^2 to rounding: measured 7.6e-15.
  CHECK(stabilised.max_bar_length_error < 1e-12);
  // Energy: RK4 at omega_max dt = 0.023 errs by O(dt^4) per step and across each of the 340
  // slack transitions (kinks inside a step); measured 3.8e-8 of the initial energy. Bound 1e-6.
  CHECK(plain.energy.max_drift < 1e-6);
  CHECK(stabilised.energy.max_drift < 1e-6);
}

TEST_CASE("slack chatter: thousands of slack crossings, no spurious energy gain", "[stress]") {
  // Low prestress (deck strings at their stretched length: no deck prestress) and a large
  // push (0.2 m) on n = 3: strings go slack and re-tension thousands of times.
  Config c;
  ApplyPaperSwitches(c);
  c.bridge.n = 3;
  ModelOptions o;
  o.prestrain = {{MemberGroup::kDeck, 1.0}};
  const DynamicModel m = BuildDynamicModel(RunDesign(c), o);
  const SimulationSummary s = Simulate(m, Run(1.0, 5e-6, 0.2)).summary;
  Describe("chatter", s);
  CHECK(s.slack.total > 1000);  // the premise
  // A slack kink inside a step costs O(dt^2) of energy per crossing, of either sign; over
  // ~24000 crossings the measured worst is 2.7e-4 of the initial energy. Bound: no gain above
  // 1e-3, ever.
  CHECK(s.energy.max_drift < 1e-3);
  CHECK(s.max_bar_length_error < 1e-3);  // the default guard (measured 2.8e-4)
}

TEST_CASE("extreme prestrain p = 0.9 runs at its own stable step", "[stress]") {
  Config c;
  ApplyPaperSwitches(c);
  c.bridge.n = 2;
  ModelOptions o;
  o.prestrain = {{MemberGroup::kDeck, 0.9}};
  const DynamicModel m = BuildDynamicModel(RunDesign(c), o);
  const double limit = Rk4Limit(m);
  const SimulationSummary s = Simulate(m, Run(0.2, limit / 8, 0.05)).summary;
  Describe("p = 0.9, dt = limit/8 = " + std::to_string(limit / 8), s);
  // The prestrained deck strings are 10x stiffer in strain and go slack 559 times in 0.2 s:
  // measured 1.5e-4 bar-length error and 4e-6 energy drift. Bounds: the default guard 1e-3,
  // and 1e-4 of the energy.
  CHECK(s.max_bar_length_error < 1e-3);
  CHECK(s.energy.max_drift < 1e-4);
}

// An extreme design run for 0.05 s at a step of an eighth of its RK4 limit, perturbed by
// 1 mm, must behave like any other run: bar-length error (measured <= 2e-9) within a tenth of
// the default guard, energy drift (measured <= 4e-5) below 1e-3.
void CheckBehavesLikeAnyRun(const Config& c, const std::string& label) {
  const DynamicModel m = BuildDynamicModel(RunDesign(c));
  const double limit = Rk4Limit(m);
  const SimulationSummary s = Simulate(m, Run(0.05, limit / 8, 1e-3)).summary;
  Describe(label + ", dt = " + std::to_string(limit / 8), s);
  CHECK(s.max_bar_length_error < 1e-4);
  CHECK(s.energy.max_drift < 1e-3);
}

TEST_CASE("extreme geometry: beta = 1 and 80 degrees", "[stress]") {
  for (const double beta : {1.0, 80.0}) {
    Config c;
    ApplyPaperSwitches(c);
    c.bridge.n = 3;
    c.bridge.beta_deg = beta;
    CheckBehavesLikeAnyRun(c, "beta = " + std::to_string(beta));
  }
}

TEST_CASE("very heavy and very light loads", "[stress]") {
  for (const double payload : {1.2e2, 1.2e7}) {
    Config c;
    ApplyPaperSwitches(c);
    c.bridge.n = 3;
    c.bridge.payload = payload;
    CheckBehavesLikeAnyRun(c, "payload " + std::to_string(payload) + " N");
  }
}

TEST_CASE("n = 12: design and a short run with the automatic integrator", "[stress]") {
  Config c;
  ApplyPaperSwitches(c);
  c.bridge.n = 12;
  const DynamicModel m = BuildDynamicModel(RunDesign(c));
  // From the design state, under the design loads: 1e-4 s is ~250x RK4's limit here (more
  // RK4 sub-steps than an SDIRK3 step costs), so "auto" must take the implicit path, and the
  // designed equilibrium must hold. (A push of the central bar sets strings chattering, where
  // the history is chaotic from n = 9 on and SDIRK3 no fallback: BENCHMARKS.md.)
  const SimulationSummary s = Simulate(m, Run(2e-3, 1e-4, 0.0, IntegratorKind::kAuto)).summary;
  Describe("n = 12", s);
  CHECK(s.integrator == "sdirk3");
  CHECK(s.steps == 20);
  // At rest only the design's equilibrium residual and Newton's tolerance move anything:
  // measured 1.3e-6 relative; a hundredth of the default guard bounds it.
  CHECK(s.max_bar_length_error < 1e-5);
  CHECK(s.slack.total == 0);  // nothing moved enough to slacken a string
}

TEST_CASE("a step too large stops with the step, the time and a safe dt", "[stress]") {
  Config c;
  ApplyPaperSwitches(c);
  c.bridge.n = 3;
  const DynamicModel m = BuildDynamicModel(RunDesign(c));
  const double limit = Rk4Limit(m);  // 2.8e-4 s (SPEC.md §9)
  try {
    Simulate(m, Run(0.5, 4 * limit, 0.1));
    FAIL("the run at 4x the RK4 limit did not stop");
  } catch (const ModelError& e) {
    const std::string what = e.what();
    INFO(what);
    CHECK_THAT(what, Catch::Contains("step") && Catch::Contains("t = ") && Catch::Contains("dt"));
    CHECK_THAT(what, Catch::Contains("highest linearised frequency"));
  }
}

}  // namespace
}  // namespace tbridge
