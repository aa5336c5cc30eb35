// Bad `loads` input: each is a ConfigError whose message names the offending key path.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "config_expect.h"
#include "core/config.h"

namespace tbridge {
namespace {

using nlohmann::json;

// A valid engineering config; each test replaces one part of its loads section.
json WithLoads(const json& loads) {
  json root = json::parse(R"({ "bridge": { "n": 2 } })");
  root["loads"] = loads;
  return root;
}

// The message names the key as the parser quotes it ('loads.x').
void ExpectKeyNamed(const json& loads, const std::string& key) {
  const std::string message = test::ConfigErrorOf([&] { ParseConfig(WithLoads(loads)); });
  INFO("message: " << message);
  CHECK(message.find("'" + key + "'") != std::string::npos);
}

TEST_CASE("a good loads section parses") {
  // The control: without it the rejections below could come from the rest of the file.
  const Config c =
      ParseConfig(WithLoads(json::parse(R"({"cases": ["permanent", "payload"], "gamma_q": 1.2})")));
  CHECK(c.loads.cases.size() == 2);
  CHECK(c.loads.gamma_q == 1.2);  // copied from the text, never computed: exact
}

TEST_CASE("bad loads input gets an error naming the key") {
  ExpectKeyNamed(json::parse(R"({"cases": ["earthquake"]})"), "loads.cases[0]");
  ExpectKeyNamed(json::parse(R"({"cases": ["permanent", "earthquake"]})"), "loads.cases[1]");
  ExpectKeyNamed(json::parse(R"({"gamma_q": -1})"), "loads.gamma_q");
  ExpectKeyNamed(json::parse(R"({"deflection_limit": 0})"), "loads.deflection_limit");
  ExpectKeyNamed(json::parse(R"({"cases": ["paper", "payload"]})"), "loads.cases");
  ExpectKeyNamed(json::parse(R"({"cases": ["payload", "paper"]})"), "loads.cases");
  ExpectKeyNamed(json::parse(R"({"gamma_g_sup": 1.2, "gamma_g_inf": 1.3})"), "loads.gamma_g_inf");
  // A planar bridge drops "wind" (design/load_cases.h), which would leave nothing to design for.
  ExpectKeyNamed(json::parse(R"({"cases": ["wind"]})"), "loads.cases");
}

TEST_CASE("the wind case alone is a case list for the 3D bridge") {
  // The control of the rule above: the 3D bridge carries wind, so the same list parses.
  json root = WithLoads(json::parse(R"({"cases": ["wind"]})"));
  root["bridge"]["planes"] = 2;
  CHECK(ParseConfig(root).loads.cases == std::vector<LoadFamily>{LoadFamily::kWind});
}

}  // namespace
}  // namespace tbridge
