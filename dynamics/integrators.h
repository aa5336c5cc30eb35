// Time integrators for y' = f(t, y): fixed-step classical RK4 (the paper's) and adaptive
// Dormand-Prince 5(4) with error control, FSAL and 4th-order dense output (Hairer, Norsett,
// Wanner, "Solving ODEs I", II.5). Both work in caller-owned workspaces (dynamics/workspace.h)
// and allocate nothing per step.
#pragma once

#include <Eigen/Core>

#include "dynamics/workspace.h"

namespace tbridge {

// A first-order system of size() equations. Derivative must not allocate (the integrators
// promise allocation-free steps only if it does not).
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  virtual int size() const = 0;
  // dy = f(t, y); y and dy point to size() values and do not alias.
  virtual void Derivative(double t, const double* y, double* dy) = 0;
  // The rate at which the last Derivative's state loses energy to dissipation [W] (string
  // dampers), integrated by the explicit integrators with their own stage weights: the
  // quadrature that matches their update of the state, so an energy balance closes to the
  // method's order even where the power jumps (a string going slack).
  virtual double DissipatedPower() const { return 0.0; }
};

// One classical RK4 step of size h from (t, y); y is overwritten with y(t + h). `ws` must be
// sized for the system (Rk4Workspace(system.size())); preconditions are not checked here.
// Returns the energy dissipated over the step, h/6 (P1 + 2 P2 + 2 P3 + P4) [J].
// CAUTION: performance-sensitive
double Rk4Step(OdeSystem& system, double t, double h, Eigen::VectorXd& y, Rk4Workspace& ws);

// Rk4Step in two parts, so that a driver can evaluate the first stage of a step as soon as the
// state it starts from is known (the run monitor reads that evaluation): Rk4FirstStage leaves
// k1 = f(t, y) and its dampers' power in ws; Rk4FinishStep takes the rest of the step from them
// and returns what Rk4Step returns. Together they compute exactly what Rk4Step computes.
void Rk4FirstStage(OdeSystem& system, double t, const Eigen::VectorXd& y, Rk4Workspace& ws);
double Rk4FinishStep(OdeSystem& system, double t, double h, Eigen::VectorXd& y, Rk4Workspace& ws);

struct Dopri5Options {
  double rtol = 1e-8;    // relative tolerance [-]
  double atol = 1e-10;   // absolute tolerance [units of y]
  double h_min = 1e-14;  // smallest step before giving up [s]
  double h_max = 0;      // largest step [s]; 0 = no limit
  double safety = 0.9;   // step-size safety factor
  double fac_min = 0.2;  // bounds on the step change per attempt
  double fac_max = 5.0;
  int max_rejections = 50;  // consecutive rejected attempts before giving up
};

// Adaptive Dormand-Prince 5(4). The error of a step is the RMS over all components of
// err_i / (atol + rtol max(|y_i|, |y_new_i|)); a step is accepted when it is <= 1, and the
// next step is h safety err^(-1/5), bounded by fac_min/fac_max. The first stage of a step is
// the last of the previous one (FSAL).
class Dopri5 {
 public:
  explicit Dopri5(const Dopri5Options& options = {}) : options_(options) {}

  // Must be called before Step: evaluates f(t, y) into the FSAL slot.
  void Start(OdeSystem& system, double t, const Eigen::VectorXd& y, Dopri5Workspace& ws);

  // Advances (t, y) by one accepted step of at most min(h, t_end - t). `h` is the proposed
  // size on entry and the next proposal on exit. Returns the accepted step size. Throws
  // ModelError when the step would fall below h_min or too many attempts in a row fail
  // (a non-finite error counts as a failure). The dense output then covers [t_old, t].
  double Step(OdeSystem& system, double& t, Eigen::VectorXd& y, double& h, double t_end,
              Dopri5Workspace& ws);

  // The 4th-order continuous extension of the last accepted step at time t_out in
  // [t_old, t_new]; writes into `out` (sized like y). Allocation-free.
  void Interpolate(double t_out, const Dopri5Workspace& ws, Eigen::VectorXd& out) const;

  // The energy dissipated over the last accepted step, by the 5th-order weights [J].
  double last_dissipated() const { return last_dissipated_; }
  int accepted() const { return accepted_; }
  int rejected() const { return rejected_; }
  int evaluations() const { return evaluations_; }

 private:
  Dopri5Options options_;
  double t_old_ = 0, h_last_ = 0;
  double power_[7] = {0, 0, 0, 0, 0, 0, 0};  // DissipatedPower of each stage [W]
  double last_dissipated_ = 0;
  int accepted_ = 0, rejected_ = 0, evaluations_ = 0;
};

}  // namespace tbridge
