// Configs that pass every key's own range but leave nothing a bridge can be designed for, run
// through the built `tbridge` as a user would: exit 2, the key named, and the folder that
// holds the config and the output byte for byte as before.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;
using tbridge::test::CliResult;
using tbridge::test::FreshDir;
using tbridge::test::Quote;
using tbridge::test::RunTbridge;
using tbridge::test::Snapshot;

TEST_CASE("design: \"wind\" alone on a planar bridge names loads.cases and changes nothing") {
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

}  // namespace
