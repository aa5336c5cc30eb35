// The highest linearised frequency by power iteration against the dense modal analysis.

#include "dynamics/step_size.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "core/config.h"
#include "design/design.h"
#include "dynamics/class1.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"

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
                << " iterations; RK4 limits " << Rk4StepLimit(bound.omega_max) << " and " << dense << " s");
    CHECK(bound.converged);
    // The two differ only by the forward-difference error of the Jacobian product (~1e-7
    // relative) and the power iteration's stopping rule (1e-4): 1e-3 covers both.
    CHECK(Rk4StepLimit(bound.omega_max) == Approx(dense).epsilon(1e-3));
  }
}

TEST_CASE("no strings, no stiffness: the step limit is unbounded") {
  CHECK(Rk4StepLimit(0) > 1e100);
  CHECK(Rk4StepLimit(100) == Approx(2 * std::sqrt(2.0) / 100).epsilon(1e-15));  // the formula itself
}

}  // namespace
}  // namespace tbridge
