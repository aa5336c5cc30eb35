// `tbridge design` of a structure to design (members in groups), as a user runs it: the shipped
// 10-bar stress problem written and summarised; `simulate` and `modes` refusing it, naming the
// key; a failed design leaving the output as it was.

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "core/config.h"

namespace tbridge {
namespace {

const std::string kStress = TBRIDGE_SOURCE_DIR "/configs/truss_10bar_stress.json";

TEST_CASE("design: a structure's members sized, written and summarised", "[truss]") {
  const test::fs::path dir = test::FreshDir("structure_design_10bar");
  const test::CliResult r = test::RunTbridge(
      dir, "design " + test::Quote(kStress) + " -o " + test::Quote((dir / "out.json").string()));
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("PASS") && Catch::Contains("1593.18 lb") &&
                        Catch::Contains("first- and second-order conditions hold"));
  const nlohmann::json d = nlohmann::json::parse(test::ReadText(dir / "out.json"));
  CHECK(d["kind"] == "structure");
  CHECK(d["config"] == ToJson(LoadConfig(kStress)));  // the resolved config, echoed
  CHECK(d["members"].size() == 10);
  CHECK(d["verdict"]["pass"] == true);
  CHECK(d["not_applicable"].contains("comfort"));
  // The reactions hold the two 100 kip loads: the vertical ones sum to 2 x 444 822.16 N, to
  // the round-off of the solve.
  double vertical = 0;
  for (const auto& r2 : d["cases"][0]["reactions"]) vertical += r2["force_n"][1].get<double>();
  CHECK(vertical == Approx(2 * 444822.16152605).epsilon(1e-10));
}

TEST_CASE("simulate and modes refuse a structure to design, naming its members", "[truss]") {
  const test::fs::path dir = test::FreshDir("structure_design_simulate");
  nlohmann::json config = nlohmann::json::parse(test::ReadText(kStress));
  config["dynamics"] = {{"duration", 0.1}, {"dt", 1e-3}};
  const test::fs::path work = dir / "work";
  test::fs::create_directory(work);
  std::ofstream(work / "c.json") << config.dump();
  for (const char* command : {"simulate", "modes"}) {
    INFO(command);
    const auto before = test::Snapshot(work);
    const test::CliResult r =
        test::RunTbridge(dir, std::string(command) + " " + test::Quote((work / "c.json").string()) +
                                  " -o " + test::Quote((work / "out").string()));
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("structure.members") && Catch::Contains("tbridge design"));
    CHECK(test::Snapshot(work) == before);  // nothing written
  }
}

TEST_CASE("design: a structure that is a mechanism fails, named, and writes nothing", "[truss]") {
  const test::fs::path dir = test::FreshDir("structure_design_mechanism");
  nlohmann::json config = nlohmann::json::parse(test::ReadText(kStress));
  // Without members 6 (1-2) and 10 (4-1), node 1 hangs on member 2 alone: a mechanism.
  auto& members = config["structure"]["members"];
  auto& groups = config["structure"]["groups"];
  members.erase(9);
  members.erase(5);
  groups.erase(9);
  groups.erase(5);
  std::ofstream(dir / "c.json") << config.dump();
  std::ofstream(dir / "out.json") << "old";
  const test::CliResult r =
      test::RunTbridge(dir, "design " + test::Quote((dir / "c.json").string()) + " -o " +
                                test::Quote((dir / "out.json").string()));
  CHECK(r.code == 3);
  CHECK_THAT(r.err, Catch::Contains("mechanism"));
  CHECK(test::ReadText(dir / "out.json") == "old");
}

TEST_CASE("check: a structure's design file checked as written, an edited area named", "[truss]") {
  const test::fs::path dir = test::FreshDir("structure_check");
  const auto path = [&dir](const char* name) { return test::Quote((dir / name).string()); };
  REQUIRE(
      test::RunTbridge(dir, "design " + test::Quote(kStress) + " -q -o " + path("d.json")).code ==
      0);
  // Unedited: the same verdict and the same numbers, nothing listed as edited.
  test::CliResult r = test::RunTbridge(dir, "check " + path("d.json") + " -q -o " + path("c.json"));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json designed = nlohmann::json::parse(test::ReadText(dir / "d.json"));
  const nlohmann::json checked = nlohmann::json::parse(test::ReadText(dir / "c.json"));
  CHECK(checked["members"] == designed["members"]);
  CHECK(checked["solver"] == designed["solver"]);
  CHECK(checked["edited_members"].empty());
  // Member 1 (5-3) at half its area: the truss is indeterminate, so its force falls a little
  // and its stress nearly doubles: it fails, named, and the file says it was edited.
  nlohmann::json edited = designed;
  edited["members"][0]["area"] = designed["members"][0]["area"].get<double>() / 2;
  std::ofstream(dir / "e.json") << edited.dump();
  r = test::RunTbridge(dir, "check " + path("e.json") + " -o " + path("ce.json"));
  CHECK(r.code == 1);
  CHECK_THAT(r.out, Catch::Contains("edited") && Catch::Contains("5-3") && Catch::Contains("FAIL"));
  const nlohmann::json failed = nlohmann::json::parse(test::ReadText(dir / "ce.json"));
  CHECK(failed["edited_members"] == nlohmann::json::array({"5-3"}));
  CHECK(failed["members"][0]["utilisation"].get<double>() > 1.5);
  CHECK(failed["verdict"]["pass"] == false);
  // The lever: member 1's group, which the sizing would have raised (it has no largest area).
  CHECK_THAT(failed["verdict"]["lever"].get<std::string>(), Catch::Contains("structure.groups[0]"));
  CHECK_THAT(r.out, Catch::Contains("what moves it: the area of structure.groups[0]"));
  // The loads are still carried: the supports' vertical reactions sum to the two loads.
  double vertical = 0;
  for (const auto& s : failed["cases"][0]["reactions"]) vertical += s["force_n"][1].get<double>();
  CHECK(vertical == Approx(2 * 444822.16152605).epsilon(1e-10));
  // A bad area is named.
  edited["members"][3]["area"] = -1;
  std::ofstream(dir / "bad.json") << edited.dump();
  r = test::RunTbridge(dir, "check " + path("bad.json") + " -o " + path("cb.json"));
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("members[3].area"));
  CHECK(!test::fs::exists(dir / "cb.json"));
}

}  // namespace
}  // namespace tbridge
