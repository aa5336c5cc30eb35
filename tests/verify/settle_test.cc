// The static solution against a damped time history left to settle under the same loads.
//
// The paper's design (no self-weight, gravity off the structure): the dynamic model's loads
// are exactly the design's reference loads, so both analyses see the same forces, and a
// constant extra load from t = 0 must bring the damped motion to rest at the static solution.

#include <Eigen/Core>
#include <catch2/catch.hpp>

#include "bridge/design_model.h"
#include "checks/static_check.h"
#include "design/static_model.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "test_support.h"

namespace tbridge {
namespace {

TEST_CASE("a damped time history settles at the static solution") {
  const Design& d = test::PaperDesign(2);
  const Structure& s = d.topology.structure;
  const int deck_node = d.topology.deck_nodes[0];  // off the symmetry axis
  const double extra = 0.1 * d.deck.node_load;     // [N], down: a visible deflection

  // Static: from the reference state to the reference loads plus the extra load.
  const StaticModel statics = StaticModelOf(d);
  const StaticState start =
      StateAt(statics, s.nodes, d.reference_forces.head(s.num_bars()), d.loads);
  Eigen::Matrix3Xd loads = d.loads;
  loads(1, deck_node) -= extra;
  const StaticResult st = SolveStatic(statics, start, d.loads, loads);
  REQUIRE(st.converged);

  // Dynamic: the same extra load held from t = 0, strings damped, every free node recorded.
  DynamicsConfig c;
  c.duration = 6.0;
  c.dt = 1e-5;
  c.damping_c = 3e5;
  c.frequency.enabled = false;
  c.record.csv = false;
  c.record.every = 100;
  c.loads.push_back({0.0, 2.0 * c.duration, deck_node + 1, {0.0, -extra, 0.0}});
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (!s.fixed[v]) c.record.nodes.push_back(v + 1);
  }
  ModelOptions options;
  options.damping = c.damping_c;
  const DynamicModel model = BuildDynamicModel(d, options);
  const SimulationResult r = Simulate(model, c);
  const Eigen::MatrixXd& h = r.history;
  REQUIRE(h.rows() > 10);

  // The last record against the static positions, and the spread of the last tenth of the
  // run: how far the motion still is from rest.
  double error = 0, spread = 0, deflection = 0;
  const int tail = static_cast<int>(h.rows()) / 10;
  for (size_t k = 0; k < c.record.nodes.size(); ++k) {
    const int v = c.record.nodes[k] - 1;
    for (int a = 0; a < r.dim; ++a) {
      const Eigen::VectorXd x = h.col(1 + r.dim * static_cast<int>(k) + a).tail(tail);
      error = std::max(error, std::abs(x(tail - 1) - st.state.nodes(a, v)));
      spread = std::max(spread, x.maxCoeff() - x.minCoeff());
      deflection = std::max(deflection, std::abs(st.state.nodes(a, v) - s.nodes(a, v)));
    }
  }
  INFO("deflection " << deflection << " m, error " << error << " m, spread " << spread << " m");
  CHECK(deflection > 1e-4);  // 1.8 mm: the extra load really moves the bridge
  // Strings damped at c = 3e5 N s/m for 6 s: the slowest mode has died out (measured spread
  // 9e-14 m; at 2 s it was still 1.8e-6 m, so this check does fail on a motion not at rest).
  CHECK(spread <= 1e-9 * deflection);
  // At rest the dynamics sit at its equilibrium; what separates the two is that spread and
  // the static solve's stopping test (forces to 1e-10 of the largest member force, 1.3e-5 N,
  // against string stiffnesses of 2e7-1.3e8 N/m and the softer prestress-held swing of the
  // bars: ~1e-12 m). Measured 7.5e-13 m; 1e-8 of the deflection (1.8e-11 m) bounds both with
  // a margin of ten.
  CHECK(error <= 1e-8 * deflection);
}

}  // namespace
}  // namespace tbridge
