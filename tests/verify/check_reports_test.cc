// The checks as functions: each takes a design and returns its report, changing nothing; the
// verdict is built from the reports, and a check not run makes it INCOMPLETE, never PASS. A
// run of a design counts every weight once.

#include <catch2/catch.hpp>
#include <sstream>

#include "bridge/design_model.h"
#include "checks/comfort_check.h"
#include "checks/dynamic_check.h"
#include "checks/static_check.h"
#include "checks/verdict.h"
#include "design/equilibrium.h"
#include "design/static_model.h"
#include "io/design_report.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

std::string JsonOf(const Design& d) {
  std::ostringstream os;
  WriteDesignJson(d, os);
  return os.str();
}

const LoadCase& CaseNamed(const Design& d, const std::string& name) {
  for (const LoadCase& c : d.cases) {
    if (c.name == name) return c;
  }
  FAIL("no case " << name);
  return d.cases.front();
}

TEST_CASE("a run with no extra load starts in the design's own serviceability state",
          "[verify][dynamics]") {
  Config config;  // engineering defaults: self-weight, deck inertia, the payload standing in a run
  config.bridge.n = 2;
  config.loads.superimposed_dead_n_per_m = 800;  // so that every weight of the deck is in play
  const Design d = RunDesign(config);
  ModelOptions options;
  options.gravity_on_structure = true;
  options.deck_inertia = true;
  const DynamicModel model = BuildDynamicModel(d, options);

  // The run's loads are the characteristic G + Q_full of the design (sls_payload_full): every
  // weight once. 1e-12 of the largest node load: the same sums in another order.
  const Eigen::Matrix3Xd sls = d.actions.Loads(CaseNamed(d, "sls_payload_full"));
  const double scale = sls.cwiseAbs().maxCoeff();
  CHECK((model.loads - sls).cwiseAbs().maxCoeff() <= 1e-12 * scale);
  // Conservation: the vertical loads sum to the weight of everything the bridge carries, the
  // members' (as the design lumps them, supports included), the deck beams', the superimposed
  // dead load's over the span and the payload. Counted twice, the deck and payload would add
  // about 100 %. 1e-12 relative: sums of a few hundred terms.
  const double g = config.design.gravity;
  const double weight = d.actions.base[kSelfWeight].row(1).sum() * -1.0;
  CHECK(weight == Approx(g * d.mass.structure).epsilon(1e-12));
  const double deck_on_nodes = -d.actions.base[kDeckDead].row(1).sum();
  const double payload_on_nodes = -d.actions.base[kPayloadFull].row(1).sum();
  CHECK(-model.loads.row(1).sum() ==
        Approx(weight + deck_on_nodes + payload_on_nodes).epsilon(1e-12));

  // And the run starts where the design's nonlinear static solve of that case puts the bridge:
  // 1e-9 m, well above the solver's convergence (forces to 1e-10 of the largest) and far below
  // the deflection itself (about 1e-2 m).
  const StaticModel statics = StaticModelOf(d);
  const StaticResult r = SolveStatic(statics, ReferenceState(statics, d), d.loads, sls);
  REQUIRE(r.converged);
  const double deflection = (r.state.nodes - d.topology.structure.nodes).cwiseAbs().maxCoeff();
  INFO("serviceability deflection " << deflection << " m");
  REQUIRE(deflection > 1e-3);
  CHECK((model.positions - r.state.nodes).cwiseAbs().maxCoeff() <= 1e-9);
}

TEST_CASE("the checks change nothing in the design they check", "[verify]") {
  Config config;
  config.bridge.n = 2;
  const Design d = RunDesign(config);
  const std::string before = JsonOf(d);
  Design copy = d;
  const StaticCheck statics = CheckStatics(copy);
  const DynamicCheck dynamics = CheckDynamics(copy);
  const ComfortCheck comfort = CheckComfort(copy);
  CHECK(JsonOf(copy) == before);
  // They did find something: the control that the comparison above can fail. Recording their
  // reports changes the design's outputs (its utilisations, its checks).
  REQUIRE(statics.done);
  REQUIRE(dynamics.done);
  REQUIRE(comfort.done);
  RecordChecks(copy, statics, dynamics, comfort);
  CHECK(JsonOf(copy) != before);
}

