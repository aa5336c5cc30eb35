// Slips in a config, run through the built `tbridge` as a user would: a case list that leaves
// nothing to design for, values in the wrong unit (exit 2, the key and the unit named, the
// folder that holds the config and the output byte for byte as before), and a value that is
// only implausible (a warning; an error under --strict).

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;
using tbridge::test::CliResult;
using tbridge::test::FreshDir;
using tbridge::test::Quote;
using tbridge::test::RunTbridge;
using tbridge::test::Snapshot;

TEST_CASE("design: the wind case alone on a planar bridge names loads.cases and changes nothing") {
  const fs::path dir = FreshDir("slip_wind_planar");
  const fs::path work = dir / "work";  // the config and the output; the captures stay in `dir`
  fs::create_directories(work);
  std::ofstream(work / "s.json") << R"({"bridge":{"n":3},"loads":{"cases":["wind"]}})";
  std::ofstream(work / "o.json") << "an earlier design\n";  // what a failed run must leave alone
  const auto before = Snapshot(work);
  const CliResult r = RunTbridge(dir, "design " + Quote((work / "s.json").string()) + " -o " +
                                          Quote((work / "o.json").string()));
  INFO(r.err);
  REQUIRE(r.exited);   // a signal (a crash) is never acceptable
  CHECK(r.code == 2);  // bad input (README, exit codes)
  CHECK_THAT(r.err, Catch::Contains("'loads.cases' = [\"wind\"]") && Catch::Contains("planar") &&
                        Catch::Contains("\"permanent\""));
  CHECK(Snapshot(work) == before);  // no .o.json.tmp.XXXXXX left, o.json untouched
}

TEST_CASE("design: a span in mm and an angle in radians are refused naming the key and the unit") {
  const fs::path dir = FreshDir("slip_units");
  const fs::path work = dir / "work";
  fs::create_directories(work);
  const std::pair<const char*, const char*> slips[] = {
      {R"({"bridge": {"n": 3, "span": 30000}})", "'bridge.span' = 30000"},
      {R"({"bridge": {"n": 3, "beta_deg": 0.349}})", "'bridge.beta_deg' = 0.349"}};
  const char* units[] = {"mm", "radians"};
  for (int k = 0; k < 2; ++k) {
    std::ofstream(work / "c.json") << slips[k].first;
    const auto before = Snapshot(work);
    const CliResult r = RunTbridge(dir, "design " + Quote((work / "c.json").string()) + " -o " +
                                            Quote((work / "o.json").string()));
    INFO(r.err);
    CHECK(r.code == 2);  // before any design: no solver status, no self-weight that never settles
    CHECK_THAT(r.err, Catch::Contains(slips[k].second) && Catch::Contains(units[k]));
    CHECK(Snapshot(work) == before);
  }
}

TEST_CASE("design: a density below water's warns, and --strict refuses it writing nothing") {
  const fs::path dir = FreshDir("slip_density");
  const fs::path config = dir / "c.json", out = dir / "o.json";
  std::ofstream(config) << R"({"bridge": {"n": 2}, "material": {"density": 500}})";
  const CliResult r =
      RunTbridge(dir, "design " + Quote(config.string()) + " -q -o " + Quote(out.string()));
  INFO(r.err);
  CHECK(r.code == 0);  // a warning: timber is lighter still
  CHECK_THAT(r.err, Catch::Contains("tbridge: warning: material.density = 500") &&
                        Catch::Contains("t/m^3"));
  fs::remove(out);
  const CliResult strict = RunTbridge(
      dir, "design " + Quote(config.string()) + " -q --strict -o " + Quote(out.string()));
  CHECK(strict.code == 2);  // plausibility warnings under --strict (README, exit codes)
  CHECK_THAT(strict.err, Catch::Contains("material.density"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE(
    "design: a payload given in kN warns naming the key, and --strict refuses it writing nothing") {
  const fs::path dir = FreshDir("slip_payload_kn");
  const fs::path config = dir / "c.json", out = dir / "o.json";
  // The 20 m by 2 m footbridge's 176 kN crowd written as 176: 4.4 Pa of deck, a bridge that
  // designs and passes, for a load 1000 times too small.
  std::ofstream(config) << R"({"bridge": {"n": 2, "span": 20, "deck_width": 2, "payload": 176}})";
  const CliResult r =
      RunTbridge(dir, "design " + Quote(config.string()) + " -q -o " + Quote(out.string()));
  INFO(r.err);
  CHECK(r.code != 2);
  CHECK_THAT(r.err, Catch::Contains("tbridge: warning: bridge.payload = 176 N") &&
                        Catch::Contains("below 0.5 kPa") && Catch::Contains("kN"));
  CHECK(fs::exists(out));
  fs::remove(out);
  const CliResult strict = RunTbridge(
      dir, "design " + Quote(config.string()) + " -q --strict -o " + Quote(out.string()));
  CHECK(strict.code == 2);
  CHECK_THAT(strict.err, Catch::Contains("--strict") && Catch::Contains("bridge.payload = 176 N"));
  CHECK_FALSE(fs::exists(out));
}

}  // namespace
