// `tbridge check`: the checks of a written design run again on the file, as written. The same
// design checked in memory (tbridge design) and from its file must agree; a member edited
// consistently (area, radius, mass, stiffness) is checked as built, its reference state
// re-derived; a file whose members are not self-consistent, or whose config no longer matches
// them, is refused with the key; a design that fails a check exits 1.

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <tuple>

#include "cli_support.h"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using tbridge::test::FreshDir;
using tbridge::test::Quote;
using tbridge::test::ReadText;
using tbridge::test::RunTbridge;

json ReadJson(const fs::path& path) { return json::parse(ReadText(path)); }

void WriteJson(const fs::path& path, const json& j) { std::ofstream(path) << j.dump(2); }

// dir/design.json, the design `tbridge design` writes for configs/NAME.
fs::path DesignFile(const fs::path& dir, const std::string& name) {
  const fs::path design = dir / "design.json";
  const std::string config = std::string(TBRIDGE_SOURCE_DIR) + "/configs/" + name;
  const int code =
      RunTbridge(dir, "design " + Quote(config) + " -q -o " + Quote(design.string())).code;
  // Written whatever the verdict; the exit says it (1 for the paper's design, which fails).
  REQUIRE(code == tbridge::test::VerdictExit(design));
  return design;
}

TEST_CASE("check: the written default design, checked from its file, gives the design's checks",
          "[tools]") {
  const fs::path dir = FreshDir("check_default");
  const fs::path design = DesignFile(dir, "default.json"), checked = dir / "checked.json";
  const auto r =
      RunTbridge(dir, "check " + Quote(design.string()) + " -o " + Quote(checked.string()));
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("PASS") && Catch::Contains("read from its file"));
  const json a = ReadJson(design), b = ReadJson(checked);
  // The same runs on the same bridge, once from memory and once from the file's 17 digits:
  // 1e-9 relative leaves the rounding of a reread, a chaotic run would differ at once.
  REQUIRE(a["dynamic_check"]["runs"].size() == b["dynamic_check"]["runs"].size());
  for (size_t k = 0; k < a["dynamic_check"]["runs"].size(); ++k) {
    const json& x = a["dynamic_check"]["runs"][k];
    const json& y = b["dynamic_check"]["runs"][k];
    INFO("run " << x["name"]);
    CHECK(y["peak_deck_displacement"].get<double>() ==
          Approx(x["peak_deck_displacement"].get<double>()).epsilon(1e-9));
  }
  REQUIRE(a["deflection_max"].size() == b["deflection_max"].size());
  for (size_t k = 0; k < a["deflection_max"].size(); ++k) {
    CHECK(b["deflection_max"][k]["deflection"].get<double>() ==
          Approx(a["deflection_max"][k]["deflection"].get<double>()).epsilon(1e-9));
  }
  // The check's utilisations are those of its nonlinear cases and runs, which the design also
  // took: never above the design's (1e-9 for the reread), and the largest within 1 % of it
  // (the design's linear envelope of every station may govern a member at most that much).
  double largest = 0;
  for (size_t k = 0; k < a["members"].size(); ++k) {
    INFO("member " << a["members"][k]["name"]);
    CHECK(b["members"][k]["utilisation"].get<double>() <=
          a["members"][k]["utilisation"].get<double>() + 1e-9);
    largest = std::max(largest, b["members"][k]["utilisation"].get<double>());
  }
  CHECK(largest == Approx(a["utilisation_max"].get<double>()).epsilon(0.01));
}

