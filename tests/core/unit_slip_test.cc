// Values given in the wrong unit (a span in mm, an angle in radians, a modulus in GPa) are
// refused by the ends of their keys' ranges, and the message names the key and the unit the
// value was likely given in; numbers in messages carry at most 6 significant digits.

#include <catch2/catch.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "config_expect.h"
#include "core/config.h"
#include "core/error.h"

namespace tbridge {
namespace {

using nlohmann::json;
using test::ConfigErrorOf;

// The message of the ConfigError the config `text` is refused with.
std::string Refusal(const std::string& text) {
  return ConfigErrorOf([&] { ParseConfig(json::parse(text)); });
}

// `message` names every fragment of `named`.
void ExpectNames(const std::string& message, std::initializer_list<const char*> named) {
  INFO("message: " << message);
  for (const char* fragment : named) CHECK(message.find(fragment) != std::string::npos);
  // At most 6 significant digits: no run of 7 digits (std::to_string writes 1e160 in 161).
  CHECK_FALSE(std::regex_search(message, std::regex("[0-9]{7}")));
}

TEST_CASE("unit slips are refused naming the key and the likely unit") {
  // The conversions are printf's %g of value x factor: 30000 mm = 30 m; 0.349 rad =
  // 0.349 x 180 / pi = 19.9962 deg; 7.85 t/m^3 = 7850 kg/m^3; 355 MPa = 3.55e+08 Pa.
  ExpectNames(Refusal(R"({"bridge": {"n": 3, "span": 30000}})"),
              {"'bridge.span' = 30000", "(0, 2000]", "mm", "30000 mm is 30 m"});
  ExpectNames(Refusal(R"({"bridge": {"n": 3, "beta_deg": 0.349}})"),
              {"'bridge.beta_deg' = 0.349", "[1, 90)", "radians", "0.349 rad is 19.9962 deg"});
  ExpectNames(Refusal(R"({"bridge": {"n": 3}, "material": {"density": 7.85}})"),
              {"'material.density' = 7.85", ">= 100", "t/m^3 or g/cm^3", "7850 kg/m^3"});
  ExpectNames(Refusal(R"({"bridge": {"n": 3}, "material": {"youngs_modulus": 210}})"),
              {"'material.youngs_modulus' = 210", ">= 1e+09", "GPa", "MPa"});
  ExpectNames(Refusal(R"({"bridge": {"n": 3}, "material": {"yield_stress": 355}})"),
              {"'material.yield_stress' = 355", ">= 1e+06", "MPa", "3.55e+08 Pa"});
}

TEST_CASE("a Young's modulus at or below the yield stress is refused naming both") {
  // Both above their own slips' ends (1e9 and 1e6 Pa), but a strain at yield of 1.5.
  ExpectNames(
      Refusal(R"({"bridge": {"n": 3}, "material": {"youngs_modulus": 2e9, "yield_stress": 3e9}})"),
      {"'material.youngs_modulus' = 2e+09", "material.yield_stress = 3e+09", "1.5"});
}

TEST_CASE("Validate refuses the same slips in a config built in code, with the same message") {
  Config span;
  span.bridge.n = 3;
  span.bridge.span = 30000;
  CHECK(ConfigErrorOf([&] { Validate(span); }) ==
        Refusal(R"({"bridge": {"n": 3, "span": 30000}})"));
  Config modulus;
  modulus.bridge.n = 3;
  modulus.material.youngs_modulus = 2e9;
  modulus.material.yield_stress = 3e9;
  CHECK(
      ConfigErrorOf([&] { Validate(modulus); }) ==
      Refusal(R"({"bridge": {"n": 3}, "material": {"youngs_modulus": 2e9, "yield_stress": 3e9}})"));
}

TEST_CASE("a partial factor of 0 is refused naming the key, except gamma_g_inf") {
  for (const char* key : {"gamma_g_sup", "gamma_q", "gamma_w"}) {
    json j = json::parse(R"({"bridge": {"n": 3}, "loads": {"gamma_g_inf": 0}})");
    j["loads"][key] = 0;
    const std::string message = Refusal(j.dump());
    ExpectNames(message, {"(0, 10]", "partial factor of 0"});
    CHECK(message.find("'loads." + std::string(key) + "' = 0") != std::string::npos);
  }
  // 0 on the favourable permanent action has a meaning (G left out where it helps), so it
  // parses; the design warns of it (design/plausibility.h).
  const Config c = ParseConfig(json::parse(R"({"bridge": {"n": 3}, "loads": {"gamma_g_inf": 0}})"));
  CHECK(c.loads.gamma_g_inf == 0);  // copied from the text: exact
}

TEST_CASE("a value outside its range that is no slip gets no slip note") {
  // A negative span or a zero density is no unit slip: the range alone is said.
  const std::string negative = Refusal(R"({"bridge": {"n": 3, "span": -12}})");
  CHECK(negative.find("mm") == std::string::npos);
  const std::string zero = Refusal(R"({"bridge": {"n": 3}, "material": {"density": 0}})");
  CHECK(zero.find("t/m^3") == std::string::npos);
}

TEST_CASE("NumberText prints what printf's %g prints: at most 6 significant digits") {
  for (const double v : {1e160, 30000.0, 0.349, 19.99620, 1.0 / 3.0, 123456789.0, -2.5e-300}) {
    char expected[32];
    std::snprintf(expected, sizeof expected, "%g", v);  // the independent truth: C's %g
    CHECK(NumberText(v) == expected);
  }
}

}  // namespace
}  // namespace tbridge
