// The implicit integrator for stiff scenes: a three-stage, third-order, L-stable singly
// diagonally implicit Runge-Kutta method (Alexander 1977; Hairer & Wanner, "Solving ODEs II",
// IV.6, Table 6.5 with gamma = 0.43586652150845899942), at a fixed step.
//
// Why this method. As n grows the bridges' highest linearised frequency climbs by orders of
// magnitude while the motion of interest stays near 50-200 rad/s (SPEC.md §9). An explicit
// method must resolve the highest frequency (RK4: dt < 2 sqrt(2)/omega_max); an L-stable one
// takes steps sized for the motion and damps the unresolved stiff modes (bar-string rattling)
// instead of blowing up. All three stages share one Newton matrix, so one factorisation
// serves a step and, while Newton converges fast, many steps.
//
// The system is second order: y = (x, v), x' = v, v' = a(t, x, v), with x and v of size c
// (state layout of dynamics/class1.h). Each stage solves for its velocity V only:
//   X = s_x + h gamma V,  G(V) = V - s_v - h gamma a(X, V) = 0,
// with the simplified Newton matrix I - h gamma D, D = h gamma da/dx + da/dv. D is estimated
// by forward differences along (h gamma e_q, e_q), one evaluation per colour and direction
// (dynamics/coupling.h), and factorised by KLU on a pattern analysed once (core/klu_factor.h).
//
// Allocation. The constructor allocates every buffer and analyses the pattern. A step
// allocates nothing unless it refreshes the Jacobian: KLU's numeric factorisation allocates
// its factors. The Jacobian is refreshed only when Newton converges slowly (contraction
// > 0.5 or more than `fast_iterations`): first at the step's start, then, across slack kinks
// where the right-hand side is only piecewise smooth, at the current iterate (semismooth
// Newton).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/klu_factor.h"
#include "dynamics/coupling.h"
#include "dynamics/integrators.h"

namespace tbridge {

struct SdirkOptions {
  // Newton stops when max_i |dV_i| / (abs_tol + rel_tol |V_i|) <= 1 [m/s, -]. Far below the
  // discretisation error of any useful step so that Newton adds nothing visible.
  // 1e-8 m/s sits just above what rounding allows on a stiff bridge (x ~ 10 m carries
  // 1e-15 m of rounding, times omega_max^2 ~ 1e10 s^-2, times h gamma ~ 1e-4 s).
  double abs_tol = 1e-8;
  double rel_tol = 1e-8;
  int max_iterations = 30;       // per stage, then the step fails
  int fast_iterations = 6;       // this many without converging triggers a refresh
  double max_contraction = 0.5;  // ||dV_k+1|| / ||dV_k|| above this triggers a refresh
  int max_refreshes = 4;         // re-linearisations within one stage (slack kinks)
  // When Newton fails even with a fresh Jacobian (a slack kink inside the step can leave no
  // contraction), the step is done as two halves, recursively, at most this many times deep
  // (h / 2^k); only then does Step throw. Rare: the default step sizes rarely need it.
  int max_halvings = 6;
  // Forward-difference increment: the velocity moves by eps max(1, |v_q|) and the position
  // by h gamma times that, but at least eps max(1, |x_q|) [-].
  double fd_eps = 1e-7;
};

struct SdirkStats {
  long steps = 0;     // accepted steps, halves of split steps counted singly
  long halvings = 0;  // steps split in two after Newton failed
  long newton_iterations = 0;
  long jacobians = 0;    // Jacobian estimates (each costs colours x dim evaluations)
  long evaluations = 0;  // right-hand-side calls, Jacobian ones included
  int colours = 0;
};

// What a step's work scales with, from the pattern alone (known before any step).
struct SdirkCounts {
  long matrix_nonzeros = 0;     // of the Newton matrix I - h gamma D
  double factor_nonzeros = 0;   // KLU's estimate of nonzeros in L + U: a solve's work
  double factor_flops = 0;      // KLU's estimate of a factorisation's flops
  int refresh_evaluations = 0;  // right-hand sides a Jacobian refresh takes: colours x dim + 1
};

class Sdirk3 {
 public:
  // `coupling` gives the Jacobian's pattern; `size` is the state size 2 c of the system it
  // will step. Throws std::invalid_argument when size != 2 dim n_n of the coupling.
  Sdirk3(const AccelerationCoupling& coupling, int size, const SdirkOptions& options = {});
  ~Sdirk3();
  Sdirk3(const Sdirk3&) = delete;
  Sdirk3& operator=(const Sdirk3&) = delete;

  // One step of size h [s] from (t, y); y becomes y(t + h). `system` must be second order as
  // described at the top and of the size given to the constructor. Throws ModelError naming
  // t and proposing a smaller dt when Newton fails with a fresh Jacobian at max_halvings deep,
  // when the state is not finite, or when the factorisation fails.
  void Step(OdeSystem& system, double t, double h, Eigen::VectorXd& y);

  const SdirkStats& stats() const { return stats_; }
  // The energy dissipated over the last Step, by the method's own weights on the stages'
  // damper power (stiffly accurate: b = the last row of A), halves of a split step added [J].
  double last_dissipated() const { return last_dissipated_; }
  const SdirkCounts& counts() const { return counts_; }

 private:
  // Step, split in halves while Newton fails (up to `halvings_left` deep).
  void Split(OdeSystem& system, double t, double h, Eigen::VectorXd& y, int halvings_left);
  // One step; false (y untouched) when Newton fails with a fresh Jacobian.
  bool Attempt(OdeSystem& system, double t, double h, Eigen::VectorXd& y);
  // Estimates D at (t, y) for step h and factorises I - h gamma D.
  void Refresh(OdeSystem& system, double t, double h, const Eigen::VectorXd& y);
  // Solves one stage; returns false when Newton must restart with a fresh Jacobian.
  bool SolveStage(OdeSystem& system, int stage, double t_stage, double h, bool fresh);

  int c_ = 0;
  SdirkOptions options_;
  SdirkStats stats_;
  SdirkCounts counts_;
  // Column groups: per colour and direction, the value slots of the matrix they fill.
  struct Slot {
    int value;  // index into the matrix's value array
    int row;    // coordinate row
    int col;    // coordinate column
  };
  std::vector<std::vector<int>> group_columns_;  // coordinate columns per (colour, direction)
  std::vector<std::vector<Slot>> group_slots_;
  std::vector<int> diagonal_;           // value index of each diagonal entry
  Eigen::SparseMatrix<double> matrix_;  // I - h gamma D, fixed pattern
  KluFactor lu_;                        // the sparse LU of I - h gamma D
  double factor_h_ = 0;                 // step the current factorisation was made for (0: none)
  double stage_power_[3] = {0, 0, 0};   // DissipatedPower at each stage's last Newton iterate [W]
  double last_dissipated_ = 0;
  // Workspace: state-sized (2 c) and coordinate-sized (c) buffers.
  Eigen::VectorXd y0_, dy_, dy_pert_, y_pert_, stage_;
  Eigen::VectorXd sx_, sv_, vel_, vel_old_, residual_, delta_, eps_;
  Eigen::VectorXd kx_[3], kv_[3];
};

}  // namespace tbridge
