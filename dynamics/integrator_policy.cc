#include "dynamics/integrator_policy.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "dynamics/class1.h"
#include "dynamics/classk.h"
#include "dynamics/initial_state.h"
#include "dynamics/step_size.h"

namespace tbridge {

namespace {

// Unit costs on the reference machine, fitted to `bench_integrator_costs` on the paper's
// bridges n = 2-7 (BENCHMARKS.md, Cost per step, which prints model and measurement side by
// side). Fixed numbers, not timings taken at run time: a config picks the same integrator on
// any machine. The class-k engine's constraint solve is not counted in the right-hand side:
// on a class-k bridge the estimate then leans to RK4 sub-steps, the more accurate choice.
constexpr double kRhsNsPerMember = 4.0;       // ~16-20 ns per member per RK4 step, four sides
constexpr double kRhsNsPerCoordinate = 1.0;   // the loads' copy, x' = v, pinned and lone nodes
constexpr double kSolveNsPerNonzero = 0.8;    // a KLU solve: a multiply-add per nonzero of L + U
constexpr double kVectorNsPerCoordinate = 3;  // a Newton iteration's vector updates and norm
constexpr double kIterationNs = 100;          // a Newton iteration's fixed cost
constexpr double kFactorNsPerFlop = 0.5;      // a KLU refactorisation, per estimated flop
// Newton iterations per step (three stages): 9 on small bridges, growing as a bridge gets
// stiffer with its size, ~ (coordinates / 72)^0.4 (measured 9, 9, 10.5, 12.3, 16, 20 for
// n = 2..7 at dt = 5e-4 s; a step twice as long adds 10-15 %).
constexpr double kNewtonIterationsSmall = 9;
constexpr double kNewtonCoordinatesSmall = 72;
constexpr double kNewtonGrowth = 0.4;
// Jacobian refreshes per step: none up to n = 5, 0.03-0.2 at n = 6, 0.5-0.7 at n = 7; a
// refresh is a small share of a step's cost even there.
constexpr double kRefreshesPerStep = 0.25;

// kAutoRk4Fraction of RK4's stability limit at the state y [s].
double AutoRk4Step(OdeSystem& ode, const Eigen::VectorXd& y) {
  return kAutoRk4Fraction * Rk4StepLimit(HighestFrequency(ode, y).omega_max);
}

}  // namespace

int StepCosts::Rk4StepsPerSdirk3Step() const {
  if (!(rk4_ns > 0)) return 1;
  return std::max(1, static_cast<int>(std::floor(sdirk3_ns / rk4_ns)));
}

StepCosts EstimateStepCosts(int rhs_members, int coordinates, const SdirkCounts& newton) {
  const double rhs = kRhsNsPerMember * rhs_members + kRhsNsPerCoordinate * coordinates;
  const double iteration = rhs + kSolveNsPerNonzero * newton.factor_nonzeros +
                           kVectorNsPerCoordinate * coordinates + kIterationNs;
  const double iterations =
      kNewtonIterationsSmall *
      std::max(1.0, std::pow(coordinates / kNewtonCoordinatesSmall, kNewtonGrowth));
  const double refresh = newton.refresh_evaluations * rhs + kFactorNsPerFlop * newton.factor_flops;
  StepCosts c;
  c.rk4_ns = 4 * rhs;
  c.sdirk3_ns = iterations * iteration + kRefreshesPerStep * refresh;
  return c;
}

EngineKind EngineFor(const DynamicModel& model, const DynamicsConfig& config) {
  const int k = MaxBarsAtANode(model);
  if (config.engine == EngineKind::kClassK) return EngineKind::kClassK;
  if (config.engine == EngineKind::kClass1) {
    if (k > 1) {
      throw ConfigError("dynamics.engine", "\"class1\"",
                        "this bridge is class " + std::to_string(k) +
                            " (a node carries several bars); use \"auto\" or \"classk\"");
    }
    return EngineKind::kClass1;
  }
  return k > 1 ? EngineKind::kClassK : EngineKind::kClass1;
}

IntegratorChoice ResolveIntegrator(IntegratorKind requested, double dt, OdeSystem& ode,
                                   const Eigen::VectorXd& y,
                                   const std::function<StepCosts()>& costs) {
  if (requested != IntegratorKind::kAuto) return {requested, 1};
  const double stable = AutoRk4Step(ode, y);
  const double m = std::ceil(dt / stable - 1e-12);
  if (m <= 1) return {IntegratorKind::kRk4, 1};
  if (m <= costs().Rk4StepsPerSdirk3Step()) return {IntegratorKind::kRk4, static_cast<int>(m)};
  return {IntegratorKind::kSdirk3, 1};
}

EngineOptions EngineOptionsOf(const DynamicsConfig& config) {
  EngineOptions options;
  options.stabilisation = config.stabilisation.enabled;
  options.omega_rad_s = config.stabilisation.omega_rad_s;
  options.zeta = config.stabilisation.zeta;
  return options;
}

double Rk4StableStep(const DynamicModel& model, const DynamicsConfig& config) {
  const EngineOptions options = EngineOptionsOf(config);
  const Eigen::VectorXd y = InitialState(model, config);
  if (EngineFor(model, config) == EngineKind::kClass1) {
    const Class1System system(model, options);
    Class1Ode ode(system);
    return AutoRk4Step(ode, y);
  }
  const ClassKSystem system(model, options);
  ClassKOde ode(system);
  return AutoRk4Step(ode, y);
}

}  // namespace tbridge
