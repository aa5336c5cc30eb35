// `tbridge sweep` and `tbridge merge` as a user runs them: the same bytes for 1 and 2
// threads and for merged shards, --resume recomputes nothing, bad input writes nothing.

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_support.h"

namespace {

namespace fs = std::filesystem;

using tbridge::test::FreshDir;
using tbridge::test::Quote;
using tbridge::test::ReadText;
using Result = tbridge::test::CliResult;
Result Run(const fs::path& dir, const std::string& args) {
  return tbridge::test::RunTbridge(dir, args);
}

// Six candidates with a first frequency and the dynamic check each.
fs::path SmallSweep(const fs::path& dir) {
  const fs::path path = dir / "sweep.json";
  std::ofstream(path) << R"({"bridge": {"beta_deg": 10},
    "sweep": {"n": [1, 2, 3], "deck_prestrain": [1.0, 0.99],
              "joint_mass": {"per_node_kg": 10},
              "constraints": {"min_first_frequency_rad_s": 35, "max_dynamic_stress_ratio": 10}}})";
  return path;
}

TEST_CASE("sweep: 1 and 2 threads write the same bytes and a resume evaluates nothing", "[sweep]") {
  const fs::path dir = FreshDir("threads");
  const std::string config = Quote(SmallSweep(dir).string());
  const Result one =
      Run(dir, "sweep " + config + " -o " + Quote((dir / "one").string()) + " --threads 1");
  REQUIRE(one.code == 0);
  CHECK_THAT(one.out, Catch::Contains("evaluated 6, reused 0"));
  const Result two = Run(dir, "sweep " + config + " -o " + Quote((dir / "two").string()) + " -j 2");
  REQUIRE(two.code == 0);
  for (const char* file : {"sweep.csv", "sweep.json"}) {
    INFO(file);
    CHECK(ReadText(dir / "one" / file) == ReadText(dir / "two" / file));
  }
  CHECK(fs::exists(dir / "two" / "candidates" / "5.json"));
  const nlohmann::json j = nlohmann::json::parse(ReadText(dir / "one" / "sweep.json"));
  CHECK(j["rows"].size() == 6);
  CHECK(j["choice"]["found"] == true);
  CHECK(j["shard"].is_null());

  // Resume: every candidate is stored, none is computed again, and the outputs are unchanged.
  const std::string before = ReadText(dir / "two" / "sweep.json");
  const auto stamp = fs::last_write_time(dir / "two" / "candidates" / "3.json");
  const Result again =
      Run(dir, "sweep " + config + " -o " + Quote((dir / "two").string()) + " --resume");
  REQUIRE(again.code == 0);
  CHECK_THAT(again.out, Catch::Contains("evaluated 0, reused 6"));
  CHECK(ReadText(dir / "two" / "sweep.json") == before);
  CHECK(fs::last_write_time(dir / "two" / "candidates" / "3.json") == stamp);

  // An interrupted run: two candidates lost; the resume computes exactly those.
  fs::remove(dir / "two" / "candidates" / "1.json");
  fs::remove(dir / "two" / "candidates" / "4.json");
  const Result partial =
      Run(dir, "sweep " + config + " -o " + Quote((dir / "two").string()) + " --resume");
  REQUIRE(partial.code == 0);
  CHECK_THAT(partial.out, Catch::Contains("evaluated 2, reused 4"));
  CHECK(ReadText(dir / "two" / "sweep.json") == before);
}

TEST_CASE("sweep: shards merged equal the single run byte for byte", "[sweep]") {
  const fs::path dir = FreshDir("shards");
  const std::string config = Quote(SmallSweep(dir).string());
  REQUIRE(Run(dir, "sweep " + config + " -o " + Quote((dir / "all").string()) + " -q").code == 0);
  for (const char* s : {"1", "2", "3"}) {
    const Result r =
        Run(dir, "sweep " + config + " -o " + Quote((dir / (std::string("s") + s)).string()) +
                     " --shard " + s + "/3 -j 1");
    REQUIRE(r.code == 0);
    CHECK_THAT(r.out, Catch::Contains("evaluated 2, reused 0"));
  }
  const nlohmann::json slice = nlohmann::json::parse(ReadText(dir / "s2" / "sweep.json"));
  CHECK(slice["rows"].size() == 2);
  CHECK(slice["rows"][0]["index"] == 1);
  CHECK(slice["rows"][1]["index"] == 4);
  CHECK(slice["choice"].is_null());
  const std::string shards = Quote((dir / "s3").string()) + " " + Quote((dir / "s1").string()) +
                             " " + Quote((dir / "s2").string());
  const Result merged = Run(dir, "merge " + shards + " -o " + Quote((dir / "merged").string()));
  REQUIRE(merged.code == 0);
  for (const char* file : {"sweep.csv", "sweep.json"}) {
    INFO(file);
    CHECK(ReadText(dir / "all" / file) == ReadText(dir / "merged" / file));
  }
  // A missing shard or one given twice is bad input, and nothing is written.
  const Result missing =
      Run(dir, "merge " + Quote((dir / "s1").string()) + " -o " + Quote((dir / "bad").string()));
  CHECK(missing.code == 2);
  CHECK_THAT(missing.err, Catch::Contains("missing"));
  const Result twice = Run(dir, "merge " + shards + " " + Quote((dir / "s1").string()) + " -o " +
                                    Quote((dir / "bad").string()));
  CHECK(twice.code == 2);
  CHECK_THAT(twice.err, Catch::Contains("already"));
  CHECK_FALSE(fs::exists(dir / "bad"));
}

TEST_CASE("sweep: bad command lines and configs exit 2 and write nothing", "[sweep]") {
  const fs::path dir = FreshDir("bad");
  const std::string config = Quote(SmallSweep(dir).string());
  const std::string out = Quote((dir / "out").string());
  for (const char* shard : {"3/2", "0/2", "a/b"}) {
    INFO(shard);
    const Result r = Run(dir, "sweep " + config + " -o " + out + " --shard " + shard);
    CHECK(r.code == 2);
    CHECK_THAT(r.err,
               Catch::Contains("--shard") && Catch::Contains(shard) && Catch::Contains("i/N"));
  }
  CHECK(Run(dir, "sweep " + config + " -o " + out + " --threads 0").code == 2);
  std::ofstream(dir / "bad.json") << R"({"bridge": {}, "sweep": {"n": [0, 1]}})";
  const Result r = Run(dir, "sweep " + Quote((dir / "bad.json").string()) + " -o " + out);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("sweep.n[0]"));
  CHECK_FALSE(fs::exists(dir / "out"));
}

}  // namespace
