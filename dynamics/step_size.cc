#include "dynamics/step_size.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace tbridge {

FrequencyBound HighestFrequency(OdeSystem& system, const Eigen::VectorXd& y,
                                const FrequencyBoundOptions& options) {
  const Eigen::Index n = system.size(), c = n / 2;
  Eigen::VectorXd base = y, probe(n), f0(n), f1(n);
  base.tail(c).setZero();
  system.Derivative(0.0, base.data(), f0.data());
  const double scale = std::max(1.0, base.head(c).cwiseAbs().maxCoeff());
  // A fixed, non-symmetric start so that no mode is missed by symmetry.
  Eigen::VectorXd w(c);
  for (Eigen::Index i = 0; i < c; ++i)
    w[i] = 1.0 + 0.37 * std::sin(1.0 + 2.3 * static_cast<double>(i));
  w.normalize();
  FrequencyBound out;
  double previous = 0;
  for (int k = 0; k < options.max_iterations; ++k) {
    const double h = options.increment * scale;
    probe = base;
    probe.head(c) += h * w;
    system.Derivative(0.0, probe.data(), f1.data());
    Eigen::VectorXd::SegmentReturnType aw = f1.tail(c);
    aw -= f0.tail(c);
    aw /= h;
    const double norm = aw.norm();
    if (!std::isfinite(norm))
      throw ModelError("highest frequency: the right-hand side is not finite");
    out.iterations = k + 1;
    if (norm == 0) break;  // nothing is stiff (no strings): omega_max = 0
    out.omega_max = std::sqrt(norm);
    w = aw / norm;
    if (k > 20 && std::abs(out.omega_max - previous) <= options.tolerance * out.omega_max) {
      out.converged = true;
      break;
    }
    previous = out.omega_max;
  }
  return out;
}

double Rk4StepLimit(double omega_max) {
  return omega_max > 0 ? 2.0 * std::numbers::sqrt2 / omega_max : 1e300;
}

}  // namespace tbridge
