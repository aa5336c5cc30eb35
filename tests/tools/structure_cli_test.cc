// `tbridge simulate` and `tbridge modes` on a custom scene (a config's "structure" section), as
// a user runs them: the shipped D-bar, and a bad scene that must be named and write nothing.

#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "core/config.h"

namespace tbridge {
namespace {

const std::string kDBar = TBRIDGE_SOURCE_DIR "/configs/motes_dbar.json";

// `tbridge COMMAND CONFIG -o OUTPUT`, run in `dir`.
test::CliResult Run(const test::fs::path& dir, const std::string& command,
                    const std::string& config, const test::fs::path& output) {
  return test::RunTbridge(
      dir, command + " " + test::Quote(config) + " -o " + test::Quote(output.string()));
}

TEST_CASE("simulate: the D-bar scene runs and echoes its structure") {
  const test::fs::path dir = test::FreshDir("structure_dbar");
  const test::CliResult r = Run(dir, "simulate", kDBar, dir / "out");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("classk") && Catch::Contains("wrote"));
  const nlohmann::json summary =
      nlohmann::json::parse(test::ReadText(dir / "out" / "summary.json"));
  CHECK(summary["config"] == ToJson(LoadConfig(kDBar)));  // the resolved config, structure included
  CHECK(summary["model"]["nodes"] == 4);
  CHECK(summary["run"]["engine"] == "classk");
  CHECK(summary["run"]["steps"] == 5000);
  CHECK(test::fs::exists(dir / "out" / "history.csv"));
}

TEST_CASE("simulate: record.bar_forces puts each bar's force peaks in the summary") {
  const test::fs::path dir = test::FreshDir("structure_bar_forces");
  nlohmann::json config = nlohmann::json::parse(test::ReadText(kDBar));
  config["dynamics"]["record"]["bar_forces"] = true;
  const test::fs::path path = dir / "dbar_forces.json";
  std::ofstream(path) << config.dump(2);
  const test::CliResult r = Run(dir, "simulate", path.string(), dir / "out");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json summary =
      nlohmann::json::parse(test::ReadText(dir / "out" / "summary.json"));
  const nlohmann::json& peaks = summary["bar_force_peaks"];
  REQUIRE(peaks.size() == 4);
  CHECK(peaks[0]["bar"] == "4-1");
  double largest = 0;
  for (const auto& p : peaks) {
    CHECK(p["compression_n"].get<double>() >= 0);
    CHECK(p["tension_n"].get<double>() >= 0);
    largest = std::max({largest, p["compression_n"].get<double>(), p["tension_n"].get<double>()});
  }
  // The strings start at 150 N and 100 N (k = 100 N/m, stretched 1.5 m and 1 m): the bars
  // that hold them apart carry forces of that order.
  CHECK(largest > 10.0);
  CHECK(largest < 1e4);
  CHECK(summary["config"]["dynamics"]["record"]["bar_forces"] == true);
}

TEST_CASE("modes: the D-bar scene") {
  const test::fs::path dir = test::FreshDir("structure_modes");
  const test::CliResult r = Run(dir, "modes", kDBar, dir / "modes.json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const nlohmann::json modes = nlohmann::json::parse(test::ReadText(dir / "modes.json"));
  // 3 free nodes in the plane, 4 bar lengths held: 2 modes.
  CHECK(modes["modes"].size() == 2);
  CHECK(modes["config"].contains("structure"));
}

TEST_CASE("simulate: a bad structure is named and writes nothing") {
  const test::fs::path dir = test::FreshDir("structure_bad");
  const test::fs::path config = dir / "config.json";
  nlohmann::json bad = nlohmann::json::parse(test::ReadText(kDBar));
  bad["structure"]["strings"][1]["nodes"] = {1, 7};
  std::ofstream(config) << bad.dump();
  const test::CliResult r = Run(dir, "simulate", config.string(), dir / "out");
  CHECK(r.exited);
  CHECK(r.code == 2);
  CHECK_THAT(r.err,
             Catch::Contains("'structure.strings[1].nodes[1]' = 7") && Catch::Contains("[1, 4]"));
  CHECK(!test::fs::exists(dir / "out"));
}

TEST_CASE("design: a structure config is not a bridge") {
  const test::fs::path dir = test::FreshDir("structure_design");
  const test::CliResult r = Run(dir, "design", kDBar, dir / "d.json");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("'structure.members'") && Catch::Contains("\"bridge\""));
  CHECK(!test::fs::exists(dir / "d.json"));
}

}  // namespace
}  // namespace tbridge
