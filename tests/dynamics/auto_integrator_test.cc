// integrator "auto" beyond RK4's limit, while RK4 sub-steps cost less than an SDIRK3 step: it
// must be RK4 at the finer step, computed the same way.

#include <catch2/catch.hpp>

#include "bridge/design_model.h"
#include "core/dynamics_config.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "test_support.h"

namespace tbridge {
namespace {

DynamicsConfig Pushed(double dt, const std::string& integrator, int record_every) {
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

TEST_CASE("auto beyond RK4's limit runs RK4 sub-steps, as RK4 at the finer step does", "[dynamics]") {
  // n = 3: RK4's limit 2.8e-4 s (SPEC.md §9), 0.9 of it 2.5e-4 s, so dt = 1e-3 s takes
  // ceil(3.9) = 4 sub-steps of 2.5e-4 s.
  const DynamicModel m = BuildDynamicModel(test::PaperDesign(3));
  const SimulationResult automatic = Simulate(m, Pushed(1e-3, "auto", 1));
  const SimulationResult fine = Simulate(m, Pushed(2.5e-4, "rk4", 4));
  CHECK(automatic.summary.integrator == "rk4");
  CHECK(automatic.summary.substeps == 4);
  CHECK(automatic.summary.steps == 20);
  CHECK(automatic.summary.evaluations == fine.summary.evaluations);
  REQUIRE(automatic.history.rows() == fine.history.rows());
  // 1e-12 m: the same RK4 steps; only the sub-step (t - t_old) / 4 may differ from 2.5e-4 s
  // in its last bit.
  CHECK((automatic.history - fine.history).cwiseAbs().maxCoeff() <= 1e-12);
  const Eigen::Index coordinates = fine.history.cols() - 1;  // after the time column
  CHECK((fine.history.bottomRows(1) - fine.history.topRows(1)).rightCols(coordinates).cwiseAbs().maxCoeff() > 1e-5);  // it moves [m]
}

}  // namespace
}  // namespace tbridge
