// The non-bar node forces every engine needs, in packed coordinates (node-major, `dim` per
// node): the external loads (constant plus timed steps) and the string pulls (eqs 16-17).
// Shared by the class-1 and class-k engines so both apply exactly the same forces.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "dynamics/model.h"

namespace tbridge {

// A force on one node (0-based) for t_start <= t < t_end [s], added to the constant loads,
// ramped up over rise_s and down over fall_s and spread over spread_s (LoadStepConfig); with
// omega_rad_s > 0 it is harmonic, force sin(omega_rad_s t) (a pedestrian crowd's load,
// checks/comfort_check.h).
struct TimedLoad {
  double t_start = 0, t_end = 0;
  int node = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // [N]; z ignored when dim = 2
  double rise_s = 0, fall_s = 0;
  double omega_rad_s = 0;  // [rad/s]; 0: the force as given
  double spread_s = 0;     // [s]; 0: the shape as given
};

// The integral of the unspread shape (below) from t_start to t [s]; rise_s + fall_s <= t_end -
// t_start.
inline double LoadShapeIntegral(double t, double t_start, double t_end, double rise_s,
                                double fall_s) {
  if (t <= t_start) return 0.0;
  const double total = t_end - t_start - 0.5 * (rise_s + fall_s);
  if (t >= t_end) return total;
  const double left = t_end - t;
  if (fall_s > 0 && left < fall_s) return total - 0.5 * left * left / fall_s;
  const double u = t - t_start;
  if (rise_s > 0 && u < rise_s) return 0.5 * u * u / rise_s;
  return u - 0.5 * rise_s;
}

// The fraction of a timed load's force acting at t: 0 outside [t_start, t_end), linear over
// the rise and the fall, 1 between; with spread_s > 0, that shape's mean over
// [t - spread_s / 2, t + spread_s / 2]: a load spread over a length c moving at v is, on each
// node it passes, its point load's shape spread over c / v. The spread rounds each corner of
// the shape into a parabola (the force's slope changes over spread_s, not at once), so that
// an undamped model does not ring at its highest modes at each corner (checks/modal_run.h).
// The interval a timed load acts over [s]: [t_start, t_end), widened by half the spread either
// side when it is spread.
struct LoadInterval {
  double first, last;
};
inline LoadInterval LoadActive(double t_start, double t_end, double spread_s) {
  const double half = spread_s > 0 ? 0.5 * spread_s : 0.0;
  return {t_start - half, t_end + half};
}

inline double LoadShape(double t, double t_start, double t_end, double rise_s, double fall_s,
                        double spread_s = 0) {
  if (spread_s > 0) {
    const LoadInterval active = LoadActive(t_start, t_end, spread_s);
    if (t <= active.first || t >= active.last) return 0.0;
    const double half = 0.5 * spread_s;
    return (LoadShapeIntegral(t + half, t_start, t_end, rise_s, fall_s) -
            LoadShapeIntegral(t - half, t_start, t_end, rise_s, fall_s)) /
           spread_s;
  }
  if (t < t_start || t >= t_end) return 0.0;
  double f = 1.0;
  if (rise_s > 0 && t < t_start + rise_s) f = (t - t_start) / rise_s;
  if (fall_s > 0 && t > t_end - fall_s) f = std::min(f, (t_end - t) / fall_s);
  return f;
}

// One string between coordinate offsets oi, oj (node x dim); `index` is its place in the
// model's strings.
struct PackedString {
  int oi, oj;
  double k, k_rest, c;  // stiffness k [N/m], k L0 [N], damping c [N s/m]
  int index;
};

// Where an evaluation records every string's geometry at its state, by model string: s . s
// [m^2], 1/|s| [1/m] and, when the strings are damped, s . s_dot [m^2/s]. What the run monitor
// measures the strings from (RunMonitor::Accept); three arrays, so that its pass over them
// runs in vector registers.
struct StringGeometry {
  double* len2;
  double* inv_len;
  double* rate;
};

// Loads as a function of time, packed like the positions. Built once; At allocates nothing.
class NodeLoads {
 public:
  NodeLoads() = default;
  // `model` passed CheckModel. Throws ModelError (naming `engine`) when a timed load names a
  // node out of range.
  NodeLoads(const DynamicModel& model, const std::vector<TimedLoad>& timed, const char* engine);

  // force (dim x n_n) = constant loads + the timed loads active at t [N].
  void At(double t, double* force) const;
  bool has_timed() const { return !timed_.empty(); }

 private:
  struct PackedLoad {
    double t_start, t_end, rise_s, fall_s, omega, spread_s;
    int o;
    double f[3];
  };
  int dim_ = 2;
  Eigen::VectorXd constant_;
  std::vector<PackedLoad> timed_;
};

// The strings of `model` (which passed CheckModel) that can move something (not both ends
// pinned), packed for `dim`. `damped` is set when any kept string has c > 0.
std::vector<PackedString> PackStrings(const DynamicModel& model, bool& damped);

// Adds every string's pull to f: force density
//   gamma = max(k (1 - L0/s) + c (s . s_dot)/s^2, 0) if s >= L0, else 0,
// pulling node i by gamma s and node j by -gamma s (s = n_j - n_i). Returns the power the
// dampers take out of the motion, sum (gamma - k (1 - L0/s)) (s . s_dot) over the taut strings
// [W] (0 when not Damped), so that an integrator can integrate it with its own stages.
// CAUTION: performance-sensitive (inlined into the engines' loops).
// With Record, each string's geometry also goes to `record` (its rate only when Damped).
template <int D, bool Damped, bool Record = false>
inline double AccumulateStringForces(const std::vector<PackedString>& strings, const double* x,
                                     const double* v, double* f,
                                     [[maybe_unused]] const StringGeometry* record = nullptr) {
  [[maybe_unused]] double power = 0;
  for (const PackedString& s : strings) {
    double dx[D];
    double len2 = 0;
    for (int d = 0; d < D; ++d) {
      dx[d] = x[s.oj + d] - x[s.oi + d];
      len2 += dx[d] * dx[d];
    }
    const double inv_len = 1.0 / std::sqrt(len2);
    double gamma = s.k - s.k_rest * inv_len;  // k (1 - L0/s): negative exactly when s < L0
    if constexpr (Record) {
      record->len2[s.index] = len2;
      record->inv_len[s.index] = inv_len;
    }
    if constexpr (Damped) {
      double rate = 0;  // s . s_dot
      for (int d = 0; d < D; ++d) rate += dx[d] * (v[s.oj + d] - v[s.oi + d]);
      if constexpr (Record) record->rate[s.index] = rate;
      const double spring = gamma;
      const double total = gamma + s.c * rate * inv_len * inv_len;
      gamma = gamma >= 0 ? std::max(total, 0.0) : 0.0;
      if (spring >= 0) power += (gamma - spring) * rate;
    } else {
      gamma = std::max(gamma, 0.0);
    }
    for (int d = 0; d < D; ++d) {
      f[s.oi + d] += gamma * dx[d];
      f[s.oj + d] -= gamma * dx[d];
    }
  }
  return power;
}

}  // namespace tbridge
