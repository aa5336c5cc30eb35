// Config values inside their ranges that are still no bridge practice give a plausibility
// warning naming the key and the likely slip; no shipped config gives one.

#include "design/plausibility.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/config.h"

namespace tbridge {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The one warning `config` gives; fails unless there is exactly one.
std::string OnlyWarning(const char* config) {
  const std::vector<std::string> warnings = ConfigWarnings(ParseConfig(json::parse(config)));
  REQUIRE(warnings.size() == 1);
  return warnings[0];
}

TEST_CASE("a density below water's warns naming the key and t/m^3") {
  // 500 kg/m^3 is above the 100 kg/m^3 that the range refuses outright (timber is about 450).
  const std::string w = OnlyWarning(R"({"bridge": {"n": 3}, "material": {"density": 500}})");
  CHECK_THAT(w, Catch::Contains("material.density = 500 kg/m^3") && Catch::Contains("t/m^3"));
  // The threshold itself is plausible (below, not at).
  CHECK(ConfigWarnings(
            ParseConfig(json::parse(R"({"bridge": {"n": 3}, "material": {"density": 1000}})")))
            .empty());
  // A member kind's own density is read the same way, under its own key.
  const std::string strings = OnlyWarning(R"({"bridge": {"n": 3}, "material": {"strings": {"density": 500}}})");
  CHECK_THAT(strings, Catch::Contains("material.strings.density = 500 kg/m^3"));
  const std::string bars = OnlyWarning(R"({"bridge": {"n": 3}, "material": {"bars": {"density": 500}}})");
  CHECK_THAT(bars, Catch::Contains("material.bars.density = 500 kg/m^3"));
}

TEST_CASE("a favourable permanent factor of 0 warns naming the key, except in the paper's case") {
  const std::string w = OnlyWarning(R"({"bridge": {"n": 3}, "loads": {"gamma_g_inf": 0}})");
  CHECK_THAT(w, Catch::Contains("loads.gamma_g_inf = 0") && Catch::Contains("1.0"));
  // The paper's one unfactored case reads no partial factor.
  CHECK(ConfigWarnings(
            ParseConfig(json::parse(
                R"({"bridge": {"n": 3}, "loads": {"cases": ["paper"], "gamma_g_inf": 0}})")))
            .empty());
}

TEST_CASE("no shipped config gives a config warning") {
  int bridges = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(TBRIDGE_SOURCE_DIR "/configs")) {
    if (e.path().extension() != ".json") continue;
    json j = json::parse(std::ifstream(e.path()));
    if (!j.contains("bridge")) continue;  // a custom scene has no material or loads
    j.erase("sweep");                     // a sweep's grid sets n; its base is a normal config
    if (!j["bridge"].contains("n")) j["bridge"]["n"] = 1;
    INFO(e.path().filename().string());
    CHECK(ConfigWarnings(ParseConfig(j)).empty());
    ++bridges;
  }
  CHECK(bridges >= 30);  // the paper's tables, the footbridges, the 3D bridge, the sweep
}

}  // namespace
}  // namespace tbridge
