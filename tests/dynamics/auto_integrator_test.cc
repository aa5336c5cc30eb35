// integrator "auto" beyond RK4's limit, while RK4 sub-steps cost less than an SDIRK3 step: it
// must be RK4 at the finer step, computed the same way.

#include <catch2/catch.hpp>

#include "bridge/design_model.h"
#include "core/dynamics_config.h"
#include "dynamics/coupling.h"
#include "dynamics/integrator_policy.h"
#include "dynamics/model.h"
#include "dynamics/sdirk.h"
#include "dynamics/simulation.h"
#include "test_support.h"

namespace tbridge {
namespace {

DynamicsConfig Pushed(double dt, IntegratorKind integrator, int record_every) {
  DynamicsConfig c;
  c.duration = 0.02;
  c.dt = dt;
  c.integrator = integrator;
  c.perturbation = {1, 1e-3};
  c.frequency.enabled = false;
  c.record.nodes = {5, 6, 7};
  c.record.every = record_every;
  return c;
}

TEST_CASE("auto beyond RK4's limit runs RK4 sub-steps, as RK4 at the finer step does",
          "[dynamics]") {
  // n = 3: RK4's limit 2.8e-4 s (SPEC.md §9), 0.9 of it 2.5e-4 s, so dt = 1e-3 s takes
  // ceil(3.9) = 4 sub-steps of 2.5e-4 s.
  const DynamicModel m = BuildDynamicModel(test::PaperDesign(3));
  const SimulationResult automatic = Simulate(m, Pushed(1e-3, IntegratorKind::kAuto, 1));
  const SimulationResult fine = Simulate(m, Pushed(2.5e-4, IntegratorKind::kRk4, 4));
  CHECK(automatic.summary.integrator == "rk4");
  CHECK(automatic.summary.substeps == 4);
  CHECK(automatic.summary.steps == 20);
  CHECK(automatic.summary.evaluations == fine.summary.evaluations);
  REQUIRE(automatic.history.rows() == fine.history.rows());
  // 1e-12 m: the same RK4 steps; only the sub-step (t - t_old) / 4 may differ from 2.5e-4 s
  // in its last bit.
  CHECK((automatic.history - fine.history).cwiseAbs().maxCoeff() <= 1e-12);
  const Eigen::Index coordinates = fine.history.cols() - 1;  // after the time column
  CHECK((fine.history.bottomRows(1) - fine.history.topRows(1))
            .rightCols(coordinates)
            .cwiseAbs()
            .maxCoeff() > 1e-5);  // it moves [m]
}

TEST_CASE("auto takes RK4 sub-steps up to the estimated cost of an SDIRK3 step, and SDIRK3 beyond",
          "[dynamics]") {
  // The threshold k comes from the model's counts alone; a dt that needs k sub-steps runs
  // RK4, one that needs k + 1 runs SDIRK3.
  const DynamicModel m = BuildDynamicModel(test::PaperDesign(3));
  const Sdirk3 sdirk(CouplingOf(m), 4 * m.num_nodes());
  const int members = static_cast<int>(m.bars.size() + m.strings.size());
  const StepCosts costs = EstimateStepCosts(members, 2 * m.num_nodes(), sdirk.counts());
  const int k = costs.Rk4StepsPerSdirk3Step();
  // The estimate lies within the range measured on the paper's bridges (BENCHMARKS.md, Cost
  // per step: 9-29 at n = 2..7), not at the former fixed 40.
  CHECK(k >= 9);
  CHECK(k <= 29);
  const double stable = Rk4StableStep(m, Pushed(1e-3, IntegratorKind::kAuto, 1));
  // Just below k steps of the stable step: k sub-steps (1e-9 relative: clear of ceil's edge).
  const SimulationSummary at_k =
      Simulate(m, Pushed(k * stable * (1 - 1e-9), IntegratorKind::kAuto, 1)).summary;
  CHECK(at_k.integrator == "rk4");
  CHECK(at_k.substeps == k);
  const SimulationSummary beyond =
      Simulate(m, Pushed((k + 0.5) * stable, IntegratorKind::kAuto, 1)).summary;
  CHECK(beyond.integrator == "sdirk3");
  CHECK(beyond.substeps == 1);
}

}  // namespace
}  // namespace tbridge
