// Nonlinear static analysis of a prestressed tensegrity: rigid bars, elastic strings that go
// slack, large displacements.
//
// Unknowns: the free node positions x and one multiplier per bar. Equilibrium at every free
// node, f_ext + f_strings(x) + C(x)^T lambda = 0, with C the gradient of the bar constraints
// g_b = |x_j - x_i|^2 - l_b^2 = 0 (bar compression = 2 lambda_b l_b). A string pulls with
// T = k (s - L0) while s > L0, else nothing. Newton's method on the saddle-point system
//   [K_t - sum lambda_b H_b   -C^T] [dx]   [R]
//   [C                         0  ] [dl] = [-g]
// (K_t the strings' tangent stiffness, H_b the Hessian of g_b), with the load applied in
// steps from a state in equilibrium, halving a step that does not converge.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/klu_factor.h"
#include "core/structure.h"

namespace tbridge {

// The constant data of the analysis. Bar lengths are those of `structure.nodes`.
struct StaticModel {
  Structure structure;
  std::vector<double> string_stiffness;    // k = E A / L0 [N/m]
  std::vector<double> string_rest_length;  // L0 [m]
};

struct StaticState {
  Eigen::Matrix3Xd nodes;           // positions [m]
  Eigen::VectorXd bar_compression;  // [N], per bar (negative: tension)
  Eigen::VectorXd string_tension;   // [N], per string (0 when slack)
  Eigen::Matrix3Xd reactions;       // [N], zero at free nodes; balance the applied loads
};

struct StaticResult {
  StaticState state;
  bool converged = false;
  int newton_iterations = 0;
  int load_steps = 0;
  double residual = 0;  // largest |force imbalance| at a free node [N]
  int slack_strings = 0;
  std::string message;  // why it did not converge
};

class StaticWorkspace;

// The linear response about a state in equilibrium: SolveStatic's Newton matrix at `state`
// (its bar forces as the multipliers, the strings' tangent at its geometry), factorised once,
// so that each load change costs a pair of triangular solves. The first-order change of the
// state under a load change df: [dx; dlambda] = -J^-1 [df; 0], a bar's compression changing by
// 2 l_b dlambda_b and a taut string's tension by k_s e_s . (dx_j - dx_i) (a string slack in
// `state` stays at 0). The model and state must outlive it.
class StaticTangent {
 public:
  StaticTangent(const StaticModel& model, const StaticState& state);
  // Whether the matrix factorised (a mechanism the state's forces do not hold does not).
  bool ok() const { return ok_; }
  // The changes under `dloads` (3 x n_n [N]): node displacements (3 x n_n [m], zero at fixed
  // nodes) and member forces [dC_bars; dT_strings] [N]; the outputs are sized on first use.
  void Solve(const Eigen::Matrix3Xd& dloads, Eigen::Matrix3Xd& displacement,
             Eigen::VectorXd& force_change);

 private:
  friend StaticResult SolveStatic(const StaticModel&, const StaticState&, const Eigen::Matrix3Xd&,
                                  const Eigen::Matrix3Xd&, const StaticTangent*, StaticWorkspace*);
  const StaticModel& model_;
  const StaticState& state_;
  std::vector<int> first_;  // per node, its first free coordinate or -1 (fixed)
  int dim_ = 3, free_ = 0;
  bool ok_ = false;
  KluFactor lu_;                // of the Newton matrix at `state`
  Eigen::VectorXd rhs_, step_;  // the solves' workspace
};

// The scratch that a series of static solves of one model shares: the Newton matrix's pattern,
// its KLU analysis and the pivots of its last factorisation. A solve given it analyses nothing
// again and factorises with the last pivots (klu_refactor); the static check's stations take
// 3.4 Newton steps each, and the analysis and first factorisation of each solve were a third of
// the check. Tied to the first model it serves (the model must outlive it); a solve of another
// model starts it afresh.
class StaticWorkspace {
 public:
  StaticWorkspace();
  ~StaticWorkspace();
  StaticWorkspace(const StaticWorkspace&) = delete;
  StaticWorkspace& operator=(const StaticWorkspace&) = delete;

 private:
  friend StaticResult SolveStatic(const StaticModel&, const StaticState&, const Eigen::Matrix3Xd&,
                                  const Eigen::Matrix3Xd&, const StaticTangent*, StaticWorkspace*);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Equilibrium under `loads` (3 x n_n [N]), starting from `start`, a state in equilibrium under
// `start_loads` (its bar forces seed the multipliers). Planar structures move in x-y only.
// `tangent`, when given, is a StaticTangent of this model at `start`: its factorisation serves
// the Newton steps taken from `start` (the same matrix, not factorised again). `workspace`,
// when given, is shared with the other solves of this model (the same result, less work).
StaticResult SolveStatic(const StaticModel& model, const StaticState& start,
                         const Eigen::Matrix3Xd& start_loads, const Eigen::Matrix3Xd& loads,
                         const StaticTangent* tangent = nullptr,
                         StaticWorkspace* workspace = nullptr);

// A series of static solves of one model whose loads change a little from one to the next (a
// load crossing the deck, station by station): each solve starts from the last one's
// equilibrium where that converged, else from `start` (a state in equilibrium under
// `start_loads`, with `tangent` as SolveStatic's), and all share one StaticWorkspace. From the
// last station's equilibrium Newton takes 3.4 steps per station, from the reference state 10.4
// (the default at n = 6), to the same equilibrium within the solve's tolerance. `model`,
// `start`, `start_loads` and `tangent` must outlive it.
class StaticSeries {
 public:
  StaticSeries(const StaticModel& model, const StaticState& start,
               const Eigen::Matrix3Xd& start_loads, const StaticTangent* tangent = nullptr)
      : model_(model), start_(start), start_loads_(start_loads), tangent_(tangent) {}
  // Equilibrium under `loads` (as SolveStatic's), from the last solve's where it converged.
  StaticResult Solve(const Eigen::Matrix3Xd& loads);
  // The next solve starts from `start` (the loads of another case follow).
  void Restart() { last_.reset(); }

 private:
  const StaticModel& model_;
  const StaticState& start_;
  const Eigen::Matrix3Xd& start_loads_;
  const StaticTangent* tangent_;
  StaticWorkspace workspace_;
  std::optional<StaticState> last_;  // the last solve's equilibrium, where it converged
  Eigen::Matrix3Xd last_loads_;      // its loads
};

// The force every member exerts on the nodes of `nodes` with the given bar compressions,
// string tensions from the model (slack = 0), and the reactions that balance `loads`.
StaticState StateAt(const StaticModel& model, const Eigen::Matrix3Xd& nodes,
                    const Eigen::VectorXd& bar_compression, const Eigen::Matrix3Xd& loads);

}  // namespace tbridge
