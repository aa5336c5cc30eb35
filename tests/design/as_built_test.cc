// A design whose members were edited in its file (io/design_reader.h, WithAreas): the
// reference state the members carry as built, re-derived by the nonlinear static solve, against
// the linear response of the design's own tangent to the same change of load, and against the
// string law and node equilibrium at the geometry it finds.

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/string_law.h"
#include "design/design.h"
#include "design/equilibrium.h"
#include "design/static_model.h"
#include "io/design_reader.h"
#include "statics/static_solve.h"

namespace tbridge {

namespace {

std::vector<double> AreasOf(const Design& d) {
  std::vector<double> out;
  for (const MemberSizing& m : d.bars) out.push_back(m.area);
  for (const MemberSizing& m : d.strings) out.push_back(m.area);
  return out;
}

}  // namespace

TEST_CASE("as built: a heavier bar moves the reference state as the design's tangent says",
          "[design]") {
  Config config;  // the default bridge, self-weight on
  config.bridge.n = 2;
  const Design d = RunDesign(config);
  REQUIRE(config.design.self_weight);
  // The heaviest bar 50 % thicker: a change of weight the bridge carries by stiffness.
  size_t bar = 0;
  for (size_t k = 1; k < d.bars.size(); ++k) {
    if (d.bars[k].mass > d.bars[bar].mass) bar = k;
  }
  std::vector<double> areas = AreasOf(d);
  areas[bar] *= 1.5;
  const Design e = WithAreas(d, areas);
  REQUIRE(e.as_built.re_derived);
  // Named among the edits: its resistance as designed no longer follows from its area.
  CHECK(e.as_built.edited == std::vector<std::string>{d.bars[bar].name});
  CHECK(e.bars[bar].mass == Approx(1.5 * d.bars[bar].mass).epsilon(1e-12));

  // The linear response of the design's reference state to the loads' change.
  const StaticModel model = StaticModelOf(d);
  const StaticState state = ReferenceState(model, d);
  StaticTangent tangent(model, state);
  REQUIRE(tangent.ok());
  Eigen::Matrix3Xd du;
  Eigen::VectorXd dforce;
  tangent.Solve(e.loads - d.loads, du, dforce);
  const Eigen::Matrix3Xd moved = e.topology.structure.nodes - d.topology.structure.nodes;
  const Eigen::VectorXd changed = e.reference_forces - d.reference_forces;
  REQUIRE(du.cwiseAbs().maxCoeff() > 1e-7);  // a response the comparison can see
  // What is left is second order in the change (its share of the geometry, ~1e-4 here): 1 %
  // of the largest is far above it and far below a wrong load, sign or stiffness.
  CHECK((moved - du).cwiseAbs().maxCoeff() <= 0.01 * du.cwiseAbs().maxCoeff());
  CHECK((changed - dforce).cwiseAbs().maxCoeff() <= 0.01 * dforce.cwiseAbs().maxCoeff());
  CHECK(e.as_built.node_move_m == Approx(moved.colwise().norm().maxCoeff()).epsilon(1e-12));

  // At the geometry found: every string pulls k (s - L0), every bar keeps its length, and the
  // forces balance the loads at every free node (1e-10 of the largest force: the solve's own
  // criterion).
  const Structure& s = e.topology.structure;
  for (size_t k = 0; k < e.strings.size(); ++k) {
    const MemberSizing& m = e.strings[k];
    CHECK(m.reference_force ==
          Approx(StringTension(m.stiffness, m.rest_length, s.Length(s.strings[k]))).epsilon(1e-9));
    CHECK(m.rest_length == d.strings[k].rest_length);
  }
  for (size_t k = 0; k < e.bars.size(); ++k) {
    CHECK(s.Length(s.bars[k]) ==
          Approx(d.topology.structure.Length(d.topology.structure.bars[k])).epsilon(1e-12));
  }
  const Eigen::VectorXd residual =
      EquilibriumResidual(BuildEquilibrium(s), e.reference_forces, e.loads);
  CHECK(residual.cwiseAbs().maxCoeff() <= 1e-10 * e.reference_forces.cwiseAbs().maxCoeff());
}

TEST_CASE("as built: unchanged areas re-derive nothing and bad areas are refused naming the key",
          "[design]") {
  Config config;
  config.bridge.n = 1;
  const Design d = RunDesign(config);
  const Design same = WithAreas(d, AreasOf(d));
  CHECK_FALSE(same.as_built.re_derived);
  CHECK(same.reference_forces == d.reference_forces);
  std::vector<double> areas = AreasOf(d);
  areas[1] = -1;
  CHECK_THROWS_WITH(WithAreas(d, areas), Catch::Contains("areas[1]") && Catch::Contains("-1"));
  areas.pop_back();
  CHECK_THROWS_WITH(WithAreas(d, areas), Catch::Contains("'areas'"));
}

}  // namespace tbridge
