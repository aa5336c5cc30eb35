// Strict config parsing: every bad input is a ConfigError whose message names the key path,
// the value seen and what is allowed (configs/README.md lists the same ranges).

#include "core/config.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "config_expect.h"
#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {
namespace {

using nlohmann::json;
using test::ConfigErrorOf;
using test::ExpectRejected;

// A valid config with the paper's n = 3 parameters; tests break one key at a time.
json GoodConfig() {
  return json::parse(R"({
    "bridge":   { "n": 3, "p": 1, "beta_deg": 10, "span": 12.0, "payload": 12000.0,
                  "deck_width": 1.5, "planes": 1 },
    "material": { "density": 7862, "yield_stress": 6.9e8, "youngs_modulus": 2.06e11 },
    "design":   { "yield_safety_factor": 10, "buckling_safety_factor": 1,
                  "deck_string_min_radius": 0.01, "gravity": 9.81, "solver": "ipopt" } })");
}

std::filesystem::path TempDir() {
  const auto dir = std::filesystem::temp_directory_path() / "tbridge_config_test";
  std::filesystem::create_directories(dir);
  return dir;
}

std::string WriteText(const std::string& name, const std::string& text) {
  const auto path = TempDir() / name;
  std::ofstream(path) << text;
  return path.string();
}

TEST_CASE("the good config parses to the paper's values") {
  const Config c = ParseConfig(GoodConfig());
  // Exact comparisons: the values are copied from the JSON text, never computed.
  CHECK(c.bridge.n == 3);
  CHECK(c.bridge.p == 1);
  CHECK(c.bridge.beta_deg == 10.0);
  CHECK(c.bridge.span == 12.0);
  CHECK(c.material.yield_stress == 6.9e8);
  CHECK(c.design.solver == SolverKind::kIpopt);
  CHECK_FALSE(c.dynamics.has_value());
}

TEST_CASE("absent optional keys take their documented defaults") {
  const Config c = ParseConfig(json::parse(R"({"bridge": {"n": 2}})"));
  // Exact: defaults are literal constants of the config structs (SPEC.md §1 values for the
  // bridge and material; EN 1993-2's gamma_M1 = 1.1 and EN 1990's combination factors for
  // the design and loads, configs/README.md).
  CHECK(c.bridge.p == 1);
  CHECK(c.bridge.beta_deg == 10.0);
  CHECK(c.bridge.span == 12.0);
  CHECK(c.bridge.payload == 12000.0);
  CHECK(c.bridge.deck_width == 1.5);
  CHECK(c.bridge.planes == 1);
  CHECK(c.material.density == 7862.0);
  CHECK(c.material.yield_stress == 6.9e8);
  CHECK(c.material.youngs_modulus == 2.06e11);
  CHECK(c.design.yield_safety_factor == 1.1);
  CHECK(c.design.buckling_safety_factor == 1.1);
  CHECK(c.design.self_weight);
  CHECK(c.design.bar_resistance == BarResistanceRule::kColumnCurve);
  CHECK(c.loads.gamma_g_sup == 1.35);
  CHECK(c.loads.gamma_q == 1.5);
  CHECK(c.design.deck_string_min_radius == 0.01);
  CHECK(c.design.gravity == 9.81);
  CHECK(c.design.solver == SolverKind::kAuto);
}

TEST_CASE("the resolved config parses back to itself") {
  const Config c = LoadConfig(TBRIDGE_SOURCE_DIR "/configs/default.json");
  const json echoed = ToJson(c);
  // Exact: ToJson writes doubles with round-trip precision, so nothing may change.
  CHECK(ToJson(ParseConfig(echoed)) == echoed);
  // configs/default.json spells out every key of these sections: the echo adds none.
  const json file = ReadJsonFile(TBRIDGE_SOURCE_DIR "/configs/default.json");
  for (const char* section : {"bridge", "material", "design", "loads"}) {
    INFO("section " << section);
    CHECK(echoed[section].size() == file[section].size());
  }
}

TEST_CASE("the temperature case and its change are given together") {
  json asked = GoodConfig();
  asked["loads"] = {{"cases", {"permanent", "temperature"}}};
  ExpectRejected(asked, "loads.temperature_delta_k", "0", "must be > 0 with \"temperature\"");
  json given = GoodConfig();
  given["loads"] = {{"temperature_delta_k", 25}};
  ExpectRejected(given, "loads.temperature_delta_k", "25", "needs \"temperature\" in loads.cases");
  json alone = GoodConfig();
  alone["loads"] = {{"cases", {"temperature"}}, {"temperature_delta_k", 25}};
  ExpectRejected(alone, "loads.cases", "[\"temperature\"]", "accompanies the other cases");
  json unit = GoodConfig();
  unit["material"]["thermal_expansion"] = 12;
  ExpectRejected(unit, "material.thermal_expansion", "12", "1e-6/K");
  json both = GoodConfig();
  both["loads"] = {{"cases", {"permanent", "temperature"}}, {"temperature_delta_k", 25}};
  const Config c = ParseConfig(both);
  CHECK(c.loads.temperature_delta_k == 25);
}

