// The rest-length tolerance (design.rest_length_tolerance, design/prestress_states.h): the
// sizing's highest state against the closed form of the self-stress it adds and against the
// nonlinear as-built solve of the bridge with its rest lengths so changed, and a verified design
// whose deck string, shortened by the tolerance in its file, still passes `check`.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "checks/verdict.h"
#include "design/as_built.h"
#include "design/design.h"
#include "design/prestress_states.h"
#include "io/design_reader.h"
#include "io/design_report.h"
#include "sizing/sizing_problem.h"
#include "sizing/verified_design.h"
#include "verify/prestress_state_support.h"

namespace tbridge {
namespace {

// The default at n = 3 with comfort off and the tolerance alone (no loss).
Config ToleranceOnly(double tolerance) {
  Config config;
  config.bridge.n = 3;
  config.comfort.check = false;
  config.design.prestress_loss = 0;
  config.design.rest_length_tolerance = tolerance;
  return config;
}

using test::CheckShiftedRows;
using test::FirstOrderChange;

TEST_CASE(
    "the rest-length tolerance raises the prestress as its closed form and the nonlinear solve say",
    "[verify]") {
  const Config config = ToleranceOnly(5e-4);
  const Design d = RunDesign(config);
  REQUIRE(d.self_stress_states == 1);  // a planar bridge: the deck chain
  const std::vector<PrestressStateSpec> states = PrestressStatesOf(config);
  REQUIRE(states.size() == 3);
  REQUIRE(states[1].state == PrestressState::kHighest);
  const std::vector<double> shortenings = ToleranceShortenings(d);
  // Every string the prestress tensions (the deck chain) by 5e-4 of its length, the others none.
  const Eigen::VectorXd p = PrestressForces(d);
  const int nb = static_cast<int>(d.bars.size());
  for (size_t k = 0; k < d.strings.size(); ++k) {
    const bool tensioned = p[nb + static_cast<Eigen::Index>(k)] > 1e-9 * p.cwiseAbs().maxCoeff();
    CHECK(shortenings[k] == (tensioned ? 5e-4 * d.strings[k].length : 0.0));
  }
  std::vector<double> all(d.bars.size(), 0.0);  // the bars' none
  all.insert(all.end(), shortenings.begin(), shortenings.end());
  const Eigen::VectorXd change = FirstOrderChange(d, all);
  REQUIRE(change.cwiseAbs().maxCoeff() > 0);

  // The nonlinear as-built solve of the bridge with those rest lengths (the check's state): the
  // first-order change to 2 % of its largest (what is left is the geometry's: the deck sags by
  // its strain under the raised chain, second order).
  const Design high = DesignInState(d, states[1]);
  REQUIRE(high.as_built.re_derived);
  const Eigen::VectorXd solved = high.reference_forces - d.reference_forces;
  INFO("first order " << change.cwiseAbs().maxCoeff() << " N, solved "
                      << solved.cwiseAbs().maxCoeff() << " N");
  CHECK((solved - change).cwiseAbs().maxCoeff() <= 0.02 * change.cwiseAbs().maxCoeff());

  // The sizing's rows in the highest state are the rows as designed at the prestress raised by
  // that change: the same code at two points, so equal to rounding (1e-10 of a row's scale).
  const SizingProblem with(d, {});
  const SizingProblem without(RunDesign(ToleranceOnly(0)), {});
  CheckShiftedRows(d, with, without, change);
}

TEST_CASE("a deck string shortened by the tolerance in the design file still passes check",
          "[verify]") {
  // The verified default at n = 3 with the defaults' loss and tolerance; its most tensioned deck
  // string made shorter by the tolerance of its length (rest length and stiffness together, as an
  // engineer edits the file): check re-derives the state as built, names the string, and passes.
  Config config = ToleranceOnly(5e-4);
  config.design.prestress_loss = 0.05;
  const Design d = DesignAndVerify(config);
  INFO(DesignVerdict(d).summary);
  REQUIRE(DesignVerdict(d).pass);
  REQUIRE(d.statics.prestress_states.size() == 2);
  size_t deck = 0;
  for (size_t k = 0; k < d.strings.size(); ++k) {
    if (d.strings[k].kind == MemberKind::kDeckString &&
        d.strings[k].reference_force > d.strings[deck].reference_force)
      deck = k;
  }
  REQUIRE(d.strings[deck].kind == MemberKind::kDeckString);
  std::vector<double> shortenings(d.strings.size(), 0.0);
  shortenings[deck] = 5e-4 * d.strings[deck].rest_length;
  Design edited = WithRestLengths(d, shortenings);
  REQUIRE(edited.as_built.re_derived);
  CHECK(edited.as_built.edited == std::vector<std::string>{d.strings[deck].name});
  CHECK(edited.strings[deck].reference_force > d.strings[deck].reference_force);
  CheckAgain(edited);
  INFO(DesignVerdict(edited).summary);
  CHECK(DesignVerdict(edited).pass);
  // Its rest lengths are now those built: checked after the loss, not short or long again.
  CHECK(edited.statics.prestress_states == std::vector<std::string>{"after the prestress loss"});
}

}  // namespace
}  // namespace tbridge
