// A step too large for the integrator: `tbridge simulate` stops with the step, the time and a
// safe dt from the highest linearised frequency, and writes no output.

#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <string>

#include "cli_support.h"

namespace tbridge {
namespace {

TEST_CASE("simulate: a blown-up run names step, time and a safe dt and writes nothing") {
  const test::fs::path dir = test::FreshDir("guard");
  const test::fs::path config = dir / "config.json";
  // n = 3 at dt = 2e-3 s: 7x RK4's stability limit 2.8e-4 s (SPEC.md §9).
  std::ofstream(config) << R"({"bridge": {"n": 3},
    "dynamics": {"duration": 0.5, "dt": 2e-3, "integrator": "rk4",
                 "perturbation": {"bar_class": 1, "delta": 0.1}}})";
  const test::CliResult r = test::RunTbridge(dir, "simulate " + test::Quote(config.string()) +
                                                      " -o " + test::Quote((dir / "out").string()));
  INFO(r.err);
  CHECK(r.exited);
  CHECK(r.code != 0);
  CHECK_THAT(r.err, Catch::Contains("blew up at step") && Catch::Contains("t = "));
  CHECK_THAT(r.err, Catch::Contains("highest linearised frequency") && Catch::Contains("dt = "));
  CHECK(!test::fs::exists(dir / "out" / "summary.json"));
  CHECK(!test::fs::exists(dir / "out" / "history.csv"));
}

TEST_CASE("design: an out-of-memory names the stage and n, exit 4, nothing written") {
  // A bridge at n = 9 under 200 MB of address space (its design peaks near 1 GB): the memory
  // runs out in the first design, before the sizing, in a third of a second. Its limit is set
  // far above its estimate (5.0 GB), so that it is not refused before the work on a machine
  // with less memory available than that.
  const test::fs::path dir = test::FreshDir("guard_memory");
  const test::fs::path config = dir / "config.json", out = dir / "design.json";
  std::ofstream(config) << R"({"bridge": {"n": 9}, "design": {"memory_limit_bytes": 1e15}})";
  const std::string command = "ulimit -v 200000; " + test::Quote(TBRIDGE_BINARY) + " design " +
                              test::Quote(config.string()) + " -q -o " + test::Quote(out.string()) +
                              " 2> " + test::Quote((dir / "stderr.txt").string());
  const int status = std::system(command.c_str());
  const std::string err = test::ReadText(dir / "stderr.txt");
  INFO(err);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 4);
  CHECK_THAT(err, Catch::Contains("out of memory in ") &&
                      Catch::Contains("of the design of the bridge at n = 9") &&
                      Catch::Contains("a smaller bridge.n"));
  CHECK(!test::fs::exists(out));
}

TEST_CASE("design: a design over its memory limit is refused at once, exit 2, output kept") {
  // The default bridge at n = 6 is estimated at 112 MB (sizing/memory_estimate.h); a limit of
  // 50 MB refuses it before any work, and OUT.json keeps what it held.
  const test::fs::path dir = test::FreshDir("guard_memory_limit");
  const test::fs::path config = dir / "config.json", out = dir / "design.json";
  std::ofstream(config) << R"({"bridge": {"n": 6}, "design": {"memory_limit_bytes": 5e7}})";
  std::ofstream(out) << "an earlier design\n";
  const auto before = test::Snapshot(dir);
  const test::CliResult r = test::RunTbridge(
      dir, "design " + test::Quote(config.string()) + " -q -o " + test::Quote(out.string()));
  INFO(r.err);
  REQUIRE(r.exited);
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("config key 'design.memory_limit_bytes' = 5e+07") &&
                        Catch::Contains("would take an estimated") &&
                        Catch::Contains("bridge.n = 6") && Catch::Contains("a smaller bridge.n"));
  CHECK_THAT(r.err,
             Catch::Contains("refused before any work") && !Catch::Contains("out of memory"));
  test::fs::remove(dir / "stdout.txt");
  test::fs::remove(dir / "stderr.txt");
  auto after = test::Snapshot(dir);
  CHECK(after == before);
  // The control: the same config with the limit above its estimate is not refused by it (run
  // at n = 2, estimated at 21 MB and designed in two seconds, the limit still 50 MB).
  std::ofstream(config) << R"({"bridge": {"n": 2}, "design": {"memory_limit_bytes": 5e7}})";
  const test::CliResult small = test::RunTbridge(
      dir, "design " + test::Quote(config.string()) + " -q -o " + test::Quote(out.string()));
  INFO(small.err);
  CHECK(small.exited);
  CHECK(small.code <= 1);
  CHECK_THAT(small.err, !Catch::Contains("memory_limit_bytes"));
}

}  // namespace
}  // namespace tbridge
