// The class-k right-hand side: bars may share nodes, and every bar length is held by a
// Lagrange multiplier (the formulation the paper cites in Sect. 7.3: Skelton; Cheong and
// Skelton). Same state and forces as the class-1 engine (dynamics/class1.h), so the
// integrators and the scenario driver take either.
//
// State y (size 2 c, c = dim x n_n): node positions then velocities, node-major [m], [m/s].
// Pinned nodes stay in the state with zero velocity and acceleration (prescribed, SPEC §8).
//
// Formulation. Every bar gets its own copy of each free end node, so the mass matrix stays
// the per-bar 2 x 2 block of eq 21, M_b = [m/3 m/6; m/6 m/3] (x) I_dim, inverted once (a
// pinned end drops its row: m/3). A node's point mass and its non-bar force F (loads plus
// strings) go to its first copy (the "primary"); a free node without bars is a point mass.
// Constraints on the copies q (J: n_c x dim n_copies):
//   bar k:          (b.b - l0^2)/2 = 0,  row -b^T on the copy of end i, +b^T on end j;
//   coincidence:    q_r - q_0 = 0 for every further copy r of a node with primary 0 (dim rows).
// With M a = F + J^T mu and J a = -J' v - stabilisation:
//   (J M^-1 J^T) mu = -(J' v + s) - J M^-1 F,   a = M^-1 (F + J^T mu),
// where J' v is |b_dot|^2 on bar rows and 0 on coincidence rows, and s the Baumgarte term
// 2 zeta omega b.b_dot + (omega^2/2)(b.b - l0^2) on bar rows (SPEC eq 26: h = b.b - l0^2
// obeys h'' + 2 zeta omega h' + omega^2 h = 0). mu_k of a bar row is its force density
// lambda (> 0 in compression, as in class 1). The copies are filled from the node state at
// every evaluation, so they coincide exactly in position and velocity and the coincidence
// rows need no stabilisation. On a class-1 model there are no coincidence rows and this is
// the class-1 closed form.
//
// The matrix A = J M^-1 J^T (symmetric positive definite when the bar constraints are
// independent) has a fixed sparsity pattern: bar rows couple only to the coincidence rows of
// their own copies, coincidence rows to those sharing a bar. Its coincidence-coincidence
// entries are constant; the rest are linear in b (bar-bar: w |b|^2). The pattern is analysed
// once (AMD ordering, then CHOLMOD's symbolic analysis of the permuted matrix); each
// evaluation refreshes the values, refactorises numerically into the same simplicial LDL^T
// factor and solves with it.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "dynamics/class1.h"
#include "dynamics/engine_ode.h"
#include "dynamics/integrators.h"
#include "dynamics/model.h"
#include "dynamics/node_forces.h"

namespace tbridge {

// The stabilisation settings are those of class 1: omega [rad/s] > 0, zeta [-] >= 0.
using ClassKOptions = EngineOptions;

class ClassKWorkspace;

class ClassKSystem : public EngineFrame {
 public:
  // Compiles `model` into flat arrays and the constant pattern of A. Throws ModelError when
  // the model fails CheckModel (dynamics/model.h), a bar has a singular mass block, a free node
  // without a bar has no mass, stabilisation has omega <= 0 or zeta < 0, or a timed load names a
  // node out of range.
  ClassKSystem(const DynamicModel& model, const ClassKOptions& options = {},
               std::vector<TimedLoad> timed_loads = {});

  int num_copies() const { return static_cast<int>(copies_.size()); }
  int num_bars() const { return static_cast<int>(bars_.size()); }  // bars with a free end
  int num_constraints() const { return n_rows_; }                  // bar rows + dim x extra copies
  long matrix_nonzeros() const { return static_cast<long>(a_row_.size()); }  // lower triangle

  // dy = f(t, y). `ws` must be ClassKWorkspace(*this). Allocation-free after the workspace's
  // construction (see ClassKWorkspace). Throws ModelError when A is not positive definite
  // (dependent bar constraints, or a bar of zero length).
  // CAUTION: performance-sensitive
  void Derivative(double t, const double* y, double* dy, ClassKWorkspace& ws) const;

  // The bar force densities lambda (> 0 in compression) [N/m] of the last evaluation in `ws`,
  // in the order of the model's bars (0 for bars with both ends pinned), into `out`.
  // Allocation-free when `out` already has one entry per model bar.
  void BarForceDensities(const ClassKWorkspace& ws, Eigen::VectorXd& out) const;

