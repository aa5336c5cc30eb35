// Cost of one class-1 RK4 step per member for the paper's planar bridges n = 1..12, with the
// scene's variants: plain, string damping on, stabilisation on.
//
//   build/bench/bench_step [max_n]
//
// Each case is timed over enough steps to take ~0.2 s, after a warm-up; the state starts from
// the design with the central bar 1 mm down, so strings stay taut and nothing is skipped.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace {

using tbridge::Class1Options;
using tbridge::Class1System;

double NsPerMemberStep(const tbridge::DynamicModel& model, const Class1Options& options,
                       const Eigen::VectorXd& y0) {
  const Class1System system(model, options);
  tbridge::Class1Ode ode(system);
  tbridge::Rk4Workspace ws(system.state_size());
  Eigen::VectorXd y = y0;
  const double dt = 1e-8;  // tiny: the state barely changes, so every step costs the same
  long steps = 16;
  for (;;) {
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < steps; ++k) tbridge::Rk4Step(ode, k * dt, dt, y, ws);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > 0.2) return 1e9 * seconds / (static_cast<double>(steps) * system.num_members());
    steps *= 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 12;
  std::printf("%3s %8s %8s %12s %12s %12s\n", "n", "members", "nodes", "plain", "damped", "stabilised");
  std::printf("%3s %8s %8s %12s %12s %12s\n", "", "", "", "ns/mem/step", "ns/mem/step", "ns/mem/step");
  for (int n = 1; n <= max_n; ++n) {
    tbridge::Config config;
    config.bridge.n = n;
    const tbridge::Design design = tbridge::RunDesign(config);
    tbridge::DynamicsConfig scene;
    scene.perturbation = {1, 1e-3};
    const tbridge::DynamicModel plain = tbridge::BuildDynamicModel(design);
    tbridge::ModelOptions damping;
    damping.damping = 100;
    const tbridge::DynamicModel damped = tbridge::BuildDynamicModel(design, damping);
    const Eigen::VectorXd y0 = tbridge::InitialState(plain, scene);
    Class1Options stab;
    stab.stabilisation = true;
    const double a = NsPerMemberStep(plain, {}, y0);
    const double b = NsPerMemberStep(damped, {}, y0);
    const double c = NsPerMemberStep(plain, stab, y0);
    std::printf("%3d %8zu %8d %12.1f %12.1f %12.1f\n", n, plain.bars.size() + plain.strings.size(),
                plain.num_nodes(), a, b, c);
    std::fflush(stdout);
  }
  return 0;
}
