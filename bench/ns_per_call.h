// The benchmarks' one timing loop: how long one call of `call(k)` takes [ns], from batches of
// doubling size (k = 0, 1, ... within each) until one batch takes more than 0.2 s, so that the
// clock's resolution and a batch's start vanish in it. The state a call changes carries over
// from batch to batch; the benchmarks step with a tiny dt, so every call costs the same.
#pragma once

#include <chrono>

template <class Call>
double NsPerCall(Call&& call) {
  for (long calls = 16;; calls *= 2) {
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < calls; ++k) call(k);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > 0.2) return 1e9 * seconds / static_cast<double>(calls);
  }
}