 private:
  friend class ClassKWorkspace;

  struct PackedBar {
    int oi, oj;            // coordinate offsets of the end nodes
    int ci, cj;            // copy indices of the ends, -1 for a pinned end
    int row;               // its row of A (after the fill-reducing order)
    bool fi, fj;           // whether the end's copy receives the node force (primary copy)
    double a00, a01, a11;  // inverse mass block (a00 unused for a pinned i, a11 for a pinned j)
    double w;              // (-1, 1) A_inv (-1, 1)^T over the free ends: A_kk = w |b|^2
    double rest_sq;        // l0^2
    int model_index;       // index in model.bars
  };
  struct Copy {
    int bar, end;  // owning packed bar and end (0 = i, 1 = j)
    int o;         // coordinate offset of its node
  };
  struct Coincidence {  // dim rows q_copy - q_primary
    int row;            // first of its dim rows in the natural order
    int copy, primary;
    int rows[3];  // its rows of A (after the fill-reducing order)
  };
  // Entries of A that depend on the state: value index `at` += coef x (b_d, or |b|^2 if d < 0).
  struct BarEntry {
    int at, bar, d;
    double coef;
  };
  friend class EngineFrame;  // dispatches to DerivativeImpl
  template <int D, bool Damped, bool Stabilised>
  void DerivativeImpl(double t, const double* y, double* dy, ClassKWorkspace& ws) const;
  // The constructor's bars with a free end, their copies (node_copies[a]: node a's, its primary
  // first) and their mass blocks.
  void PackBars(const DynamicModel& model, std::vector<std::vector<int>>& node_copies);

  int n_model_bars_ = 0, n_rows_ = 0;
  std::vector<PackedBar> bars_;
  std::vector<Copy> copies_;
  std::vector<Coincidence> coincidences_;
  std::vector<int> primary_copy_;  // per node: its primary copy, -1 without bars
  // Lower triangle of A in compressed columns (CHOLMOD's layout): column pointers, row
  // indices, the constant part of the values, and the state-dependent entries.
  std::vector<int> a_col_, a_row_;
  std::vector<double> a_const_;
  std::vector<BarEntry> a_bar_;
};

// Scratch of one ClassKSystem: node forces, per-copy vectors, the CHOLMOD matrix and factor.
// The constructor allocates everything, analyses A's pattern once and runs one evaluation at
// rest, in which CHOLMOD allocates the numeric factor and its work arrays; later evaluations
// refactorise into them and solve with the factor in place (tests/dynamics/classk_test.cc
// counts zero CHOLMOD allocations per step; cholmod_solve2 would allocate twice per call).
// Throws ModelError when CHOLMOD cannot analyse or factorise A at rest.
class ClassKWorkspace {
 public:
  explicit ClassKWorkspace(const ClassKSystem& system);
  ~ClassKWorkspace();
  ClassKWorkspace(const ClassKWorkspace&) = delete;
  ClassKWorkspace& operator=(const ClassKWorkspace&) = delete;

  Eigen::VectorXd force;          // non-bar node forces, packed [N]
  Eigen::VectorXd u;              // M^-1 F per copy, then the copy accelerations [m/s^2]
  Eigen::VectorXd jt_mu;          // J^T mu per copy [N]
  Eigen::VectorXd b;              // bar vectors, dim per packed bar [m]
  Eigen::VectorXd bar_length_sq;  // |b|^2 per packed bar [m^2]
  Eigen::VectorXd mu;             // right-hand side, then the multipliers, per row of A [N/m], [N]
  double damper_power = 0;        // the dampers' power at the last evaluation [W]
  // When set, the next evaluation writes each string's geometry there (one per model string)
  // and clears it.
  const StringGeometry* record_strings = nullptr;

  // Nonzeros of the factor L (with its diagonal); 0 without constraints.
  long factor_nonzeros() const;
  // Factorises A again at the values of the last evaluation, alone (for benchmarks).
  void Refactorise();

  struct Solver;  // CHOLMOD state (classk.cc)
  std::unique_ptr<Solver> solver;
};

inline ClassKWorkspace MakeWorkspace(const ClassKSystem& system) { return ClassKWorkspace(system); }

// Adapter to the integrators: owns the workspace (dynamics/engine_ode.h).
using ClassKOde = EngineOde<ClassKSystem, ClassKWorkspace>;

}  // namespace tbridge
