// Every static case of the default config: the support reactions balance the case's loads,
// recomputed here from the case's actions.

#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>

#include "checks/static_check.h"
#include "core/config.h"
#include "design/design.h"

namespace tbridge {
namespace {

TEST_CASE("reactions balance the applied loads in every static case of the default config") {
  Design d = RunDesign(LoadConfig(TBRIDGE_SOURCE_DIR "/configs/default.json"));
  d.statics = CheckStatics(d);
  REQUIRE(d.statics.cases.size() >= d.cases.size());  // a travelling family adds stations
  for (const CaseResponse& r : d.statics.cases) {
    INFO(r.label);
    REQUIRE(r.converged);
    const Eigen::Matrix3Xd loads = d.actions.Loads(d.cases[r.case_index], r.station);
    const double scale = loads.cwiseAbs().sum();
    REQUIRE(scale > 0);
    const Eigen::Vector3d imbalance = r.reactions.rowwise().sum() + loads.rowwise().sum();
    // The members' forces cancel pairwise, so the imbalance is the sum of the solve's
    // residuals at the free nodes. Newton stops once each is within 1e-10 of the largest
    // member force (2.8e5 N here, 22 times the 1.26e4 N of a travelling case's loads), which
    // over 28 free coordinates would allow 6e-8 of the loads; its last quadratic step leaves
    // less. Measured at most 8.3e-10 (sls_travelling at node 7), 2e-11 without a travelling
    // load: 1e-9 is the bound asked of the design output, held with a margin of only 1.2.
    CHECK(imbalance.norm() <= 1e-9 * scale);
  }
}

TEST_CASE("an abutment whose ultimate cases found no equilibrium reports the reference state") {
  // Every string half again as long as designed: no ultimate case finds an equilibrium, and the
  // abutments' envelope would be empty. It reports the reference state's reactions instead (the
  // least each abutment takes), labelled so, not 0 kN.
  Config config;
  config.bridge.n = 2;
  config.supports.horizontal_capacity_n = 1.0;  // 1 N: any reaction is far over it
  Design d = RunDesign(config);
  for (MemberSizing& s : d.strings) s.rest_length *= 1.5;
  const StaticCheck check = CheckStatics(d);
  for (const CaseResponse& r : check.cases) REQUIRE_FALSE(r.converged);  // the premise
  REQUIRE(check.abutments.size() == 2);
  for (const AbutmentFinding& a : check.abutments) {
    // The same sums over the abutment's support nodes, formed here from the design's reactions.
    double x = 0, y = 0, z = 0;
    for (const int node : a.nodes)
      x += d.reactions(0, node), y += d.reactions(1, node), z += d.reactions(2, node);
    REQUIRE(std::hypot(x, z) > 0);
    // Tolerance: the same additions in another order, a few ulps.
    CHECK(a.horizontal_n == Approx(std::hypot(x, z)).epsilon(1e-12));
    CHECK(a.vertical_n == Approx(std::abs(y)).epsilon(1e-12));
    CHECK(a.horizontal_case.find("reference state") != std::string::npos);
    CHECK(a.HorizontalUtilisation() > 1);
  }
}

}  // namespace
}  // namespace tbridge
