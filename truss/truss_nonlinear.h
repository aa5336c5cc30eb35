// The geometrically nonlinear statics of a pin-jointed structure (structure.analysis
// "nonlinear"): large displacements, each member's force N = N0 + (E A / L)(l - L) at its current
// length l, along its current direction (L its drawn length, N0 its prestress), the loads dead
// (fixed in direction and size). Each member's law is linear in its elongation in either sign,
// as the linear analysis's is: a string whose force would fall below zero reads so, and its taut
// row fails, rather than going slack unseen.
//
// Newton's method on the full tangent K_T = sum k d d^T + (N / l)(I - d d^T), from the drawn
// (prestressed) state, in load steps: the whole load first, halved where a step's Newton fails.
// Derivatives in the sizing's variables by direct differentiation at the converged state:
// K_T du/dv = df/dv - dR/dv at fixed u, R the members' pull on the free nodes.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "truss/truss_analysis.h"
#include "truss/truss_model.h"

namespace tbridge {

class TrussNonlinearStatics {
 public:
  // `member_areas` and `prestress` (N0 per member, a self-stress; empty: none) as
  // TrussAnalysis takes them.
  TrussNonlinearStatics(const TrussModel& model, const Eigen::VectorXd& member_areas,
                        const Eigen::VectorXd& prestress = Eigen::VectorXd());

  // Case c's equilibrium; with `sensitivities`, its derivatives in the sizing's variables.
  // Throws ModelError naming the case and the load reached where Newton fails at the smallest
  // load step (a snap-through, or a mechanism the prestress does not hold).
  TrussCaseResponse Solve(int c, bool sensitivities) const;
  // The force member e exerts on its node i at the displacements u (on node j the opposite):
  // N d along its current direction.
  Eigen::Vector3d Pull(int e, const Eigen::VectorXd& u) const;

 private:
  // Member e's current unit direction and length at u.
  Eigen::Vector3d Direction(int e, const Eigen::VectorXd& u, double& length) const;
  double Force(int e, double length) const;
  // The load f plus every member's pull on the free nodes: zero at equilibrium.
  Eigen::VectorXd Residual(const Eigen::VectorXd& f, const Eigen::VectorXd& u) const;
  std::unique_ptr<TrussFactor> Tangent(const Eigen::VectorXd& u) const;
  // Newton from u towards equilibrium under f; false (u as it was) where it does not converge.
  bool Newton(const Eigen::VectorXd& f, Eigen::VectorXd& u) const;
  void Sensitivities(int c, TrussCaseResponse& r) const;

  const TrussModel& model_;
  Eigen::VectorXd areas_;      // per member
  Eigen::VectorXd prestress_;  // per member [N]
};

// Every case's response by the model's analysis: `linear`'s (about the prestressed state; it
// also gives the modes) or, for structure.analysis "nonlinear", the nonlinear one at the same
// member areas and prestress (`linear` may then be null).
std::vector<TrussCaseResponse> SolveTrussCases(const TrussModel& model, const TrussAnalysis* linear,
                                               const Eigen::VectorXd& member_areas,
                                               const Eigen::VectorXd& prestress,
                                               bool sensitivities);

}  // namespace tbridge
