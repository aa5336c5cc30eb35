// The constant dynamic model of a designed bridge (paper eqs 16-27, SPEC.md §8). Built once
// from a Design, then only read by the engines, integrators and modal analysis.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/design.h"

namespace tbridge {

// How string mass enters the dynamics (eq 27).
enum class StringMassMode {
  kOff,     // massless strings
  kOnBars,  // half of each string's mass goes to the bar at each end, spread uniformly (eq 27)
  kAtNodes  // half of each string's mass lumped at each end node
};

struct DynamicBar {
  int i = 0, j = 0;    // 0-based end nodes; bar vector b = n_j - n_i
  double mass = 0;     // bar mass plus its share of string mass (kOnBars) [kg]
  double length = 0;   // l, held constant [m]
};

struct DynamicString {
  int i = 0, j = 0;          // 0-based end nodes
  double rest_length = 0;    // L0 [m]
  double stiffness = 0;      // k = E A / L0 [N/m]
  double damping = 0;        // c [N s/m]; force density term c (s . s_dot) / s^2
  double mass = 0;           // rho A L0 [kg]
  std::string group;         // "deck", "substructure", "transverse"
  std::string name;          // "i-j", 1-based
};

struct DynamicModel {
  int dim = 2;                        // 2: motion in the x-y plane; 3: full 3D
  Eigen::Matrix3Xd positions;         // equilibrium node positions N0 (3 x n_n) [m]
  std::vector<bool> fixed;            // pinned nodes are prescribed, not integrated
  std::vector<DynamicBar> bars;
  std::vector<DynamicString> strings;
  Eigen::VectorXd node_mass;          // point masses at nodes [kg] (kAtNodes, free string nodes)
  Eigen::Matrix3Xd loads;             // constant external node loads W [N]
  double allowed_stress = 0;          // sigma_w [Pa], for stress reports
  double youngs_modulus = 0;          // E [Pa]
  std::vector<double> string_area;    // A per string [m^2], for stress reports
  int tensegrity_class = 1;           // max bars at a node

  int num_nodes() const { return static_cast<int>(positions.cols()); }
};

}  // namespace tbridge
