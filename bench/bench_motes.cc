// The two MOTES example scenes, loaded from configs/motes_prism.json and configs/motes_dbar.json
// (their "structure" sections; the scenes are described in configs/README.md) and run with
// MOTES's published method (RK4, dt = 1e-3 s, 5000 steps, the configs' "dynamics"): time per
// step and total error against a converged reference (RK4 at dt / 100).
//
//   build/bench/bench_motes [CONFIG_DIR]      (default: the source tree's configs/)
//
// Class-1 prism: bottom triangle on the unit circle at z = 0, top triangle at z = 1 turned by
// 150 deg; bars b_k-t_k; strings: bottom b_k-b_k+1, top t_k-t_k+1, vertical b_k-t_k+1, each
// split into 3 segments (24 nodes, 27 segments). Bar mass 1 kg; each segment k = 100 N/m,
// c = 10 N s/m, mass 0.05 kg lumped half at each end; rest length 0.95 x its length; no load.
// D-bar (class 2): nodes 1 (1,0), 2 (0,1), 3 (-1,0), 4 (0,-1); bars 4-1, 1-2, 2-3, 3-4 (1 kg
// each: MOTES gives no mass); strings 2-4 (L0 = 1 m) and 1-3 (L0 = 0.5 m), k = 100 N/m, c = 0;
// node 1 pinned. Runs on the class-k engine.
// Error: max over the recorded samples (every 10 steps: 0.01 s) and nodes of |x - x_ref| [m].

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "core/config.h"
#include "core/error.h"
#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "dynamics/structure_model.h"

namespace {

using namespace tbridge;

// RK4 from y0 for `steps` of dt; positions sampled every `every` steps into the returned rows.
Eigen::MatrixXd Run(OdeSystem& ode, Eigen::VectorXd y, double dt, long steps, long every,
                    double* seconds) {
  Rk4Workspace ws(ode.size());
  const int c = ode.size() / 2;
  Eigen::MatrixXd out(steps / every + 1, c);
  out.row(0) = y.head(c).transpose();
  const auto start = std::chrono::steady_clock::now();
  for (long k = 1; k <= steps; ++k) {
    Rk4Step(ode, (k - 1) * dt, dt, y, ws);
    if (k % every == 0) out.row(k / every) = y.head(c).transpose();
  }
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

struct LoadedScene {
  DynamicModel model;
  DynamicsConfig dynamics;
};

LoadedScene Load(const std::string& path) {
  const Config config = LoadConfig(path);
  if (!config.structure || !config.dynamics)
    throw ConfigError(path + ": needs \"structure\" and \"dynamics\"");
  return {BuildStructureModel(*config.structure, ModelOptionsOf(*config.dynamics)),
          *config.dynamics};
}

template <class System, class Ode>
void Scene(const char* name, const LoadedScene& scene) {
  const DynamicModel& m = scene.model;
  const double dt = scene.dynamics.dt;
  const long steps = std::lround(scene.dynamics.duration / dt), every = scene.dynamics.record.every;
  const System system(m);
  Ode ode(system);
  const Eigen::VectorXd y0 = system.RestState();
  double ref_s = 0, s = 0, best = 1e300;
  const Eigen::MatrixXd ref = Run(ode, y0, dt / 100, 100 * steps, 100 * every, &ref_s);
  Eigen::MatrixXd run;
  for (int r = 0; r < 5; ++r) {  // best of five
    run = Run(ode, y0, dt, steps, every, &s);
    best = std::min(best, s);
  }
  const double err = (run - ref).cwiseAbs().maxCoeff();
  const double moved = (ref.rowwise() - ref.row(0)).cwiseAbs().maxCoeff();
  std::printf(
      "%-8s nodes %2d bars %d strings %2d | RK4 dt %g s x %ld: %.3g us/step, %.3g ms total | "
      "max position error %.2e m (motion %.3g m) | reference dt %g s: %.2f s\n",
      name, m.num_nodes(), static_cast<int>(m.bars.size()), static_cast<int>(m.strings.size()), dt,
      steps, 1e6 * best / steps, 1e3 * best, err, moved, dt / 100, ref_s);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : TBRIDGE_SOURCE_DIR "/configs";
  try {
    // The engines "auto" picks for these scenes (dynamics.engine): no node of the prism
    // carries two bars, every node of the D-bar does.
    Scene<Class1System, Class1Ode>("prism", Load(dir + "/motes_prism.json"));
    Scene<ClassKSystem, ClassKOde>("d-bar", Load(dir + "/motes_dbar.json"));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_motes: %s\n", e.what());
    return 1;
  }
  return 0;
}
