// Bar-force peaks of a run (dynamics.record.bar_forces) against the static design: a bridge
// left at rest in its design equilibrium keeps the bar forces the minimum-mass solve found.

#include <catch2/catch.hpp>

#include "bridge/design_model.h"
#include "core/dynamics_config.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "test_support.h"

namespace tbridge {
namespace {

TEST_CASE("at rest the bar-force peaks are the design's bar forces", "[dynamics]") {
  for (const int p : {1, 2}) {
    Config c = test::PaperConfig(2);
    c.bridge.p = p;
    const Design design = RunDesign(c);
    const DynamicModel model = BuildDynamicModel(design);
    DynamicsConfig run;
    run.duration = 1e-3;
    run.dt = 1e-5;
    run.integrator = IntegratorKind::kRk4;
    run.frequency.enabled = false;
    run.record.bar_forces = true;
    const SimulationSummary s = Simulate(model, run).summary;
    INFO("p = " << p << ", engine " << s.engine);
    CHECK(s.engine == (p == 1 ? "class1" : "classk"));
    REQUIRE(s.peak_bar_compression.size() == design.bars.size());
    for (size_t k = 0; k < design.bars.size(); ++k) {
      // 1e-7 relative: the design's equilibrium residual (design.tolerance 1e-10 on forces of
      // ~1e4 N) leaves accelerations ~1e-7 m/s^2, which move nothing in 1 ms.
      CHECK(s.peak_bar_compression[k] == Approx(design.bars[k].force).epsilon(1e-7));
      CHECK(s.peak_bar_tension[k] == 0.0);  // bars of a tensegrity bridge are compressed
    }
  }
}

TEST_CASE("bar-force peaks are off unless asked", "[dynamics]") {
  const DynamicModel model = BuildDynamicModel(test::PaperDesign(1));
  DynamicsConfig run;
  run.duration = 1e-4;
  run.dt = 1e-5;
  run.frequency.enabled = false;
  const SimulationSummary s = Simulate(model, run).summary;
  CHECK(s.peak_bar_compression.empty());
  CHECK(s.peak_bar_tension.empty());
}

}  // namespace
}  // namespace tbridge
