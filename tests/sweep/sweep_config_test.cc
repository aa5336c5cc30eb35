// Strict parsing of the "sweep" section and of --shard: bad input names the key, the value
// and what is allowed.

#include "sweep/sweep_config.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.h"
#include "sweep/sweep.h"

namespace tbridge {
namespace {

using nlohmann::json;

json Base() { return json::parse(R"({"bridge": {"beta_deg": 10}, "sweep": {"n": [1, 2, 3]}})"); }

// The message of the ConfigError that parsing `root` throws ("" when it parses).
std::string ErrorOf(const json& root) {
  try {
    ParseSweepSpec(root);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST_CASE(
    "the sweep's own travelling-load run of earlier versions is refused: each key names what "
    "replaced it",
    "[sweep]") {
  // Each old key, its value, and the key (or the reason for none) that replaced it.
  const std::vector<std::tuple<std::string, json, std::string>> replaced = {
      {"duration", 0.5, "loads.travelling_speed_m_s"},
      {"dt", 5e-4, "loads.dynamic_dt_s"},
      {"integrator", "sdirk3", "loads.dynamic_method"},
      {"load_factor", 2.0, "loads.travelling_load_n"},
      {"string_mass", "off", "nothing replaces it"},
      {"damping_c", 1.0, "nothing replaces it"},
      {"deck_inertia", false, "nothing replaces it"},
  };
  for (const auto& [key, value, by] : replaced) {
    json j = Base();
    j["sweep"]["travelling_load"] = {{key, value}};
    INFO(key);
    CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.travelling_load." + key) &&
                               Catch::Contains(value.dump()) && Catch::Contains(by));
  }
  json j = Base();
  j["sweep"]["travelling_load"] = json::object();
  CHECK_THAT(ErrorOf(j),
             Catch::Contains("'sweep.travelling_load'") && Catch::Contains("loads.cases"));
  j = Base();
  j["sweep"]["report"] = {{"travelling_load", true}};
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.report.travelling_load") &&
                             Catch::Contains("sweep.report.dynamic_check"));
}

TEST_CASE("a minimal sweep config resolves its defaults", "[sweep]") {
  const SweepSpec s = ParseSweepSpec(Base());
  CHECK(s.sweep.n == std::vector<int>{1, 2, 3});
  CHECK(s.sweep.p == std::vector<int>{1});
  CHECK(s.sweep.beta_deg == std::vector<double>{10.0});
  CHECK(s.sweep.deck_prestrain == std::vector<double>{1.0});
  CHECK(s.sweep.size() == 3);
  CHECK_FALSE(s.sweep.NeedsModes());
  // Candidates are verified designs, and bar capacity and no-slack in the dynamic check's runs
  // are constraints unless switched off.
  CHECK(s.sweep.verified);
  CHECK(s.sweep.constraints.no_slack_under_service);
  CHECK(s.sweep.constraints.bar_capacity_during_motion);
  CHECK(s.sweep.NeedsDynamicCheck());
  // The echoed config (with null for absent constraints) reads back to the same spec.
  const SweepSpec again = ParseSweepSpec(ToJson(s));
  CHECK(ToJson(again) == ToJson(s));
  CHECK(SweepFingerprint(again) == SweepFingerprint(s));
}

TEST_CASE("bad sweep configs name the key, the value and what is allowed", "[sweep]") {
  json j = Base();
  j["sweep"]["bogus"] = 1;
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.bogus"));

  j = Base();
  j["sweep"]["constraints"] = {{"min_first_frequency", 50}};  // the key has a unit suffix
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.constraints.min_first_frequency"));

  j = Base();
  j["sweep"]["n"] = json::array();
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.n") && Catch::Contains("at least one"));

  j = Base();
  j["sweep"]["n"] = {1, 17};
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.n[1]") && Catch::Contains("[1, 16]"));

  j = Base();
  j["sweep"]["n"] = {2, 2};
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.n[1]") && Catch::Contains("only once"));

  j = Base();
  j["sweep"]["deck_prestrain"] = {1.0, 1.2};
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.deck_prestrain[1]"));

  j = Base();
  j["sweep"]["beta_deg"] = {10, 90};
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.beta_deg[1]"));

  j = Base();
  j["sweep"]["joint_mass"] = {{"per_node_kg", -1}};
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.joint_mass.per_node_kg"));

  j = Base();
  j["dynamics"] = json::object();
  CHECK_THAT(ErrorOf(j), Catch::Contains("dynamics") && Catch::Contains("loads.cases"));

  j = Base();
  j.erase("sweep");
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep"));

  j = Base();
  j["bridge"]["planes"] = 2;
  j["sweep"]["p"] = {1, 2};
  CHECK_THAT(ErrorOf(j), Catch::Contains("sweep.p[1]") && Catch::Contains("planes"));

  j = Base();
  j["bridge"]["colour"] = "red";  // the base config stays strict too
  CHECK_THAT(ErrorOf(j), Catch::Contains("bridge.colour"));
}

TEST_CASE("shard specs are i/N with 1 <= i <= N", "[sweep]") {
  CHECK(ParseShard("1/1", "--shard").count == 1);
  const Shard s = ParseShard("2/3", "--shard");
  CHECK((s.index == 2 && s.count == 3));
  CHECK(s.Has(1));
  CHECK(s.Has(4));
  CHECK_FALSE(s.Has(2));
  for (const char* bad : {"3/2", "0/2", "a/b", "1/0", "1", "/2", "1/2/3", "-1/2", ""}) {
    INFO(bad);
    CHECK_THROWS_WITH(ParseShard(bad, "--shard"),
                      Catch::Contains("--shard") && Catch::Contains("i/N"));
  }
}

}  // namespace
}  // namespace tbridge
