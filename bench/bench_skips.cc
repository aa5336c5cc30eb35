// What skipping unneeded work saves: each line times a scene with and without one feature the
// scene does not need, on the paper's planar bridge of complexity n.
//
//   build/bench/bench_skips [n=6]
//
// - damping: the velocity terms run only when some string has c > 0; forced on here with
//   c = 1e-300 N s/m (no physical effect) against c = 0;
// - multipliers: the class-1 closed form against the class-k engine (sparse Cholesky of the
//   bar-constraint matrix) on the same class-1 bridge;
// - recording: Simulate with nothing recorded and no deck samples against every node
//   recorded every step plus deck samples every step;
// - modal analysis: ComputeModes (dense) is never run by Simulate; its cost is what is saved,
//   beside the power iteration that the automatic integrator uses instead;
// - string mass: off (no point masses, no lumping) against on the bars (eq. 27) and at nodes.
// Times are ns per step (whole RK4 step) unless marked; best of three.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/integrators.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"
#include "dynamics/simulation.h"
#include "dynamics/step_size.h"

namespace {

using namespace tbridge;
using Clock = std::chrono::steady_clock;

// Best of three: seconds for one call of `f`.
double Best(const std::function<void()>& f) {
  double best = 1e300;
  for (int k = 0; k < 3; ++k) {
    const auto start = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
  }
  return best;
}

// ns per RK4 step of `ode` over `steps` tiny steps from y0.
double NsPerStep(OdeSystem& ode, const Eigen::VectorXd& y0, long steps) {
  Rk4Workspace ws(ode.size());
  Eigen::VectorXd y = y0;
  return 1e9 * Best([&] {
           y = y0;
           for (long k = 0; k < steps; ++k) Rk4Step(ode, k * 1e-8, 1e-8, y, ws);
         }) /
         static_cast<double>(steps);
}

void Line(const char* what, const char* with, double a, const char* without, double b,
          const char* unit) {
  std::printf("%-16s %-34s %12.4g %s | %-30s %12.4g %s | saved %5.1f %%  (x%.2f)\n", what, with, a,
              unit, without, b, unit, 100.0 * (a - b) / a, a / b);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 6;
  Config config;
  config.bridge.n = n;
  const Design design = RunDesign(config);
  const DynamicModel plain = BuildDynamicModel(design);
  DynamicsConfig scene;
  scene.perturbation = {1, 1e-4};
  const Eigen::VectorXd y0 = InitialState(plain, scene);
  const long steps =
      std::max<long>(200, 2000000 / static_cast<long>(plain.strings.size() + plain.bars.size()));
  std::printf("n = %d: %d nodes, %zu bars, %zu strings; %ld steps per timing\n", n,
              plain.num_nodes(), plain.bars.size(), plain.strings.size(), steps);

  {  // damping
    ModelOptions o;
    o.damping = 1e-300;
    const DynamicModel damped = BuildDynamicModel(design, o);
    const Class1System a(damped), b(plain);
    Class1Ode oa(a), ob(b);
    Line("damping", "velocity terms (c = 1e-300)", NsPerStep(oa, y0, steps), "skipped (c = 0)",
         NsPerStep(ob, y0, steps), "ns/step");
  }
  {  // multipliers
    const ClassKSystem k(plain);
    ClassKOde ok(k);
    const Class1System one(plain);
    Class1Ode o1(one);
    Line("multipliers", "class-k engine (CHOLMOD solve)", NsPerStep(ok, y0, steps / 4),
         "class-1 closed form", NsPerStep(o1, y0, steps), "ns/step");
  }
  {  // recording
    DynamicsConfig full = scene;
    full.duration = 2000 * 1e-6;
    full.dt = 1e-6;
    full.frequency.enabled = false;
    DynamicsConfig none = full;
    for (int a = 1; a <= plain.num_nodes(); ++a) full.record.nodes.push_back(a);
    full.frequency.enabled = true;
    full.frequency.every = 1;
    const double with = Best([&] { Simulate(plain, full); }) / 2000 * 1e9;
    const double without = Best([&] { Simulate(plain, none); }) / 2000 * 1e9;
    Line("recording", "all nodes + deck every step", with, "nothing recorded", without, "ns/step");
    // The summary's monitor (energy, stresses, slack, guard) runs on every accepted step;
    // against the bare RK4 loop it is the price of the guard.
    const Class1System s(plain);
    Class1Ode o(s);
    Line("monitor", "Simulate, nothing recorded", without, "bare RK4 loop", NsPerStep(o, y0, 2000),
         "ns/step");
  }
  {  // modal analysis
    const Class1System s(plain);
    Class1Ode o(s);
    const double modal = n <= 9 ? Best([&] { ComputeModes(plain); }) : 0.0;
    const double power = Best([&] { HighestFrequency(o, s.RestState()); });
    if (n <= 9) {
      Line("modal analysis", "ComputeModes (dense)", 1e3 * modal, "power iteration (omega_max)",
           1e3 * power, "ms");
    }
  }
  {  // string mass
    ModelOptions nodes, off;
    nodes.string_mass = StringMassMode::kAtNodes;
    off.string_mass = StringMassMode::kOff;
    const DynamicModel mn = BuildDynamicModel(design, nodes), mo = BuildDynamicModel(design, off);
    const Class1System a(plain), b(mn), c(mo);
    Class1Ode oa(a), ob(b), oc(c);
    const double off_ns = NsPerStep(oc, y0, steps);
    Line("string mass", "on the bars (eq. 27)", NsPerStep(oa, y0, steps), "off", off_ns, "ns/step");
    Line("string mass", "at the nodes", NsPerStep(ob, y0, steps), "off", off_ns, "ns/step");
    const double build_on = Best([&] { BuildDynamicModel(design); });
    const double build_off = Best([&] { BuildDynamicModel(design, off); });
    Line("model build", "string mass on the bars", 1e6 * build_on, "off", 1e6 * build_off, "us");
  }
  return 0;
}
