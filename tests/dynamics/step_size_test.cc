// The highest linearised frequency by power iteration against the dense modal analysis.

#include "dynamics/step_size.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/integrators.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"
#include "dynamics/workspace.h"

namespace tbridge {
namespace {

TEST_CASE("power iteration finds the modal analysis's highest frequency") {
  for (int n = 1; n <= 5; ++n) {
    Config c;
    c.bridge.n = n;
    const DynamicModel m = BuildDynamicModel(RunDesign(c));
    const Class1System system(m);
    Class1Ode ode(system);
    const FrequencyBound bound = HighestFrequency(ode, system.RestState());
    const ModalResult modes = ComputeModes(m);
    const double dense = Rk4StableStep(modes);
    INFO("n = " << n << ": omega_max " << bound.omega_max << " rad/s after " << bound.iterations
                << " iterations; RK4 limits " << Rk4StepLimit(bound.omega_max) << " and " << dense
                << " s");
    CHECK(bound.converged);
    // The two differ only by the forward-difference error of the Jacobian product (~1e-7
    // relative) and the power iteration's stopping rule (1e-4): 1e-3 covers both.
    CHECK(Rk4StepLimit(bound.omega_max) == Approx(dense).epsilon(1e-3));
  }
}

// x'' = -omega^2 x as a first-order system: the harmonic oscillator whose RK4 amplification
// decides the stability limit.
class Oscillator final : public OdeSystem {
 public:
  explicit Oscillator(double omega) : omega2_(omega * omega) {}
  int size() const override { return 2; }
  void Derivative(double, const double* y, double* dy) override {
    dy[0] = y[1];
    dy[1] = -omega2_ * y[0];
  }

 private:
  double omega2_;
};

// Energy-norm amplitude after `steps` RK4 steps of size h from x = 1, v = 0.
double AmplitudeAfter(double omega, double h, int steps) {
  Oscillator ode(omega);
  Rk4Workspace ws(2);
  Eigen::VectorXd y(2);
  y << 1.0, 0.0;
  for (int k = 0; k < steps; ++k) Rk4Step(ode, k * h, h, y, ws);
  return std::hypot(y[0], y[1] / omega);
}

TEST_CASE("the RK4 step limit is where the integrator itself turns unstable") {
  // Independent of the formula: the project's RK4 on the oscillator it is meant for. Per step
  // the amplitude grows by |R(i omega h)|, R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, and
  // |R(iy)|^2 = 1 + y^6 (y^2 - 8)/576 crosses 1 at y = 2 sqrt(2). 1 % either side of the
  // limit |R|^2 = 0.87 and 1.15, so 2000 steps shrink or grow the amplitude by e^(-+140):
  // far beyond the 1e-10 and 1e10 asserted, and a limit off by 1 % in either direction fails.
  const double omega = 100.0;
  const double limit = Rk4StepLimit(omega);
  CHECK(AmplitudeAfter(omega, 0.99 * limit, 2000) < 1e-10);
  CHECK(AmplitudeAfter(omega, 1.01 * limit, 2000) > 1e10);
  // No strings, no stiffness: nothing limits the step.
  CHECK(Rk4StepLimit(0) > 1e100);
}

}  // namespace
}  // namespace tbridge