TEST_CASE("check: an edited design file is refused with the key, and nothing is written",
          "[tools]") {
  const fs::path dir = FreshDir("check_edited");
  const fs::path design = DesignFile(dir, "paper_n2.json"), out = dir / "checked.json";
  const json original = ReadJson(design);
  const int string_index = original["topology"]["bars"].get<int>();  // the first string
  {
    // A string's area doubled alone: its radius, mass and stiffness are still the old area's
    // (all three disagree with it, so the area is the key edited); refused naming the area and
    // the keys to set with it.
    json edited = original;
    edited["members"][string_index]["area"] =
        2 * original["members"][string_index]["area"].get<double>();
    WriteJson(dir / "area.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "area.json").string()) + " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("members[" + std::to_string(string_index) + "].area") &&
                          Catch::Contains("set `radius`") && Catch::Contains("`stiffness`"));
    CHECK_FALSE(fs::exists(out));
  }
  {
    // A string's rest length shortened by 1e-3 alone (a fabrication error): its stiffness and
    // reference force are still the old rest length's, so the rest length is the key edited;
    // refused naming it, its old value and the stiffness to set. Set as told, check runs the
    // string as built and lists it among the edits.
    json edited = original;
    json& m = edited["members"][string_index];
    const double rest = m["rest_length"].get<double>() * (1 - 1e-3);
    m["rest_length"] = rest;
    WriteJson(dir / "rest.json", edited);
    auto r = RunTbridge(
        dir, "check " + Quote((dir / "rest.json").string()) + " -o " + Quote(out.string()));
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err,
               Catch::Contains("'members[" + std::to_string(string_index) + "].rest_length'") &&
                   Catch::Contains("without its stiffness: set `stiffness`"));
    CHECK_FALSE(fs::exists(out));
    m["stiffness"] = m["area"].get<double>() *
                     original["config"]["material"]["youngs_modulus"].get<double>() / rest;
    WriteJson(dir / "rest.json", edited);
    r = RunTbridge(dir,
                   "check " + Quote((dir / "rest.json").string()) + " -o " + Quote(out.string()));
    CHECK(r.code != 2);
    REQUIRE(fs::exists(out));
    const json checked = ReadJson(out);
    CHECK(checked["as_built"]["edited"].dump().find(
              original["members"][string_index]["name"].get<std::string>()) != std::string::npos);
    fs::remove(out);
  }
  // A member's radius, mass or stiffness edited beside its area: check reads a member from its
  // area and rest length, so the edit would be ignored; it is refused naming the member and the
  // key. 1e-9 relative is far above the reader's 1e-12 (a re-read differs by a few ulps).
  const std::string bar_name = original["members"][0]["name"];
  const std::string string_name = original["members"][string_index]["name"];
  const std::tuple<int, const char*, std::string> edits[] = {
      {0, "radius", bar_name},
      {0, "mass", bar_name},
      {string_index, "stiffness", string_name},
      {string_index, "radius", string_name}};
  for (const auto& [index, key, name] : edits) {
    json edited = original;
    edited["members"][index][key] = original["members"][index][key].get<double>() * (1 + 1e-9);
    WriteJson(dir / "member.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "member.json").string()) + " -o " + Quote(out.string()));
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("'members[" + std::to_string(index) + "]." + key + "'") &&
                          Catch::Contains("member " + name + ":"));
    CHECK_FALSE(fs::exists(out));
  }
  {
    // A bar is rigid: its stiffness is null in the file, and a number there is refused too.
    json edited = original;
    edited["members"][0]["stiffness"] = 1e9;
    WriteJson(dir / "bar.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "bar.json").string()) + " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK_THAT(r.err,
               Catch::Contains("'members[0].stiffness'") && Catch::Contains("member " + bar_name));
  }
  {
    // The members' weight switched on: the reference forces no longer balance the loads, so
    // the reference state is re-derived as built, and the output says so.
    json edited = original;
    REQUIRE_FALSE(original["config"]["design"]["self_weight"].get<bool>());
    edited["config"]["design"]["self_weight"] = true;
    WriteJson(dir / "dead.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "dead.json").string()) + " -o " + Quote(out.string()));
    INFO(r.err);
    CHECK(r.code != 2);
    CHECK_THAT(r.out, Catch::Contains("as built: reference state re-derived"));
    REQUIRE(fs::exists(out));
    CHECK(ReadJson(out)["as_built"]["re_derived"] == true);
    CHECK(ReadJson(out)["as_built"]["edited"].empty());  // only the weight changed
    fs::remove(out);
  }
  {
    // The config's payload changed on the paper's design: its one case puts the payload into
    // the deck's own load (eq. 9), so it is checked under its own loads only.
    json edited = original;
    edited["config"]["bridge"]["payload"] =
        2 * original["config"]["bridge"]["payload"].get<double>();
    WriteJson(dir / "payload.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "payload.json").string()) + " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("'config.bridge.payload'"));
    CHECK_FALSE(fs::exists(out));
  }
  {
    // A key that draws the bridge (its span) is another design: refused, naming what differs.
    json edited = original;
    edited["config"]["bridge"]["span"] = 2 * original["config"]["bridge"]["span"].get<double>();
    WriteJson(dir / "span.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "span.json").string()) + " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK_FALSE(fs::exists(out));
  }
  {
    // A deck quantity edited is refused: the deck follows from the config.
    json edited = original;
    edited["deck"]["section_mass"] = original["deck"]["section_mass"].get<double>() * (1 + 1e-9);
    WriteJson(dir / "deck.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "deck.json").string()) + " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("'deck.section_mass'") && Catch::Contains("tbridge design"));
    CHECK_FALSE(fs::exists(out));
  }
  {
    // A node moved: the config draws it elsewhere.
    json edited = original;
    edited["nodes"][3][1] = original["nodes"][3][1].get<double>() + 0.01;
    WriteJson(dir / "node.json", edited);
    const auto r = RunTbridge(
        dir, "check " + Quote((dir / "node.json").string()) + " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("nodes[3]"));
  }
  {
    const auto r = RunTbridge(dir, "check " + Quote(TBRIDGE_SOURCE_DIR "/configs/default.json") +
                                       " -o " + Quote(out.string()));
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("a design file of tbridge design"));
  }
}

TEST_CASE(
    "check: the default design under a payload 20 % higher FAILS as designed and says which load "
    "changed",
    "[tools]") {
  // The bridge as designed (members, rest lengths, the deck plates sized for the payload its file
  // records under designed_for) checked under the edited payload: its members were sized to
  // utilisation 0.9999 under the old one, so the new one fails them, exit 1, with the output
  // written and the change named (tests/verify/check_new_loads_test.cc checks the numbers).
  const fs::path dir = FreshDir("check_payload");
  const fs::path design = DesignFile(dir, "default.json"), out = dir / "checked.json";
  json edited = ReadJson(design);
  const double payload = edited["config"]["bridge"]["payload"].get<double>();
  edited["config"]["bridge"]["payload"] = 1.2 * payload;
  WriteJson(dir / "payload.json", edited);
  const auto r = RunTbridge(
      dir, "check " + Quote((dir / "payload.json").string()) + " -o " + Quote(out.string()));
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK_THAT(r.out, Catch::Contains("FAIL") &&
                        Catch::Contains("loads changed from those designed for: bridge.payload"));
  REQUIRE(fs::exists(out));
  const json checked = ReadJson(out);
  CHECK(checked["designed_for"]["bridge.payload"].get<double>() == payload);
  CHECK(checked["loads_changed"].size() == 1);
  CHECK(checked["verdict"]["pass"] == false);
}

TEST_CASE("check: a bar made 20 % thinner by a consistent edit is checked as built and FAILS",
          "[tools]") {
  // What an engineer asks of a supplier's thinner bar: area, radius and mass edited together
  // (the reader's own expressions), self-weight on (the default). Check keeps the rest lengths,
  // re-derives the reference state with the bar's new weight, says so, and fails the bar.
  const fs::path dir = FreshDir("check_thinner");
  const fs::path design = DesignFile(dir, "default.json"), out = dir / "checked.json";
  const json original = ReadJson(design);
  REQUIRE(original["config"]["design"]["self_weight"].get<bool>());
  // The bar of the largest utilisation: at 1 (the sizing's active buckling row) within 1e-3.
  int bar = 0;
  const int bars = original["topology"]["bars"].get<int>();
  for (int k = 1; k < bars; ++k) {
    if (original["members"][k]["utilisation"].get<double>() >
        original["members"][bar]["utilisation"].get<double>())
      bar = k;
  }
  REQUIRE(original["members"][bar]["utilisation"].get<double>() > 0.99);
  json edited = original;
  json& m = edited["members"][bar];
  const double area = 0.8 * m["area"].get<double>();
  m["area"] = area;
  m["radius"] = std::sqrt(area / std::numbers::pi);
  m["mass"] =
      original["config"]["material"]["density"].get<double>() * area * m["length"].get<double>();
  WriteJson(dir / "thinner.json", edited);
  const auto r = RunTbridge(
      dir, "check " + Quote((dir / "thinner.json").string()) + " -o " + Quote(out.string()));
  INFO(r.out << r.err);
  CHECK(r.code == 1);
  CHECK_THAT(r.out,
             Catch::Contains("FAIL") && Catch::Contains("as built: reference state re-derived"));
  const json checked = ReadJson(out);
  CHECK(checked["as_built"]["re_derived"] == true);
  // The bar is named among the edits, as an edited string is (told by its resistance in the file,
  // which no longer follows from its area), and the only one.
  CHECK(checked["as_built"]["edited"] == json::array({original["members"][bar]["name"]}));
  CHECK_THAT(r.out,
             Catch::Contains("edited: " + original["members"][bar]["name"].get<std::string>()));
  CHECK(
      checked["resizing"].is_null());  // check sizes nothing: no record that reads "not converged"
  CHECK(checked["members"][bar]["area"].get<double>() == area);
  // A column's resistance falls faster than its area (buckling: with I ~ A^2): the bar that
  // was used up is overloaded by at least the area's 1/0.8 = 1.25.
  CHECK(checked["members"][bar]["utilisation"].get<double>() >= 1.25 * 0.99);
  CHECK(checked["verdict"]["outcome"] == "FAIL");
  // The file check wrote is a design as built: checked again, it reads as written (no
  // re-derivation: every force balances at its nodes) and gives the same utilisations (1e-9:
  // the file's 17 digits).
  const fs::path again = dir / "again.json";
  const auto r2 =
      RunTbridge(dir, "check " + Quote(out.string()) + " -q -o " + Quote(again.string()));
  INFO(r2.err);
  CHECK(r2.code == 1);
  const json twice = ReadJson(again);
  CHECK(twice["as_built"]["re_derived"] == true);
  for (size_t k = 0; k < checked["members"].size(); ++k) {
    CHECK(twice["members"][k]["utilisation"].get<double>() ==
          Approx(checked["members"][k]["utilisation"].get<double>()).epsilon(1e-9));
  }
}

TEST_CASE("check: the paper's design fails its dynamic check and the check exits 1", "[tools]") {
  const fs::path dir = FreshDir("check_paper");
  const fs::path design = DesignFile(dir, "paper_n2.json"), out = dir / "checked.json";
  // A radius 4 ulps off, as a differently ordered derivation could leave it, is no edit: the
  // reader's 1e-12 relative admits it (4 ulps are 9e-16).
  json file = ReadJson(design);
  double radius = file["members"][0]["radius"].get<double>();
  for (int k = 0; k < 4; ++k) radius = std::nextafter(radius, 1.0);
  file["members"][0]["radius"] = radius;
  WriteJson(design, file);
  const auto r = RunTbridge(dir, "check " + Quote(design.string()) + " -o " + Quote(out.string()));
  CHECK(r.code == 1);
  CHECK_THAT(r.out, Catch::Contains("FAIL"));
  // The verdict is the design's own: checked in memory and from the file, the same.
  CHECK(ReadJson(out)["verdict"]["pass"] == ReadJson(design)["verdict"]["pass"]);
}

}  // namespace
