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
  // runs out in the first design, before the sizing, in a third of a second.
  const test::fs::path dir = test::FreshDir("guard_memory");
  const test::fs::path config = dir / "config.json", out = dir / "design.json";
  std::ofstream(config) << R"({"bridge": {"n": 9}})";
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

}  // namespace
}  // namespace tbridge
