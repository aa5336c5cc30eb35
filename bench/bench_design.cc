// In-process design time against complexity n = 1..16 (p = 1, buckling check on), per solver
// ("auto": the direct solve). bench/design_process.py times the whole process.
// Usage: bench_design [max_n] [solver] [repeats]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/json_reader.h"
#include "design/design.h"

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 16;
  const std::optional<tbridge::SolverKind> solver =
      tbridge::ValueIn(tbridge::kSolverChoiceNames, argc > 2 ? argv[2] : "auto");
  if (!solver) {
    std::fprintf(stderr, "bench_design: solver '%s': one of %s\n", argv[2],
                 tbridge::ChoiceText(tbridge::AllNames(tbridge::kSolverChoiceNames)).c_str());
    return 2;
  }
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 3;
  std::printf("%3s %6s %7s %9s %10s %12s %12s\n", "n", "bars", "strings", "iters", "mass_kg",
              "best_ms", "median_ms");
  for (int n = 1; n <= max_n; ++n) {
    tbridge::Config c;
    c.bridge.n = n;
    c.design.solver = *solver;
    c.design.buckling_safety_factor = 1.0;  // Euler constraint active in the problem
    std::vector<double> ms;
    tbridge::Design d;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      d = tbridge::RunDesign(c);
      const auto t1 = std::chrono::steady_clock::now();
      ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    std::printf("%3d %6d %7d %9d %10.3f %12.2f %12.2f\n", n, d.topology.structure.num_bars(),
                d.topology.structure.num_strings(), d.solver.iterations, d.mass.total, ms.front(),
                ms[ms.size() / 2]);
    std::fflush(stdout);
  }
  return 0;
}
