// Two pieces of independent work side by side: `beside` on a second thread, `here` on the
// calling one, joined before returning. The checks split their solves into two fixed lanes
// so that the results do not depend on the machine: on one core both lanes run here, one
// after the other. Only `here` may touch the caller's progress reporter (its cancel hook
// runs in the thread that owns it); an exception from either lane is rethrown here, the
// beside lane's first.
#pragma once

#include <exception>
#include <thread>

namespace tbridge {

template <class Beside, class Here>
void InTwoLanes(Beside&& beside, Here&& here) {
  if (std::thread::hardware_concurrency() < 2) {
    beside();
    here();
    return;
  }
  std::exception_ptr beside_error;
  std::thread lane([&] {
    try {
      beside();
    } catch (...) {
      beside_error = std::current_exception();
    }
  });
  std::exception_ptr here_error;
  try {
    here();
  } catch (...) {
    here_error = std::current_exception();
  }
  lane.join();
  if (beside_error) std::rethrow_exception(beside_error);
  if (here_error) std::rethrow_exception(here_error);
}

}  // namespace tbridge