TEST_CASE("a design with a check not run is INCOMPLETE, never PASS", "[verify]") {
  Config config;
  config.bridge.n = 2;
  config.loads.dynamic_method = DynamicMethod::kRk4;  // the nonlinear run, whose budget this is
  Design d = DesignAndVerify(config);
  REQUIRE(DesignVerdict(d).outcome == VerdictOutcome::kPass);
  // The same design with its dynamic runs skipped (a budget of one member-step).
  const DynamicCheck skipped = CheckDynamics(d, 1.0);
  REQUIRE(!skipped.runs.empty());
  CHECK(skipped.Status() == CheckStatus::kNotRun);
  Design e = d;
  e.dynamics = skipped;
  const Verdict v = DesignVerdict(e);
  CHECK(v.outcome == VerdictOutcome::kIncomplete);
  CHECK_FALSE(v.pass);
  CHECK(v.summary.rfind("INCOMPLETE: ", 0) == 0);
  // A design no check has seen is INCOMPLETE too.
  const Design raw = RunDesign(config);
  CHECK(DesignVerdict(raw).outcome == VerdictOutcome::kIncomplete);
  // A failure outranks what was not run: an overloaded member FAILs.
  e.bars.front().utilisation = 1.01;
  CHECK(DesignVerdict(e).outcome == VerdictOutcome::kFail);
}

TEST_CASE("the prestress the checks leave unfactored is the deck chain's self-stress", "[verify]") {
  // SPEC.md 4: the planar bridge (p = 1) has one self-stress, a uniform tension in the deck
  // chain between the hinges. PrestressForces must be exactly that: in equilibrium with no
  // load, equal in every deck string, zero elsewhere.
  Config config;
  config.bridge.n = 2;
  const Design d = RunDesign(config);
  const Eigen::VectorXd prestress = PrestressForces(d);
  const int nb = static_cast<int>(d.bars.size());
  double deck = 0;
  for (size_t k = 0; k < d.strings.size(); ++k) {
    if (d.strings[k].kind == MemberKind::kDeckString) deck = std::max(deck, prestress[nb + k]);
  }
  REQUIRE(deck > 0);
  // 1e-9 of the prestress: SPQR's rounding on a system of this size.
  const EquilibriumSystem eq = BuildEquilibrium(d.topology.structure);
  const Eigen::Matrix3Xd none = Eigen::Matrix3Xd::Zero(3, d.loads.cols());
  CHECK(EquilibriumResidual(eq, prestress, none).cwiseAbs().maxCoeff() <= 1e-9 * deck);
  for (int j = 0; j < prestress.size(); ++j) {
    const bool in_chain = j >= nb && d.strings[j - nb].kind == MemberKind::kDeckString;
    INFO("member " << j);
    CHECK(prestress[j] == Approx(in_chain ? deck : 0.0).margin(1e-9 * deck));
  }
}

}  // namespace
}  // namespace tbridge

namespace tbridge {
namespace {

TEST_CASE("a failing design's summary names its largest violation and the keys that move it",
          "[verify]") {
  // The verified default (comfort off) with every area at 0.8 of its own: its members fail their
  // strength by some 20 %, the largest violation; a passing design prints no such line.
  Config config;
  config.comfort.check = false;
  const Design d = DesignAndVerify(config);
  REQUIRE(DesignVerdict(d).pass);
  CHECK_THAT(DesignSummary(d, 0), !Catch::Contains("what moves it"));
  CHECK_THAT(DesignSummary(d, 0), Catch::Contains("(the lightest that passed)"));
  std::vector<double> areas = MemberAreas(d);
  for (double& a : areas) a *= 0.8;
  Design thin = SizedDesign(config, areas, d.alpha);
  CheckAgain(thin);
  REQUIRE(DesignVerdict(thin).outcome == VerdictOutcome::kFail);
  const std::string summary = DesignSummary(thin, 0);
  INFO(summary);
  CHECK_THAT(summary,
             Catch::Contains("what moves it: the largest violation is a member's strength") &&
                 Catch::Contains("keys: bridge.beta_deg and bridge.n"));
}

}  // namespace
}  // namespace tbridge
