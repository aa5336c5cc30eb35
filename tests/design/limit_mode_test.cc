// What governs a member (design/limit_mode.h): one table gives each mode its text and reads it
// back, the sizing's rows name the modes the outputs always wrote, and a design file whose mode
// or governed_by names no mode is refused naming the key, the text and the texts allowed.

#include "design/limit_mode.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "core/error.h"
#include "design/design.h"
#include "io/design_reader.h"
#include "io/design_report.h"
#include "sizing/sizing_problem.h"

namespace tbridge {
namespace {

nlohmann::json FileOf(const Design& d) {
  std::ostringstream text;
  WriteDesignJson(d, text);
  return nlohmann::json::parse(text.str());
}

}  // namespace

TEST_CASE("limit mode: every value has its own text and reads back from it", "[design]") {
  std::set<std::string> seen;
  for (int v = 0; v <= static_cast<int>(LimitMode::kPrestress); ++v) {
    const auto mode = static_cast<LimitMode>(v);
    const std::string name = NameOf(mode);
    INFO("value " << v << " \"" << name << "\"");
    // Only kNone is written as "" (a member no check reached); every other value has a text.
    CHECK(name.empty() == (mode == LimitMode::kNone));
    CHECK(seen.insert(name).second);
    const std::optional<LimitMode> back = LimitModeNamed(name);
    REQUIRE(back.has_value());
    CHECK(*back == mode);
  }
  CHECK(seen.size() == kLimitModeNames.size());  // the table holds each value once, no more
  CHECK_FALSE(LimitModeNamed("Yield").has_value());
  CHECK_FALSE(LimitModeNamed("yield ").has_value());
}

TEST_CASE("limit mode: the sizing's rows name the texts its outputs write", "[design]") {
  // The texts the design file and the tables carry for each row kind (scripts read them).
  const std::pair<SizingRow::Kind, const char*> expected[] = {
      {SizingRow::kStrength, "yield"},
      {SizingRow::kBuckling, "buckling"},
      {SizingRow::kYield, "yield"},
      {SizingRow::kTaut, "taut"},
      {SizingRow::kDeflectionDown, "deflection"},
      {SizingRow::kDeflectionUp, "deflection"},
      {SizingRow::kReferenceTaut, "reference_taut"},
      {SizingRow::kServiceStress, "serviceability"},
      {SizingRow::kSupportHorizontal, "supports"},
      {SizingRow::kSupportVertical, "supports"},
      {SizingRow::kComfort, "comfort"}};
  for (const auto& [kind, text] : expected) {
    INFO("row kind " << static_cast<int>(kind));
    CHECK(std::string(SizingRowKindName(kind)) == text);
    CHECK(LimitModeNamed(text) == ModeOfRow(kind));
  }
}

TEST_CASE("limit mode: a design file reads its modes back, and an unknown text is refused",
          "[design]") {
  Config config;
  config.bridge.n = 1;
  const Design d = RunDesign(config);
  nlohmann::json file = FileOf(d);
  const Design read = ReadDesign(file);
  REQUIRE(read.bars.size() == d.bars.size());
  REQUIRE(read.strings.size() == d.strings.size());
  for (int k = 0; k < d.topology.structure.num_members(); ++k) {
    const MemberSizing& was = d.MemberAt(k);
    const MemberSizing& now = read.MemberAt(k);
    INFO("member " << was.name);
    CHECK(now.mode == was.mode);
    CHECK(now.governed_by == was.governed_by);
  }
  // The control: the bar's mode is a real one, so the refusal below is of the text alone.
  REQUIRE(d.bars[0].mode != LimitMode::kNone);

  // A file that leaves them out (null) reads them as none.
  nlohmann::json unset = file;
  unset["members"][0]["mode"] = nullptr;
  unset["members"][0].erase("governed_by");
  CHECK(ReadDesign(unset).bars[0].mode == LimitMode::kNone);
  CHECK(ReadDesign(unset).bars[0].governed_by == LimitMode::kNone);

  for (const char* key : {"mode", "governed_by"}) {
    nlohmann::json bad = file;
    bad["members"][0][key] = "yeild";
    INFO("key " << key);
    CHECK_THROWS_MATCHES(
        ReadDesign(bad), ConfigError,
        Catch::Matchers::Predicate<ConfigError>(
            [&](const ConfigError& e) { return e.key() == std::string("members[0].") + key; },
            "names the key"));
    CHECK_THROWS_WITH(ReadDesign(bad), Catch::Contains("\"yeild\"") &&
                                           Catch::Contains("\"yield\", \"buckling\"") &&
                                           Catch::Contains("\"prestress\""));
    bad["members"][0][key] = 5;  // not a text: refused, not read as none
    CHECK_THROWS_WITH(ReadDesign(bad),
                      Catch::Contains("members[0]." + std::string(key)) && Catch::Contains("= 5:"));
  }
}

}  // namespace tbridge
