// Cost of the class-k engine: one RK4 step, and the numeric refactorisation of
// A = J M^-1 J^T alone, for planar p = 2 bridges n = 1..max_n and the paper's 3D bridge; the
// class-1 engine on the same p = 1 planar bridges for scale.
//
//   build-classk/bench/bench_classk [max_n]   (default 8)
//
// Each case is timed over enough repetitions to take ~0.2 s, after a warm-up, from the
// design's rest state (every evaluation does the same work whatever the state).

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"

namespace {

// Seconds per call of `body`, timed over doubling repetition counts until a run takes 0.2 s.
template <class Body>
double SecondsPerCall(Body body) {
  body();
  for (long reps = 8;; reps *= 2) {
    const auto start = std::chrono::steady_clock::now();
    for (long k = 0; k < reps; ++k) body();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds > 0.2) return seconds / static_cast<double>(reps);
  }
}

double Rk4StepSeconds(tbridge::OdeSystem& ode, const Eigen::VectorXd& y0) {
  tbridge::Rk4Workspace ws(ode.size());
  Eigen::VectorXd y = y0;
  double t = 0;
  const double dt = 1e-8;  // tiny: the state barely changes, so every step costs the same
  return SecondsPerCall([&] {
    tbridge::Rk4Step(ode, t, dt, y, ws);
    t += dt;
  });
}

void Row(const std::string& name, const tbridge::DynamicModel& model) {
  const tbridge::ClassKSystem system(model);
  tbridge::ClassKOde ode(system);
  const Eigen::VectorXd y0 = system.RestState();
  const double step = Rk4StepSeconds(ode, y0);
  tbridge::ClassKWorkspace ws(system);
  const double factor = SecondsPerCall([&] { ws.Refactorise(); });
  double class1 = 0;
  if (model.tensegrity_class == 1) {
    const tbridge::Class1System one(model);
    tbridge::Class1Ode ode1(one);
    class1 = Rk4StepSeconds(ode1, y0);
  }
  std::printf("%-8s %6d %5zu %6d %7ld %7ld %11.2f %11.2f %11.2f\n", name.c_str(), model.num_nodes(),
              model.bars.size(), system.num_constraints(), system.matrix_nonzeros(),
              ws.factor_nonzeros(), 1e6 * step, 1e6 * factor, 1e6 * class1);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 8;
  std::printf("%-8s %6s %5s %6s %7s %7s %11s %11s %11s\n", "bridge", "nodes", "bars", "rows",
              "nnz(A)", "nnz(L)", "step", "factorise", "class-1");
  std::printf("%-8s %6s %5s %6s %7s %7s %11s %11s %11s\n", "", "", "", "", "", "", "us/RK4",
              "us/call", "us/RK4");
  for (const int p : {1, 2}) {
    for (int n = 1; n <= max_n; ++n) {
      tbridge::Config config;
      config.bridge.n = n;
      config.bridge.p = p;
      char name[16];
      std::snprintf(name, sizeof name, "p%d n%d", p, n);
      Row(name, tbridge::BuildDynamicModel(tbridge::RunDesign(config)));
    }
  }
  tbridge::Config config;
  config.bridge = {2, 1, 20.0, 12.0, 12000.0, 1.5, 2};  // configs/paper_3d.json
  Row("3D n2", tbridge::BuildDynamicModel(tbridge::RunDesign(config)));
  return 0;
}
