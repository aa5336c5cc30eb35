// The progress of a verified design (core/progress.h through sizing/verified_design.h): each
// sizing's stages drawn with the sizing's number, the static check and the run counted (a
// percentage), and a cancel hook that stops the design where it throws.

#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

#include "core/config.h"
#include "core/progress.h"
#include "sizing/verified_design.h"

namespace tbridge {

namespace {

std::string ReadAll(std::FILE* f) {
  std::rewind(f);
  std::string out;
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) out.append(buffer, n);
  return out;
}

struct Stop {};

}  // namespace

TEST_CASE("progress of a verified design: per sizing, check and run, with the share done",
          "[verify]") {
  Config config;
  config.bridge.n = 2;
  std::FILE* file = std::tmpfile();
  REQUIRE(file != nullptr);
  {
    // Drawn from the start, every 2 ms: a stage as short as an optimisation of a few ms may be
    // passed over, the run (a third of a second) is drawn many times.
    ProgressReporter progress(true, file, 0.0, 0.002);
    const Design d = DesignAndVerify(config, &progress);
    REQUIRE(d.resizing.iterations >= 2);
  }
  const std::string drawn = ReadAll(file);
  std::fclose(file);
  CHECK_THAT(drawn, Catch::Contains("sizing 1 (of at most 25): dynamic check: moving_load"));
  CHECK_THAT(drawn, Catch::Contains("sizing 2 (of at most 25): "));
  CHECK_THAT(drawn, Catch::Contains("%"));  // the run's share done, with its ETA
  CHECK_THAT(drawn, Catch::Contains("ETA"));
}

TEST_CASE("progress of the angle's search names each trial's angle and the angle chosen",
          "[verify]") {
  // A search of a few trials: a narrow range, comfort off, the 12 m default at n = 2.
  Config config;
  config.bridge.n = 2;
  config.bridge.beta_auto = true;
  config.design.beta_range_deg = {40.0, 50.0};
  config.comfort.check = false;
  std::FILE* file = std::tmpfile();
  REQUIRE(file != nullptr);
  Design d;
  {
    ProgressReporter progress(true, file, 0.0, 0.002);
    d = DesignAndVerify(config, &progress);
  }
  const std::string drawn = ReadAll(file);
  std::fclose(file);
  REQUIRE(d.angle.done);
  // The scan starts at the range's steeper end: its first trial is at 50 deg.
  CHECK_THAT(drawn, Catch::Contains("angle 50 deg (trial 1): sizing 1 (of at most 25): "));
  CHECK_THAT(drawn, Catch::Contains("angle 40 deg (trial "));
  CHECK_THAT(drawn, Catch::Contains("angle chosen, "));
}

TEST_CASE("a cancel hook stops a verified design where it throws", "[verify]") {
  Config config;
  config.bridge.n = 2;
  ProgressReporter progress;  // silent: the hook is polled all the same
  int polls = 0;
  progress.SetCancelHook([&polls] {
    if (++polls == 50) throw Stop{};
  });
  CHECK_THROWS_AS(DesignAndVerify(config, &progress), Stop);
  CHECK(polls == 50);  // not polled again once it threw
}

}  // namespace tbridge
