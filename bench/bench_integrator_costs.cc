// The integrator policy's cost model (dynamics/integrator_policy.h) against measured steps: for
// the paper's planar bridges n = min..max, one RK4 step and one SDIRK3 step timed on the same
// model and scene, beside the model's estimate of each and of their ratio, which is what
// "auto" compares RK4 sub-steps with. Also SDIRK3's Newton iterations and Jacobian refreshes
// per step, the two rates the model takes as constants.
//
//   build/bench/bench_integrator_costs [max_n] [min_n] [dt_s]
//
// Scene: the paper's design at n (configs/paper_n1.json), the longest bar class pushed down by
// 1 mm, class-1 engine, no damping; SDIRK3 at dt (default 5e-4 s) for 0.1 s after 0.01 s of
// warm-up, RK4 at a tiny step (every step then costs the same) for ~0.2 s.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "bridge/design_model.h"
#include "core/config.h"
#include "core/error.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/coupling.h"
#include "dynamics/initial_state.h"
#include "dynamics/integrator_policy.h"
#include "dynamics/integrators.h"
#include "dynamics/sdirk.h"
#include "ns_per_call.h"

namespace {

using Clock = std::chrono::steady_clock;

double Rk4NsPerStep(tbridge::Class1Ode& ode, int size, const Eigen::VectorXd& y0) {
  tbridge::Rk4Workspace ws(size);
  Eigen::VectorXd y = y0;
  const double dt = 1e-8;
  return NsPerCall([&](long k) { tbridge::Rk4Step(ode, k * dt, dt, y, ws); });
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 8;
  const int min_n = argc > 2 ? std::atoi(argv[2]) : 2;
  const double dt = argc > 3 ? std::atof(argv[3]) : 5e-4;
  std::printf("%3s %8s %9s %12s %12s %12s %12s %10s %10s %9s %9s\n", "n", "members", "L+U nnz",
              "rk4 [ns]", "model", "sdirk3 [ns]", "model", "ratio", "model", "newton", "refresh");
  for (int n = min_n; n <= max_n; ++n) {
    tbridge::Config config = tbridge::LoadConfig(TBRIDGE_SOURCE_DIR "/configs/paper_n1.json");
    config.bridge.n = n;
    const tbridge::DynamicModel model = tbridge::BuildDynamicModel(tbridge::RunDesign(config));
    tbridge::DynamicsConfig scene;
    scene.perturbation = {1, 1e-3};
    const Eigen::VectorXd y0 = tbridge::InitialState(model, scene);
    const tbridge::Class1System system(model);
    tbridge::Class1Ode ode(system);
    const double rk4 = Rk4NsPerStep(ode, system.state_size(), y0);

    tbridge::Sdirk3 sdirk(tbridge::CouplingOf(model), system.state_size());
    Eigen::VectorXd y = y0;
    double t = 0, sdirk_ns = NAN, newton = NAN, refresh = NAN;
    try {
      for (; t < 0.01 - 1e-12; t += dt) sdirk.Step(ode, t, dt, y);
      const tbridge::SdirkStats before = sdirk.stats();
      const auto start = Clock::now();
      long steps = 0;
      for (; steps * dt < 0.1 - 1e-12; ++steps) sdirk.Step(ode, t + steps * dt, dt, y);
      sdirk_ns = 1e9 * std::chrono::duration<double>(Clock::now() - start).count() / steps;
      const tbridge::SdirkStats& after = sdirk.stats();
      newton = static_cast<double>(after.newton_iterations - before.newton_iterations) / steps;
      refresh = static_cast<double>(after.jacobians - before.jacobians) / steps;
    } catch (const tbridge::ModelError&) {
      // SDIRK3 fails on this scene from n = 8 (BENCHMARKS.md): the model's row stands alone.
    }

    const int members = static_cast<int>(model.bars.size() + model.strings.size());
    const tbridge::StepCosts model_cost =
        tbridge::EstimateStepCosts(members, system.coordinates(), sdirk.counts());
    std::printf("%3d %8d %9.0f %12.0f %12.0f %12.0f %12.0f %10.1f %10.1f %9.2f %9.3f\n", n, members,
                sdirk.counts().factor_nonzeros, rk4, model_cost.rk4_ns, sdirk_ns,
                model_cost.sdirk3_ns, sdirk_ns / rk4, model_cost.sdirk3_ns / model_cost.rk4_ns,
                newton, refresh);
    std::fflush(stdout);
  }
  return 0;
}
