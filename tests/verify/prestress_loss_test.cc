// The prestress loss (design.prestress_loss): the sizing's rows of the state after the loss
// against the intact problem at the reduced self-stress, the relaxed design against the string
// law and equilibrium, and a verified design that passes with and without the loss.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "checks/verdict.h"
#include "core/string_law.h"
#include "design/design.h"
#include "design/equilibrium.h"
#include "sizing/sizing_problem.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

TEST_CASE("the sizing's rows after the prestress loss are the intact rows at the reduced prestress",
          "[verify]") {
  // The state after the loss is the reference state with the self-stress coefficients times
  // (1 - loss), G's forces kept: each of its rows is the intact problem's row at those
  // coefficients. Both are evaluated by the same code at different points, so equal to rounding
  // (1e-12 of a row's unit scale).
  Config config;
  config.bridge.n = 2;
  config.design.prestress_loss = 0.2;
  config.design.rest_length_tolerance = 0;  // the loss alone: the intact problem at 0.8 alpha
  const Design d = RunDesign(config);
  Config intact_config = config;
  intact_config.design.prestress_loss = 0;
  const Design intact_design = RunDesign(intact_config);
  const SizingProblem with_loss(d, {}), intact(intact_design, {});
  REQUIRE(with_loss.num_variables() == intact.num_variables());
  const int n_intact = intact.num_constraints();
  REQUIRE(with_loss.num_constraints() == 2 * n_intact);  // every row again, the comfort rows aside
  for (int r = 0; r < with_loss.num_constraints(); ++r) {
    CHECK(with_loss.rows()[static_cast<size_t>(r)].state == (r >= n_intact ? 2 : 0));
  }
  const Eigen::VectorXd x =
      with_loss.VariablesOf(MemberAreas(d), with_loss.AlphaOf(d.reference_forces));
  REQUIRE(x.size() > intact.num_variables() - 1);
  const int groups = static_cast<int>(*std::max_element(with_loss.group_of().begin(),
                                                        with_loss.group_of().end())) +
                     1;
  Eigen::VectorXd reduced = x;
  reduced.tail(x.size() - groups) *= 0.8;
  REQUIRE(reduced.tail(x.size() - groups).norm() > 0);
  Eigen::VectorXd g(with_loss.num_constraints()), g0(n_intact), g_reduced(n_intact);
  with_loss.Constraints(x, g);
  intact.Constraints(x, g0);
  intact.Constraints(reduced, g_reduced);
  CHECK((g.head(n_intact) - g0).cwiseAbs().maxCoeff() <= 1e-12);
  CHECK((g.tail(n_intact) - g_reduced).cwiseAbs().maxCoeff() <= 1e-12);
  CHECK_THAT(with_loss.RowLabel(n_intact), Catch::EndsWith("after the prestress loss"));
}

TEST_CASE("a design after the prestress loss carries its reduced forces by the string law",
          "[verify]") {
  Config config;
  config.bridge.n = 2;
  const Design d = RunDesign(config);
  const double loss = 0.05;
  const Design lost = WithPrestressLoss(d, loss);
  const Eigen::VectorXd prestress = PrestressForces(d);
  REQUIRE(prestress.cwiseAbs().maxCoeff() > 0);
  // The forces: the design's less the loss's share of its self-stress, exactly as computed.
  CHECK((lost.reference_forces - (d.reference_forces - loss * prestress)).cwiseAbs().maxCoeff() <=
        1e-9 * d.reference_forces.cwiseAbs().maxCoeff());
  // Each string's new rest length and stiffness carry its new force at its drawn length (to the
  // rounding of l - L0 against l: 1e-9 of the force), and the forces still balance the loads
  // (a self-stress balances none: to the design's own equilibrium tolerance).
  for (const MemberSizing& m : lost.strings) {
    if (!(m.reference_force > 0)) continue;
    CHECK(StringTension(m.stiffness, m.rest_length, m.length) ==
          Approx(m.reference_force).epsilon(1e-9));
  }
  const Eigen::VectorXd residual = EquilibriumResidual(BuildEquilibrium(lost.topology.structure),
                                                       lost.reference_forces, lost.loads);
  CHECK(residual.cwiseAbs().maxCoeff() <= 1e-8 * d.reference_forces.cwiseAbs().maxCoeff());
}

TEST_CASE("a verified design passes with and without its prestress loss, and books what it costs",
          "[verify]") {
  // The default at n = 3 with comfort off, sized without and with a loss of 20 % (large, so that
  // the state after it governs somewhere): the second is the heavier (its feasible set is the
  // first's less the designs the loss fails), passes both states' static checks (the lost
  // state's cases in its static check), and the mass attribution books the lost rows' share.
  Config config;
  config.bridge.n = 3;
  config.comfort.check = false;
  config.design.prestress_loss = 0;
  config.design.rest_length_tolerance = 0;
  const Design none = DesignAndVerify(config);
  REQUIRE(DesignVerdict(none).pass);
  CHECK(none.statics.prestress_states.empty());
  config.design.prestress_loss = 0.2;
  const Design d = DesignAndVerify(config);
  INFO(DesignVerdict(d).summary << "; " << d.resizing.optima);
  REQUIRE(DesignVerdict(d).pass);
  CHECK(d.statics.prestress_states == std::vector<std::string>{"after the prestress loss"});
  int lost_cases = 0;
  for (const CaseResponse& r : d.statics.cases) {
    if (r.label.find("after the prestress loss") != std::string::npos) ++lost_cases;
  }
  CHECK(lost_cases > 0);
  CHECK(2 * lost_cases == static_cast<int>(d.statics.cases.size()));
  // Heavier, by more than the outer iterations' settling tolerance 5e-4 that either may leave.
  CHECK(d.mass.structure > none.mass.structure * (1 + 5e-4));
  REQUIRE(std::string(kConstraintKinds[kRobustnessKind]) == "robustness");
  CHECK(d.attribution.mass_by_kind_kg[kRobustnessKind] > 0.0);
  CHECK(none.attribution.mass_by_kind_kg[kRobustnessKind] == 0.0);
  REQUIRE(d.resizing.kkt.has_value());
  CHECK(d.resizing.kkt->proved_local_optimum);
}

}  // namespace
}  // namespace tbridge
