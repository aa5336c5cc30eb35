// Two lanes of work (core/two_lanes.h): both run to their end, each writes its own results,
// and an error in either reaches the caller after both have stopped.
#include "core/two_lanes.h"

#include <atomic>
#include <catch2/catch.hpp>
#include <stdexcept>
#include <vector>

namespace tbridge {
namespace {

TEST_CASE("two lanes: both run, each on its own half", "[lanes]") {
  std::vector<int> out(1000, 0);
  InTwoLanes(
      [&] {
        for (int i = 500; i < 1000; ++i) out[i] = i;
      },
      [&] {
        for (int i = 0; i < 500; ++i) out[i] = i;
      });
  for (int i = 0; i < 1000; ++i) CHECK(out[i] == i);
}

TEST_CASE("two lanes: an error in either reaches the caller once both have stopped", "[lanes]") {
  std::atomic<bool> other_done{false};
  CHECK_THROWS_WITH(
      InTwoLanes([] { throw std::runtime_error("beside"); }, [&] { other_done = true; }), "beside");
  CHECK(other_done);
  other_done = false;
  CHECK_THROWS_WITH(
      InTwoLanes([&] { other_done = true; }, [] { throw std::runtime_error("here"); }), "here");
  CHECK(other_done);
  // Both fail: the lane beside's error is the one reported, the same on every machine.
  CHECK_THROWS_WITH(InTwoLanes([] { throw std::runtime_error("beside"); },
                               [] { throw std::runtime_error("here"); }),
                    "beside");
}

}  // namespace
}  // namespace tbridge
