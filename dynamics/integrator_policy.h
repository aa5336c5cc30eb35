// Which engine and which integrator a run takes, decided before its first step from the model
// and the config alone, so that a config always runs the same way on any machine.
#pragma once

#include <Eigen/Core>
#include <functional>

#include "core/dynamics_config.h"
#include "dynamics/engine_frame.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/sdirk.h"

namespace tbridge {

// EngineKind::kAuto resolved: class 1 when no node carries two bars, else class k. Throws
// ConfigError naming dynamics.engine when class 1 is asked of a class-k bridge.
EngineKind EngineFor(const DynamicModel& model, const DynamicsConfig& config);

// "auto" picks RK4 up to this fraction of its linear stability limit 2 sqrt(2)/omega_max. In
// the work-precision benchmark (BENCHMARKS.md) RK4 was stable at every step below the limit,
// up to 0.92 of it, on every scene, 0.1 m pushes with slack chatter included; and between
// half the limit and the limit it beat SDIRK3 (n = 8: 3.4 s against 43 s).
inline constexpr double kAutoRk4Fraction = 0.9;

// The work of one step of each integrator, from counts of the model and of SDIRK3's Newton
// matrix, in nanoseconds of the reference machine (BENCHMARKS.md, Cost per step, where
// `bench_step --sdirk` compares these with measured steps). Only the ratio is used.
struct StepCosts {
  double rk4_ns = 0;     // four right-hand sides
  double sdirk3_ns = 0;  // Newton's evaluations and sparse solves, and a share of a refresh
  // The most RK4 sub-steps that cost no more than one SDIRK3 step (at least 1).
  int Rk4StepsPerSdirk3Step() const;
};

// rhs_members: members the right-hand side visits (strings and bars); coordinates: dim x n_n.
StepCosts EstimateStepCosts(int rhs_members, int coordinates, const SdirkCounts& newton);

struct IntegratorChoice {
  IntegratorKind kind = IntegratorKind::kRk4;  // never kAuto
  int substeps = 1;                            // RK4 steps per step of dt
};

// IntegratorKind::kAuto resolved, with L = kAutoRk4Fraction x RK4's stability limit at the
// state `y` (omega_max by power iteration, dynamics/step_size.h):
// - dt <= L: RK4 at dt;
// - else, while m = ceil(dt / L) RK4 sub-steps cost no more than one SDIRK3 step
//   (m <= costs().Rk4StepsPerSdirk3Step(), asked only here): RK4 with m sub-steps per step;
// - else SDIRK3 at dt, which damps what it does not resolve.
// Any other request is returned as it is, with one sub-step.
IntegratorChoice ResolveIntegrator(IntegratorKind requested, double dt, OdeSystem& ode,
                                   const Eigen::VectorXd& y,
                                   const std::function<StepCosts()>& costs);

// The largest RK4 step that is stable for a run of `config` on `model` at its start:
// kAutoRk4Fraction x 2 sqrt(2) / omega_max, omega_max by power iteration on the engine
// EngineFor picks, with the run's stabilisation [s]. What "auto" takes RK4 up to.
double Rk4StableStep(const DynamicModel& model, const DynamicsConfig& config);

// Both engines' stabilisation settings, from the config.
EngineOptions EngineOptionsOf(const DynamicsConfig& config);

}  // namespace tbridge
