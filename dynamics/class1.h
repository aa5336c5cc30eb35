// The class-1 right-hand side (paper eqs 16-27 with SPEC.md §8), evaluated per member with no
// matrices. Class 1: no node carries more than one bar.
//
// State y (size 2 c, c = dim x n_n): node positions then velocities, node-major
// (x_0, y_0[, z_0], x_1, ...) [m] and [m/s]. Pinned nodes stay in the state with zero
// velocity and acceleration, so they are prescribed exactly (y + h 0 = y) and carry no
// equation of motion (SPEC.md §8, eq 21).
//
// Forces. Each string pulls its ends with force density (eqs 16-17)
//   gamma = max(k (1 - L0/s) + c (s . s_dot)/s^2, 0) if s >= L0, else 0;
// F_i, F_j are the non-bar forces (loads + strings) at a bar's ends, b = n_j - n_i.
// Bars. With point masses m_i, m_j at its ends a uniform rigid bar of mass m has the 2 x 2
// mass matrix M = [m/3 + m_i, m/6; m/6, m/3 + m_j] (eq 21) acting on (a_i, a_j), with the bar
// force lambda b (lambda > 0 in compression) pushing n_j and pulling n_i:
//   M (a_i, a_j) = (F_i - lambda b, F_j + lambda b).
// With A = M^-1, a_j - a_i = p F_i + q F_j + w lambda b (p = A01 - A00, q = A11 - A01,
// w = A00 + A11 - 2 A01), and the length constraint b . (a_j - a_i) + |b_dot|^2 = 0 gives
//   lambda = -(|b_dot|^2 + b . (p F_i + q F_j)) / (w l^2),   l^2 = current |b|^2.
// Without point masses (p, q, w) = (-6, 6, 12)/m and this is eq 23 as corrected in SPEC §8:
//   lambda = -m |b_dot|^2 / (12 l^2) - b . G / (2 l^2),  G = F_j - F_i,
//   b_ddot = (6/m)(G + 2 lambda b), r_ddot = (F_i + F_j)/m, n_i,j_ddot = r_ddot -+ b_ddot/2.
// Stabilisation (eqs 24-26, SPEC §8) makes h = b.b - l0^2 obey h'' + 2 zeta omega h' +
// omega^2 h = 0:  lambda_c = lambda - (2 zeta omega b . b_dot + (omega^2/2) h) / (w l^2),
// i.e. e = m/(12 l^2)(...) without point masses.
// A bar with one pinned end rotates about it: (m/3 + m_j) a_j = F_j + lambda b.
// Free nodes without a bar move as point masses: a = F / m_node.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/engine_frame.h"
#include "dynamics/engine_ode.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/node_forces.h"
#include "dynamics/workspace.h"

namespace tbridge {

using Class1Options = EngineOptions;

class Class1System : public EngineFrame {
 public:
  // Compiles `model` into flat per-member arrays. Throws ModelError when the model fails
  // CheckModel (dynamics/model.h) or is not class 1, a bar's mass matrix is not
  // positive definite, a free node without a bar has no mass, or a timed load names a node
  // out of range.
  Class1System(const DynamicModel& model, const Class1Options& options = {},
               std::vector<TimedLoad> timed_loads = {});

  int num_members() const {
    return static_cast<int>(strings_.size() + bars_.size() + pinned_bars_.size());
  }
  int num_model_bars() const { return n_model_bars_; }

  // dy = f(t, y); t only selects the timed loads. Allocation-free; `ws` must be
  // MakeWorkspace(*this). Leaves the bar force densities and the dampers' power in `ws`.
  // CAUTION: performance-sensitive
  void Derivative(double t, const double* y, double* dy, Class1Workspace& ws) const;

  // The bar force densities lambda (> 0 in compression) [N/m] of the last evaluation in `ws`,
  // in the order of the model's bars (0 for bars with both ends pinned), into `out`.
  // Allocation-free when `out` already has one entry per model bar.
  void BarForceDensities(const Class1Workspace& ws, Eigen::VectorXd& out) const;

 private:
  struct PackedBar {  // both ends free
    int oi, oj;
    double a00, a01, a11;  // inverse mass matrix
    double p, q, inv_w;    // see the top of the file
    double rest_sq;        // l0^2
    int model_index;       // index in model.bars
  };
  struct PinnedBar {  // end i pinned
    int oi, oj;
    double mass;  // m/3 + m_j
    double inv_mass;
    double rest_sq;
    int model_index;
  };

  friend class EngineFrame;  // dispatches to DerivativeImpl
  template <int D, bool Damped, bool Stabilised>
  void DerivativeImpl(double t, const double* y, double* dy, Class1Workspace& ws) const;

  int n_model_bars_ = 0;
  std::vector<PackedBar> bars_;
  std::vector<PinnedBar> pinned_bars_;
};

inline Class1Workspace MakeWorkspace(const Class1System& system) {
  return Class1Workspace(system.coordinates(), system.num_model_bars());
}

// Adapter to the integrators: owns the workspace and can hold the timed loads at one time for
// the stages of a step (dynamics/engine_ode.h).
using Class1Ode = EngineOde<Class1System, Class1Workspace>;

}  // namespace tbridge