TEST_CASE("unknown keys are rejected at every level") {
  json top = GoodConfig();
  top["brige"] = json::object();
  ExpectRejected(top, "brige", "{}", "unknown key");

  json nested = GoodConfig();
  nested["bridge"]["spam"] = 1;
  ExpectRejected(nested, "bridge.spam", "1", "unknown key");

  json design = GoodConfig();
  design["design"]["solvr"] = "ipopt";
  ExpectRejected(design, "design.solvr", "\"ipopt\"", "unknown key");
}

TEST_CASE("bridge.beta_deg takes an angle or auto searched in design.beta_range_deg") {
  json automatic = GoodConfig();
  automatic["design"]["yield_safety_factor"] = 1.1;  // an engineering design, not the paper's
  automatic["bridge"]["beta_deg"] = "auto";
  const Config c = ParseConfig(automatic);
  CHECK(c.bridge.beta_auto);
  CHECK(c.design.beta_range_deg == std::vector<double>{10.0, 60.0});
  const json echoed = ToJson(c);
  CHECK(echoed["bridge"]["beta_deg"] == "auto");
  CHECK(ToJson(ParseConfig(echoed)) == echoed);
  CHECK_NOTHROW(Validate(c));
  // Any other text is refused, naming the key and both forms allowed.
  json other = automatic;
  other["bridge"]["beta_deg"] = "automatic";
  ExpectRejected(other, "bridge.beta_deg", "\"automatic\"", "or \"auto\"");
  // The range: two angles, the first below the second, each an angle.
  for (const json& range :
       {json::array({60.0, 10.0}), json::array({10.0}), json::array({10.0, 20.0, 30.0})}) {
    json bad = automatic;
    bad["design"]["beta_range_deg"] = range;
    ExpectRejected(bad, "design.beta_range_deg", range.dump(),
                   "two angles [low, high] with low < high");
  }
  json beyond = automatic;
  beyond["design"]["beta_range_deg"] = json::array({10.0, 95.0});
  ExpectRejected(beyond, "design.beta_range_deg[1]", "95", "[1, 90)");
  // The paper's design is checked at its own angle, never searched.
  json paper = automatic;
  paper["loads"] = {{"cases", {"paper"}}};
  ExpectRejected(paper, "bridge.beta_deg", "\"auto\"",
                 "must be a number with loads.cases [\"paper\"]");
}

TEST_CASE("wrong types are rejected") {
  json n_text = GoodConfig();
  n_text["bridge"]["n"] = "3";
  ExpectRejected(n_text, "bridge.n", "\"3\"", "an integer in [1, 16]");

  json beta_text = GoodConfig();
  beta_text["bridge"]["beta_deg"] = "10";
  ExpectRejected(beta_text, "bridge.beta_deg", "\"10\"", "[1, 90)");

  json solver_number = GoodConfig();
  solver_number["design"]["solver"] = 3;
  ExpectRejected(solver_number, "design.solver", "3",
                 "one of \"auto\", \"direct\", \"ipopt\", \"nlopt\"");

  json section_number = GoodConfig();
  section_number["material"] = 5;
  ExpectRejected(section_number, "material", "5", "must be a JSON object");

  json root_array = json::array({1, 2});
  ExpectRejected(root_array, "(root)", "[1,2]", "must be a JSON object");

  json n_fraction = GoodConfig();
  n_fraction["bridge"]["n"] = 2.5;
  ExpectRejected(n_fraction, "bridge.n", "2.5", "an integer in [1, 16]");
}

TEST_CASE("a missing required key is named") {
  json no_n = GoodConfig();
  no_n["bridge"].erase("n");
  ExpectRejected(no_n, "bridge.n", "(missing)", "required");

  json no_bridge = GoodConfig();
  no_bridge.erase("bridge");
  ExpectRejected(no_bridge, "bridge", "(missing)", "required");
}

TEST_CASE("complexity n outside [1, 16] is rejected") {
  for (int n : {0, -1, 17, 1000}) {
    json c = GoodConfig();
    c["bridge"]["n"] = n;
    ExpectRejected(c, "bridge.n", std::to_string(n), "an integer in [1, 16]");
  }
}

TEST_CASE("beta outside the half-open interval from 1 to 90 deg is rejected") {
  // Below 1 deg is an angle given in radians (tests/core/unit_slip_test.cc); 90 deg and more
  // draw no bridge.
  for (double beta : {0.0, 0.5, 90.0, -5.0, 120.0}) {
    json c = GoodConfig();
    c["bridge"]["beta_deg"] = beta;
    ExpectRejected(c, "bridge.beta_deg", json(beta).dump(), "a number in [1, 90)");
  }
  // Anything inside, 1 deg included, is a valid (if odd) bridge.
  for (double beta : {1.0, 89.9}) {
    json inside = GoodConfig();
    inside["bridge"]["beta_deg"] = beta;
    CHECK(ParseConfig(inside).bridge.beta_deg == beta);  // exact: copied from JSON
  }
}

