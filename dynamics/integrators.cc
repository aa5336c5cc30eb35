#include "dynamics/integrators.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace tbridge {

double Rk4Step(OdeSystem& system, double t, double h, Eigen::VectorXd& y, Rk4Workspace& ws) {
  Rk4FirstStage(system, t, y, ws);
  return Rk4FinishStep(system, t, h, y, ws);
}

void Rk4FirstStage(OdeSystem& system, double t, const Eigen::VectorXd& y, Rk4Workspace& ws) {
  system.Derivative(t, y.data(), ws.k1.data());
  ws.first_power = system.DissipatedPower();
}

double Rk4FinishStep(OdeSystem& system, double t, double h, Eigen::VectorXd& y, Rk4Workspace& ws) {
  // CAUTION: performance-sensitive. Every expression below is evaluated lazily into an
  // existing vector, so no temporary is allocated.
  const double half = 0.5 * h;
  double power = ws.first_power;
  ws.stage = y + half * ws.k1;
  system.Derivative(t + half, ws.stage.data(), ws.k2.data());
  power += 2.0 * system.DissipatedPower();
  ws.stage = y + half * ws.k2;
  system.Derivative(t + half, ws.stage.data(), ws.k3.data());
  power += 2.0 * system.DissipatedPower();
  ws.stage = y + h * ws.k3;
  system.Derivative(t + h, ws.stage.data(), ws.k4.data());
  power += system.DissipatedPower();
  y += (h / 6.0) * (ws.k1 + 2.0 * (ws.k2 + ws.k3) + ws.k4);
  return (h / 6.0) * power;
}

namespace {

// Dormand-Prince 5(4) tableau (Hairer, Norsett, Wanner, Table II.5.2).
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                 a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                 a76 = 11.0 / 84;
// Error weights: 5th-order minus embedded 4th-order solution.
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
// Dense output (Shampine's 4th-order extension, as in Hairer's DOPRI5).
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

}  // namespace

void Dopri5::Start(OdeSystem& system, double t, const Eigen::VectorXd& y, Dopri5Workspace& ws) {
  system.Derivative(t, y.data(), ws.k[0].data());
  power_[0] = system.DissipatedPower();
  ++evaluations_;
  t_old_ = t;
}

double Dopri5::Step(OdeSystem& system, double& t, Eigen::VectorXd& y, double& h, double t_end,
                    Dopri5Workspace& ws) {
  // CAUTION: performance-sensitive (allocation-free: lazy Eigen expressions into workspace).
  Eigen::VectorXd* k = ws.k;
  int failures = 0;
  for (;;) {
    if (options_.h_max > 0) h = std::min(h, options_.h_max);
    const double step = std::min(h, t_end - t);
    if (step < options_.h_min) {
      std::ostringstream msg;
      msg << "dopri5: step " << step << " s at t = " << t
          << " s fell below the minimum: the run blew up or is too stiff for an explicit "
             "method; try rk4 with a smaller dt";
      throw ModelError(msg.str());
    }
    ws.stage = y + step * a21 * k[0];
    system.Derivative(t + c2 * step, ws.stage.data(), k[1].data());
    power_[1] = system.DissipatedPower();
    ws.stage = y + step * (a31 * k[0] + a32 * k[1]);
    system.Derivative(t + c3 * step, ws.stage.data(), k[2].data());
    power_[2] = system.DissipatedPower();
    ws.stage = y + step * (a41 * k[0] + a42 * k[1] + a43 * k[2]);
    system.Derivative(t + c4 * step, ws.stage.data(), k[3].data());
    power_[3] = system.DissipatedPower();
    ws.stage = y + step * (a51 * k[0] + a52 * k[1] + a53 * k[2] + a54 * k[3]);
    system.Derivative(t + c5 * step, ws.stage.data(), k[4].data());
    power_[4] = system.DissipatedPower();
    ws.stage = y + step * (a61 * k[0] + a62 * k[1] + a63 * k[2] + a64 * k[3] + a65 * k[4]);
    system.Derivative(t + step, ws.stage.data(), k[5].data());
    power_[5] = system.DissipatedPower();
    ws.y_new = y + step * (a71 * k[0] + a73 * k[2] + a74 * k[3] + a75 * k[4] + a76 * k[5]);
    system.Derivative(t + step, ws.y_new.data(), k[6].data());
    power_[6] = system.DissipatedPower();
    evaluations_ += 6;

    // Error estimate, reusing `stage` for the difference of the two solutions.
    ws.stage = step * (e1 * k[0] + e3 * k[2] + e4 * k[3] + e5 * k[4] + e6 * k[5] + e7 * k[6]);
    double sum = 0;
    const Eigen::Index n = y.size();
    for (Eigen::Index i = 0; i < n; ++i) {
      const double scale =
          options_.atol + options_.rtol * std::max(std::abs(y[i]), std::abs(ws.y_new[i]));
      const double r = ws.stage[i] / scale;
      sum += r * r;
    }
    const double err = n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
    if (std::isfinite(err) && err <= 1.0) {
      // Dense output coefficients of this step, then accept.
      ws.dense[0] = y;
      ws.dense[1] = ws.y_new - y;
      ws.dense[2] = step * k[0] - ws.dense[1];
      ws.dense[3] = ws.dense[1] - step * k[6] - ws.dense[2];
      ws.dense[4] = step * (d1 * k[0] + d3 * k[2] + d4 * k[3] + d5 * k[4] + d6 * k[5] + d7 * k[6]);
      t_old_ = t;
      h_last_ = step;
      t = (step == t_end - t) ? t_end : t + step;
      y.swap(ws.y_new);
      k[0].swap(k[6]);  // FSAL
      last_dissipated_ = step * (a71 * power_[0] + a73 * power_[2] + a74 * power_[3] +
                                 a75 * power_[4] + a76 * power_[5]);
      power_[0] = power_[6];
      ++accepted_;
      const double fac = err > 0 ? options_.safety * std::pow(err, -0.2) : options_.fac_max;
      h = step * std::clamp(fac, options_.fac_min, options_.fac_max);
      return step;
    }
    ++rejected_;
    if (++failures > options_.max_rejections) {
      std::ostringstream msg;
      msg << "dopri5: " << failures << " rejected steps in a row at t = " << t << " s (last error "
          << err << "); the run blew up or the tolerances are too tight";
      throw ModelError(msg.str());
    }
    const double fac =
        std::isfinite(err) ? options_.safety * std::pow(err, -0.2) : options_.fac_min;
    h = step * std::clamp(fac, options_.fac_min, 1.0);
  }
}

void Dopri5::Interpolate(double t_out, const Dopri5Workspace& ws, Eigen::VectorXd& out) const {
  const double theta = h_last_ > 0 ? (t_out - t_old_) / h_last_ : 1.0;
  const double theta1 = 1.0 - theta;
  out =
      ws.dense[0] +
      theta * (ws.dense[1] + theta1 * (ws.dense[2] + theta * (ws.dense[3] + theta1 * ws.dense[4])));
}

}  // namespace tbridge
