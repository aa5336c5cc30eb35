// The one description of the sweep section (sweep/sweep_fields.h) against what the parse
// accepts, what the echo writes, what Validate() refuses and what configs/README.md documents.
#include "sweep/sweep_fields.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "config_fields_support.h"
#include "core/error.h"
#include "sweep/sweep_config.h"

namespace tbridge {
namespace {

using nlohmann::json;

// A sweep section with every key (every constraint on).
json FullSweep() {
  return json::parse(
      R"({"n": [1, 2], "p": [1, 2], "beta_deg": [10, 20], "deck_prestrain": [1, 0.95],
    "prestrain_sizing": "keep_area", "joint_mass": {"per_node_kg": 1, "per_force_kg_per_N": 1e-5},
    "constraints": {"min_first_frequency_rad_s": 50, "max_deck_displacement": 0.01, "span_over_displacement": 1000,
      "no_slack_under_service": true, "max_dynamic_stress_ratio": 1.5, "bar_capacity_during_motion": true,
      "prestress_within_allowed": true},
    "report": {"first_frequency": true, "dynamic_check": true}})");
}

SweepSpec Parse(const json& sweep) {
  return ParseSweepSpec(json{{"bridge", json::object()}, {"sweep", sweep}});
}

TEST_CASE("sweep: parse, echo, Validate and the README agree on every described key",
          "[sweep][fields]") {
  const SweepSpec base = Parse(FullSweep());
  CheckDescribedSection(
      test::DescribedSection<SweepConfig>{kSweepSection, SweepSectionText(), base.sweep,
                                          [](const json& j) { return Parse(j).sweep; },
                                          [&base](const SweepConfig& s) {
                                            SweepSpec spec = base;
                                            spec.sweep = s;
                                            Validate(spec);
                                          }},
      test::ReadmeText());
  // Absent constraints are echoed as null, which reads back as absent.
  const SweepSpec minimal = Parse(json{{"n", {3}}});
  CHECK(ToJson(minimal)["sweep"]["constraints"]["max_deck_displacement"].is_null());
  CHECK_FALSE(Parse(ToJson(minimal)["sweep"]).sweep.constraints.max_deck_displacement);
}

TEST_CASE("sweep: the rules across keys hold in code as in a file", "[sweep][fields]") {
  const SweepSpec base = Parse(FullSweep());
  CHECK_NOTHROW(Validate(base));
  SweepSpec repeated = base;
  repeated.sweep.n = {2, 2};
  CHECK_THROWS_WITH(Validate(repeated),
                    Catch::Contains("sweep.n[1]") && Catch::Contains("only once"));
  SweepSpec empty = base;
  empty.sweep.beta_deg.clear();
  CHECK_THROWS_WITH(Validate(empty),
                    Catch::Contains("sweep.beta_deg") && Catch::Contains("at least one"));
  SweepSpec planes = base;
  planes.base.bridge.planes = 2;
  CHECK_THROWS_WITH(Validate(planes),
                    Catch::Contains("sweep.p[1]") && Catch::Contains("planes = 2"));
}

}  // namespace
}  // namespace tbridge
