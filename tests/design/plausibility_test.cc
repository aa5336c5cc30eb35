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
#include "design/design.h"
#include "design/sizing.h"

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

// The warnings of a config given as text.
std::vector<std::string> WarningsOf(const std::string& config) {
  return ConfigWarnings(ParseConfig(json::parse(config)));
}

TEST_CASE("a payload under 0.5 kPa or over 50 kPa of deck area warns naming the key") {
  // 12 m x 1.5 m = 18 m^2: 0.5 kPa is 9000 N, 50 kPa 900 000 N; the thresholds are plausible.
  CHECK(WarningsOf(R"({"bridge": {"n": 3, "payload": 9000}})").empty());
  CHECK(WarningsOf(R"({"bridge": {"n": 3, "payload": 900000}})").empty());
  const std::string low = OnlyWarning(R"({"bridge": {"n": 3, "payload": 8990}})");
  CHECK_THAT(low, Catch::Contains("bridge.payload = 8990 N") && Catch::Contains("0.499 kPa") &&
                      Catch::Contains("below 0.5 kPa") && Catch::Contains("2.5 to 5 kPa") &&
                      Catch::Contains("kN"));
  const std::string high = OnlyWarning(R"({"bridge": {"n": 3, "payload": 900100}})");
  CHECK_THAT(high, Catch::Contains("bridge.payload = 900100 N") &&
                       Catch::Contains("above 50 kPa") && Catch::Contains("2.5 to 5 kPa"));
  // A crowd given in kN: 337.5 on 20 m x 2 m is 8.4 Pa.
  const std::string kn =
      OnlyWarning(R"({"bridge": {"n": 3, "span": 20, "deck_width": 2, "payload": 337.5}})");
  CHECK_THAT(kn, Catch::Contains("bridge.payload = 337.5 N") && Catch::Contains("0.00844 kPa"));
}

TEST_CASE("a deck over 30 m wide warns naming the key and mm") {
  // The payload keeps 2.5 kPa of deck area, so the width is the only warning.
  CHECK(WarningsOf(R"({"bridge": {"n": 3, "deck_width": 30, "payload": 900000}})").empty());
  const std::string w =
      OnlyWarning(R"({"bridge": {"n": 3, "deck_width": 30.01, "payload": 900000}})");
  CHECK_THAT(w, Catch::Contains("bridge.deck_width = 30.01 m") &&
                    Catch::Contains("wider than 30 m") && Catch::Contains("mm"));
  // A width given in mm warns of the width, and of the payload it spreads thin.
  const std::vector<std::string> mm = WarningsOf(R"({"bridge": {"n": 3, "deck_width": 2500}})");
  REQUIRE(mm.size() == 2);
  CHECK_THAT(mm[1],
             Catch::Contains("bridge.deck_width = 2500 m") && Catch::Contains("2500 mm is 2.5 m"));
}

// A design of `config` with one string of diameter `diameter` and a whole mass of `total`,
// every other quantity plausible: what PlausibilityWarnings reads, nothing designed.
Design Sketch(const char* config, double diameter, double total) {
  Design d;
  d.config = ParseConfig(json::parse(config));
  d.deck.thickness = 0.02;
  MemberSizing bar;
  bar.name = "1-2";
  bar.kind = MemberKind::kBar;
  bar.length = 3;
  bar.radius = 0.05;
  MemberSizing string = bar;
  string.name = "2-3";
  string.kind = MemberKind::kString;
  string.radius = diameter / 2;
  d.bars = {bar};
  d.strings = {string};
  d.mass.bars = d.mass.strings = d.mass.structure = 100;
  d.mass.total = total;
  return d;
}

TEST_CASE("a string over 200 mm in diameter warns naming the member") {
  const char* config = R"({"bridge": {"n": 3}})";
  CHECK(PlausibilityWarnings(Sketch(config, 0.2, 1000)).empty());
  const std::vector<std::string> w = PlausibilityWarnings(Sketch(config, 0.201, 1000));
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::Contains("1 string thicker than 200 mm") &&
                       Catch::Contains("worst 2-3") && Catch::Contains("diameter 201 mm"));
  // A bar of that diameter is no string.
  Design bar = Sketch(config, 0.01, 1000);
  bar.bars[0].radius = 0.15;
  CHECK(PlausibilityWarnings(bar).empty());
}

TEST_CASE("a bridge over 3 t per metre of span warns naming the mass and the span") {
  // The default 12 m span: 3 t/m is 36 000 kg.
  const char* config = R"({"bridge": {"n": 3}})";
  CHECK(PlausibilityWarnings(Sketch(config, 0.02, 36000)).empty());
  const std::vector<std::string> w = PlausibilityWarnings(Sketch(config, 0.02, 36010));
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::Contains("mass.total = 36010 kg") &&
                       Catch::Contains("3 t per metre of the 12 m span") &&
                       Catch::Contains("above 3 t/m"));
}

TEST_CASE("the paper's switches raise none of the engineering warnings") {
  // Each value beyond its threshold, with the paper's one case: the paper's blanket factor of
  // 10 and its 12 kN are its own.
  CHECK(
      WarningsOf(R"({"bridge": {"n": 3, "payload": 10}, "loads": {"cases": ["paper"]}})").empty());
  CHECK(
      WarningsOf(R"({"bridge": {"n": 3, "payload": 1e9}, "loads": {"cases": ["paper"]}})").empty());
  CHECK(
      WarningsOf(
          R"({"bridge": {"n": 3, "deck_width": 2500, "payload": 1e8}, "loads": {"cases": ["paper"]}})")
          .empty());
  const char* paper = R"({"bridge": {"n": 3}, "loads": {"cases": ["paper"]}})";
  CHECK(PlausibilityWarnings(Sketch(paper, 0.5, 1e6)).empty());
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
