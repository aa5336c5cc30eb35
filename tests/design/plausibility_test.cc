// Config values inside their ranges that are still no bridge practice give a plausibility
// warning naming the key and the likely slip; no shipped config gives one. A designed bridge's
// results warn too; the abutment thrust warning is true of every shipped engineering bridge,
// whose prestress against its supports sets the thrust (tests/tools/trust_cli_test.cc).

#include "design/plausibility.h"

#include <Eigen/Core>
#include <algorithm>
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
  const std::string strings =
      OnlyWarning(R"({"bridge": {"n": 3}, "material": {"strings": {"density": 500}}})");
  CHECK_THAT(strings, Catch::Contains("material.strings.density = 500 kg/m^3"));
  const std::string bars =
      OnlyWarning(R"({"bridge": {"n": 3}, "material": {"bars": {"density": 500}}})");
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

TEST_CASE(
    "a solid plate deck heavier than 40 mm of steel warns naming the key that gives girders") {
  const char* config = R"({"bridge": {"n": 1, "deck_width": 2}})";
  // 314 kg/m^2 is the limit: 40 mm of steel at 7850 kg/m^3.
  Design d = Sketch(config, 0.02, 1000);
  d.deck.section_length = 6;
  d.deck.thickness = 0.04;
  d.deck.section_mass = 7850 * 2 * 6 * 0.04;
  d.deck.sized_by = "sag (sls_payload_full)";
  CHECK(PlausibilityWarnings(d).empty());
  d.deck.thickness = 0.0401;
  d.deck.section_mass = 7850 * 2 * 6 * 0.0401;
  const std::vector<std::string> w = PlausibilityWarnings(d);
  REQUIRE(w.size() == 1);
  CHECK_THAT(w[0], Catch::Contains("solid plate 40.1 mm thick") && Catch::Contains("l = 6 m") &&
                       Catch::Contains("315 kg/m^2") &&
                       Catch::Contains("design.deck_section \"girders\""));
  // Girders of that mass are what the warning asks for.
  d.deck.girder_depth = 0.3;
  CHECK(PlausibilityWarnings(d).empty());
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

// The n = 1 bridge of `config` on the default 12 m span at beta = 10 deg, drawn: its one
// substructure node lies d = 6 m x tan(5 deg) = 0.524932 m under mid-span, so the vertical load
// W = 10 kN has the thrust W L / (8 d) = 10 kN x 12 m / (8 x 0.524932 m) = 28.5751 kN. One
// case, of limit state `state`, whose supports share W and take `h` [N] horizontally outwards
// at each end, split between the end's nodes, each node also taking `transverse` [N] across
// the bridge away from the other plane (which the end's in-plan sum cancels).
constexpr double kW = 10000;                 // [N]
constexpr double kThrust = 28575.130756903;  // [N], W L / (8 d) as above
Design Abutments(const char* config, double h, LimitState state = LimitState::kUltimate,
                 double transverse = 0) {
  Design d = Sketch(config, 0.02, 1000);
  d.topology = MakeBridge(d.config.bridge);
  const Structure& s = d.topology.structure;
  LoadCase c;
  c.name = "uls_payload_full";
  c.state = state;
  d.cases = {c};
  CaseResponse r;
  r.label = c.name;
  r.case_index = 0;
  r.converged = true;
  r.reactions = Eigen::Matrix3Xd::Zero(3, s.num_nodes());
  const double supports = static_cast<double>(std::count(s.fixed.begin(), s.fixed.end(), true));
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (!s.fixed[v]) continue;
    r.reactions(0, v) = (s.nodes(0, v) < 6 ? -h : h) / (supports / 2);
    r.reactions(1, v) = kW / supports;
    r.reactions(2, v) = s.nodes(2, v) > 0 ? transverse : -transverse;
  }
  d.statics.done = true;
  d.statics.cases = {r};
  return d;
}

TEST_CASE("an abutment thrust over twice the load's own W L / (8 d) warns naming the abutment") {
  const char* planar = R"({"bridge": {"n": 1}})";
  // At twice the thrust the load can explain it (all of W at mid-span): plausible.
  CHECK(PlausibilityWarnings(Abutments(planar, 2 * kThrust * (1 - 1e-9))).empty());
  const std::vector<std::string> w = PlausibilityWarnings(Abutments(planar, 2 * kThrust * 1.001));
  REQUIRE(w.size() == 1);
  // 2 x 28.5751 kN x 1.001 = 57.2074 kN, 2.002 times; both ends alike, x = 0 named first.
  CHECK_THAT(w[0], Catch::Contains("the abutment at x = 0 m (node 3) takes a horizontal reaction "
                                   "H = 57.21 kN (uls_payload_full), 2 times") &&
                       Catch::Contains("W L / (8 d) = 28.58 kN (W = 10 kN") &&
                       Catch::Contains("L = 12 m; d = 0.525 m") &&
                       Catch::Contains("the abutment at x = 12 m (node 4) takes 57.21 kN") &&
                       Catch::Contains("prestress, not the load, sets the thrust") &&
                       Catch::Contains("stressed ribbon's anchorage"));
  // A serviceability case's reactions are not the abutment's design load.
  CHECK(PlausibilityWarnings(Abutments(planar, 10 * kThrust, LimitState::kServiceability)).empty());
  // The 3D bridge: an abutment is the two supports at one end, its H their in-plan vector sum.
  // Each node's transverse 1000 kN cancels in the sum; below twice the thrust still plausible.
  const char* coupled = R"({"bridge": {"n": 1, "planes": 2}})";
  CHECK(
      PlausibilityWarnings(Abutments(coupled, 2 * kThrust * (1 - 1e-9), LimitState::kUltimate, 1e6))
          .empty());
  const std::vector<std::string> w3 =
      PlausibilityWarnings(Abutments(coupled, 2 * kThrust * 1.001, LimitState::kUltimate, 1e6));
  REQUIRE(w3.size() == 1);
  CHECK_THAT(w3[0], Catch::Contains("the abutment at x = 0 m (nodes ") &&
                        Catch::Contains(" and ") && Catch::Contains("H = 57.21 kN") &&
                        Catch::Contains("d = 0.525 m"));
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
  // An abutment thrust ten times the load's: the paper's one case designs no abutment.
  CHECK(PlausibilityWarnings(Abutments(paper, 10 * kThrust)).empty());
}

// The config's warnings only: the designs of default.json and footbridge_*.json warn of their
// abutment thrust, which is true of them (tests/tools/trust_cli_test.cc).
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
