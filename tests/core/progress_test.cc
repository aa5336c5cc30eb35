// ProgressReporter: the line it draws, and when it draws nothing.

#include "core/progress.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

namespace tbridge {
namespace {

// Everything written to `f` so far.
std::string Contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;) text += static_cast<char>(c);
  return text;
}

void Sleep(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

TEST_CASE("progress line: fraction, bar, elapsed time and ETA") {
  // 45 % of a 30-character bar is 13.5 characters: 13 filled, 17 open.
  CHECK(ProgressReporter::Line("simulate", 0.45, 3, 4) == "simulate  45% [" + std::string(13, '#') +
                                                              std::string(17, '.') +
                                                              "] elapsed 0:00:03  ETA 0:00:04");
  // An unknown total shows only the elapsed time; an unknown rate an ETA of "?".
  CHECK(ProgressReporter::Line("design", -1, 2, -1) == "design elapsed 0:00:02");
  CHECK(ProgressReporter::Line("x", 0, 0, -1) ==
        "x   0% [" + std::string(30, '.') + "] elapsed 0:00:00  ETA ?");
  CHECK(ClockText(3725) == "1:02:05");  // 1 h, 2 min, 5 s
  CHECK(ClockText(-5) == "0:00:00");
}

TEST_CASE("progress: a disabled reporter, or one before its delay, writes nothing") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  {
    ProgressReporter off(false, f, 0.0, 0.001);
    CHECK_FALSE(off.enabled());
    off.Stage("work");
    off.Update(1, 2);
    Sleep(20);
  }
  {
    ProgressReporter early(true, f, 10.0, 0.001);  // 10 s delay: the work ends first
    early.Stage("work");
    early.Update(1, 2);
    Sleep(20);
  }
  CHECK(Contents(f).empty());
  std::fclose(f);
}

TEST_CASE("progress: after its delay a reporter draws the stage and ends the line") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  {
    ProgressReporter p(true, f, 0.0, 0.005);
    p.Stage("work");
    p.Update(1, 4);
    Sleep(50);
    p.Update(2, 4);
    p.Finish();
    p.Update(3, 4);  // after Finish: ignored, nothing more is drawn
    Sleep(20);
  }
  const std::string text = Contents(f);
  INFO(text);
  CHECK(text.find("work  50% [") != std::string::npos);  // the final state, drawn by Finish
  // One unit took ~50 ms, two remain: an ETA of ~0.1 s, which prints as 0:00:00.
  CHECK(text.find("ETA 0:00:00") != std::string::npos);
  CHECK(text.find(" 75%") == std::string::npos);
  CHECK(text.back() == '\n');
  std::fclose(f);
}

TEST_CASE("progress: the ETA leaves out what was done before the stage's first update") {
  std::FILE* f = std::tmpfile();
  REQUIRE(f != nullptr);
  {
    ProgressReporter p(true, f, 0.0, 0.005);
    p.Stage("candidates");
    p.Update(3, 4);  // three reused candidates: no rate yet
    Sleep(30);
  }
  const std::string text = Contents(f);
  INFO(text);
  CHECK(text.find("candidates  75%") != std::string::npos);
  CHECK(text.find("ETA ?") != std::string::npos);
  std::fclose(f);
}

}  // namespace
}  // namespace tbridge
