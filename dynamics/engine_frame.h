// What the class-1 and class-k engines compile from a model alike: the checks of its sizes and
// options, the loads and strings, the rest positions, the free nodes without a bar, the pinned
// coordinates and the mass blocks that give the kinetic energy. Each engine adds its bars.
#pragma once

#include <Eigen/Core>
#include <cstring>
#include <string>
#include <vector>

#include "dynamics/engine_ode.h"
#include "dynamics/model.h"
#include "dynamics/node_forces.h"

namespace tbridge {

// Stabilisation of the bar lengths (paper eqs 24-26, SPEC.md §8), the same for both engines.
struct EngineOptions {
  bool stabilisation = false;
  double omega_rad_s = 100.0;  // corrective frequency omega [rad/s]
  double zeta = 1.0;           // corrective damping ratio [-]
};

class EngineFrame {
 public:
  int dim() const { return dim_; }
  int num_nodes() const { return n_n_; }
  int coordinates() const { return dim_ * n_n_; }
  int state_size() const { return 2 * coordinates(); }
  bool damped() const { return damped_; }
  bool stabilised() const { return options_.stabilisation; }

  // The model's positions, at rest.
  Eigen::VectorXd RestState() const;
  // Kinetic energy of the state [J]: every bar's mass block, then the lone point masses.
  double KineticEnergy(const double* y) const;
  // External node loads at time t, packed like the positions [N].
  void LoadsAt(double t, double* force) const { loads_.At(t, force); }
  // Whether any timed load exists (else loads are constant).
  bool has_timed_loads() const { return loads_.has_timed(); }

 protected:
  // Throws ModelError naming `engine` when the model fails CheckModel (dynamics/model.h),
  // stabilisation has omega <= 0 or zeta < 0, or a timed load names a node out of range.
  EngineFrame(const DynamicModel& model, const EngineOptions& options,
              const std::vector<TimedLoad>& timed, const char* engine);

  // Once the bars are known (`has_bar[a]`: a bar ends at node a): pinned nodes are held, and
  // free nodes without a bar move as point masses. Throws ModelError for such a node without mass.
  void AddNodes(const DynamicModel& model, const std::vector<bool>& has_bar);
  // The bar's mass block on the velocities at offsets oi, oj (-1: a pinned end, no term).
  void AddMassBlock(int oi, int oj, double m00, double m01, double m11) {
    if (oi >= 0 && oj >= 0) {
      blocks_.push_back({oi, oj, m00, 2.0 * m01, m11});
    } else if (oi >= 0 || oj >= 0) {
      block_ends_.push_back({oi >= 0 ? oi : oj, oi >= 0 ? m00 : m11});
    }
  }
  double NodeMass(int a) const { return node_mass_.size() != 0 ? node_mass_(a) : 0.0; }
  std::string Where() const { return engine_; }

  // dy = f(t, y) by `self.DerivativeImpl<D, Damped, Stabilised>`, with the dimension, damping
  // and stabilisation as constants (Specialise): one dispatch per evaluation.
  template <class Self, class Workspace>
  void Evaluate(const Self& self, double t, const double* y, double* dy, Workspace& ws) const {
    Specialise(dim_, damped_, options_.stabilisation, [&]<int D, bool Damped, bool Stabilised>() {
      self.template DerivativeImpl<D, Damped, Stabilised>(t, y, dy, ws);
    });
  }

  // The start of every evaluation: x' = v into dy, then the non-bar forces into f (loads at t
  // and the strings' pulls). Returns the dampers' power [W]. With `record`, each string's
  // geometry at y goes there too, by model string. CAUTION: performance-sensitive.
  template <int D, bool Damped>
  double StartDerivative(double t, const double* y, double* dy, double* f,
                         const StringGeometry* record) const {
    const int c = coordinates();
    std::memcpy(dy, y + c, sizeof(double) * static_cast<size_t>(c));
    loads_.At(t, f);
    return record != nullptr
               ? AccumulateStringForces<D, Damped, true>(strings_, y, y + c, f, record)
               : AccumulateStringForces<D, Damped>(strings_, y, y + c, f);
  }

  // Mass-proportional damping (DynamicModel::mass_damping_per_s): the force -alpha M v takes
  // alpha v off every acceleration. The bar forces need no change: the force's share along a
  // bar is -alpha m (b . b_dot) / l, zero while its length is held. Returns its power
  // alpha v^T M v = 2 alpha (kinetic energy) [W]; 0 without it. Call after FinishDerivative
  // (pinned coordinates have no velocity, so they stay at rest).
  template <int D>
  double MassDamping(const double* y, double* dy) const {
    if (mass_damping_ == 0.0) return 0.0;
    const int c = coordinates();
    for (int i = 0; i < c; ++i) dy[c + i] -= mass_damping_ * y[c + i];
    return 2.0 * mass_damping_ * KineticEnergy(y);
  }

  // The end of every evaluation: the lone nodes' accelerations F / m, and zero rate for the
  // pinned coordinates. CAUTION: performance-sensitive.
  template <int D>
  void FinishDerivative(const double* f, double* dy) const {
    double* acc = dy + coordinates();
    for (const LoneNode& n : lone_) {
      for (int d = 0; d < D; ++d) acc[n.o + d] = f[n.o + d] * n.inv_mass;
    }
    for (const int o : fixed_offsets_) {
      for (int d = 0; d < D; ++d) {
        acc[o + d] = 0;
        dy[o + d] = 0;
      }
    }
  }

  const char* engine_;
  int dim_ = 2, n_n_ = 0;
  bool damped_ = false;
  double mass_damping_ = 0;  // alpha [1/s]
  EngineOptions options_;
  NodeLoads loads_;
  std::vector<PackedString> strings_;

 private:
  struct LoneNode {
    int o;
    double mass, inv_mass;
  };
  // A bar's mass block with both ends free: its kinetic energy is
  // (m00 |v_i|^2 + 2 m01 v_i . v_j + m11 |v_j|^2) / 2.
  struct MassBlock {
    int oi, oj;
    double m00, two_m01, m11;
  };
  // The free end of a bar pinned at the other (mass m11 or m00 of its block).
  struct MassEnd {
    int o;
    double mass;
  };
  Eigen::VectorXd rest_positions_;  // packed
  Eigen::VectorXd node_mass_;
  std::vector<LoneNode> lone_;
  Eigen::VectorXd lone_mass_;  // per coordinate: its lone node's mass [kg], 0 for the others;
                               // empty when bars hold most coordinates
  std::vector<int> fixed_offsets_;
  std::vector<MassBlock> blocks_;  // kept apart from the ends, so that neither loop branches
  std::vector<MassEnd> block_ends_;

  template <int Dim>
  double KineticEnergyOf(const double* y) const;
};

}  // namespace tbridge
