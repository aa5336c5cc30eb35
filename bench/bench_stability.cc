// Time of the design's stability verdict (sparse null space + LDL^T, design/stability.h)
// against the whole design, n = 8..max_n (planar p = 1).
// Usage: bench_stability [max_n]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "design/design.h"
#include "design/stability.h"

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 14;
  std::printf("%3s %8s %10s %12s %14s\n", "n", "bars", "red_dofs", "design_ms", "stability_ms");
  for (int n = 8; n <= max_n; ++n) {
    tbridge::Config c;
    c.bridge.n = n;
    const auto t0 = std::chrono::steady_clock::now();
    const tbridge::Design d = tbridge::RunDesign(c);
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<double> k(d.strings.size());
    for (size_t i = 0; i < k.size(); ++i) k[i] = d.strings[i].stiffness;
    const tbridge::StabilityVerdict v =
        tbridge::AssessStability(d.topology.structure, tbridge::MemberForces(d), k, false);
    const auto t2 = std::chrono::steady_clock::now();
    std::printf("%3d %8zu %10d %12.1f %14.1f\n", n, d.bars.size(), v.reduced_dofs,
                std::chrono::duration<double, std::milli>(t1 - t0).count(),
                std::chrono::duration<double, std::milli>(t2 - t1).count());
  }
  return 0;
}
