// `tbridge simulate DESIGN.json`: a written design runs as its config's dynamics section asks,
// the same run as `tbridge simulate CONFIG.json` of the config it was designed from; an edited
// design runs as built; a design whose config has no dynamics section is refused naming the key,
// with nothing written.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "cli_support.h"

namespace {

using nlohmann::json;
using namespace tbridge::test;  // FreshDir, Quote, ReadText, RunTbridge, Snapshot; fs

json Summary(const fs::path& dir) {
  json s = json::parse(ReadText(dir / "summary.json"));
  s["run"].erase("wall_s");  // the one number that is not the run's
  return s;
}

}  // namespace

TEST_CASE("simulate: a design file runs as the config it was designed from, and edited as built",
          "[tools]") {
  const fs::path dir = FreshDir("simulate_design");
  json config = json::parse(ReadText(std::string(TBRIDGE_SOURCE_DIR) + "/configs/default.json"));
  config["bridge"]["n"] = 2;
  // A short run of the verified bridge standing under its loads: 2000 RK4 steps.
  config["dynamics"] = {{"duration", 0.2},
                        {"dt", 1e-4},
                        {"integrator", "rk4"},
                        {"record", {{"nodes", {3}}, {"every", 100}}},
                        {"frequency", {{"enabled", false}}}};
  std::ofstream(dir / "config.json") << config.dump(2);
  const std::string design = (dir / "design.json").string();
  REQUIRE(
      RunTbridge(dir, "design " + Quote((dir / "config.json").string()) + " -q -o " + Quote(design))
          .code == 0);
  const auto a = RunTbridge(dir, "simulate " + Quote((dir / "config.json").string()) + " -q -o " +
                                     Quote((dir / "a").string()));
  const auto b =
      RunTbridge(dir, "simulate " + Quote(design) + " -q -o " + Quote((dir / "b").string()));
  INFO(a.err << b.err);
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  // The same bridge: the design file's 17 digits are its doubles exactly, so the same run, to
  // the last bit.
  CHECK(Summary(dir / "a") == Summary(dir / "b"));
  CHECK(ReadText(dir / "a" / "history.csv") == ReadText(dir / "b" / "history.csv"));

  // The heaviest string made 20 % thinner (area, radius, mass and stiffness together): run as
  // built, it is another bridge, and its run says so in its numbers.
  json edited = json::parse(ReadText(design));
  int string = -1;
  for (size_t k = edited["topology"]["bars"].get<size_t>(); k < edited["members"].size(); ++k) {
    if (string < 0 || edited["members"][k]["mass"] > edited["members"][string]["mass"])
      string = static_cast<int>(k);
  }
  json& m = edited["members"][string];
  const double area = 0.8 * m["area"].get<double>();
  const json& mat = edited["config"]["material"];
  m["area"] = area;
  m["radius"] = std::sqrt(area / std::numbers::pi);
  m["mass"] = mat["density"].get<double>() * area * m["length"].get<double>();
  m["stiffness"] = mat["youngs_modulus"].get<double>() * area / m["rest_length"].get<double>();
  std::ofstream(dir / "edited.json") << edited.dump(2);
  const auto c = RunTbridge(dir, "simulate " + Quote((dir / "edited.json").string()) + " -q -o " +
                                     Quote((dir / "c").string()));
  INFO(c.err);
  REQUIRE(c.code == 0);
  CHECK(Summary(dir / "c")["max_string_stress"] != Summary(dir / "a")["max_string_stress"]);

  // No dynamics section in the design's config: refused, naming it, and nothing written.
  json plain = json::parse(ReadText(design));
  plain["config"].erase("dynamics");
  std::ofstream(dir / "plain.json") << plain.dump(2);
  const auto before = Snapshot(dir / "a");
  const auto d = RunTbridge(dir, "simulate " + Quote((dir / "plain.json").string()) + " -q -o " +
                                     Quote((dir / "a").string()));
  CHECK(d.code == 2);
  CHECK_THAT(d.err, Catch::Contains("config.dynamics"));
  CHECK(Snapshot(dir / "a") == before);  // the earlier run's outputs, as they were
}