TEST_CASE("zero or negative span, payload, stresses and moduli are rejected") {
  struct Case {
    const char* section;
    const char* key;
    const char* allowed;  // the key's range: above 0, or above the end that catches unit slips
  };
  const std::vector<Case> positive = {{"bridge", "span", "a number in (0, 2000]"},
                                      {"bridge", "payload", "a number > 0"},
                                      {"bridge", "deck_width", "a number > 0"},
                                      {"material", "density", "a number >= 100"},
                                      {"material", "yield_stress", "a number >= 1e+06"},
                                      {"material", "youngs_modulus", "a number >= 1e+09"}};
  for (const Case& k : positive) {
    for (double v : {0.0, -12.0}) {
      json c = GoodConfig();
      c[k.section][k.key] = v;
      ExpectRejected(c, std::string(k.section) + "." + k.key, json(v).dump(), k.allowed);
    }
  }
}

TEST_CASE("safety factors below 1 are rejected") {
  for (const char* key : {"yield_safety_factor", "buckling_safety_factor"}) {
    json c = GoodConfig();
    c["design"][key] = 0.5;
    ExpectRejected(c, std::string("design.") + key, "0.5", "a number in [1, 1000]");
  }
}

TEST_CASE("NaN and infinite numbers are rejected") {
  // JSON text cannot spell NaN or Infinity, but a json value built in code can hold them.
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    json c = GoodConfig();
    c["bridge"]["span"] = bad;
    // nlohmann shows a non-finite number as null.
    ExpectRejected(c, "bridge.span", "null", "a number in (0, 2000]");
  }
  json huge_n = GoodConfig();
  huge_n["bridge"]["n"] = 1e300;
  ExpectRejected(huge_n, "bridge.n", "1e+300", "an integer in [1, 16]");
}

TEST_CASE("NaN spelled in the file is malformed JSON naming the file") {
  const std::string path = WriteText("nan.json", R"({"bridge": {"n": 3, "span": NaN}})");
  const std::string message = ConfigErrorOf([&] { LoadConfig(path); });
  INFO("message: " << message);
  CHECK(message.find(path) != std::string::npos);
  CHECK(message.find("malformed JSON") != std::string::npos);
}

TEST_CASE("a number too large for a double (1e999) names its key") {
  const std::string path = WriteText("huge.json", R"({"bridge": {"n": 3, "span": 1e999}})");
  const std::string message = ConfigErrorOf([&] { LoadConfig(path); });
  INFO("message: " << message);
  CHECK(message.find(path) != std::string::npos);
  CHECK(message.find("bridge.span") != std::string::npos);
  CHECK(message.find("1e999") != std::string::npos);
}

TEST_CASE("a key given twice in one object is rejected, not silently overwritten") {
  // JSON parsers keep the last of two equal keys; a config with {"n": 3, "n": 4} would
  // quietly design n = 4.
  const std::string path = WriteText("duplicate.json", R"({"bridge": {"n": 3, "n": 4}})");
  const std::string message = ConfigErrorOf([&] { LoadConfig(path); });
  INFO("message: " << message);
  CHECK(message.find("bridge.n") != std::string::npos);
}

TEST_CASE("malformed JSON names the file and the position") {
  const std::string path = WriteText("trailing_comma.json", R"({"bridge": {"n": 3,}})");
  const std::string message = ConfigErrorOf([&] { LoadConfig(path); });
  INFO("message: " << message);
  CHECK(message.find(path) != std::string::npos);
  CHECK(message.find("malformed JSON") != std::string::npos);
  CHECK(message.find("line 1") != std::string::npos);

  const std::string empty = WriteText("empty.json", "");
  const std::string empty_message = ConfigErrorOf([&] { LoadConfig(empty); });
  INFO("message: " << empty_message);
  CHECK(empty_message.find(empty) != std::string::npos);
}

TEST_CASE("an unreadable config file is named") {
  const std::string missing = (TempDir() / "no_such_dir" / "config.json").string();
  const std::string message = ConfigErrorOf([&] { LoadConfig(missing); });
  INFO("message: " << message);
  CHECK(message.find(missing) != std::string::npos);
  CHECK(message.find("cannot open") != std::string::npos);

  // A directory opens as a stream on Linux but has no JSON in it.
  const std::string dir = TempDir().string();
  const std::string dir_message = ConfigErrorOf([&] { LoadConfig(dir); });
  INFO("message: " << dir_message);
  CHECK(dir_message.find(dir) != std::string::npos);
}

}  // namespace
}  // namespace tbridge
