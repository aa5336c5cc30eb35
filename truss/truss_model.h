// The constant model of a pin-jointed structure to design (the `structure` section's designable
// form, core/structure_config.h), resolved once from its config: nodes and their free degrees of
// freedom, members with their groups, the groups' limits, the factored load cases and the
// limits on displacements and frequencies. Every analysis and the sizing read it; nothing
// writes into it.
//
// Each member is elastic, E A / L, in the linear (small displacement) theory that the classic
// sizing problems assume; its kind says which sign of force it may carry. Where the prestress is
// variable, the member forces of the self-stress states (in equilibrium with no load) are
// variables beside the areas, and each analysis holds their geometric stiffness: a tensegrity
// is stiff against its infinitesimal mechanisms only through them.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/config.h"

namespace tbridge {

// The most members whose self-stress states are found (a dense SVD of the equilibrium matrix,
// O(members^3): 3000 take a few seconds here).
inline constexpr int kTrussMaxSelfStressMembers = 3000;

struct TrussGroup {
  std::string name;
  TrussKind kind = TrussKind::kTruss;
  double min_area = 0;  // [m^2]
  double max_area = 0;  // [m^2]; +inf: unbounded
  // The allowed stresses [Pa] (magnitudes); 0 where the kind carries no force of that sign.
  double allowed_tension = 0;
  double allowed_compression = 0;
  bool euler = false;        // the compression also held to the Euler load (solid round)
  std::vector<int> members;  // its members, by index
  double length_sum = 0;     // [m]: the group's mass is density x area x this
};

struct TrussMember {
  int i = 0, j = 0;  // 0-based end nodes
  int group = 0;
  double length = 0;          // [m]
  Eigen::Vector3d direction;  // unit, from node i to node j
};

struct TrussCase {
  std::string name;
  double factor = 1;
  Eigen::VectorXd loads;        // factored node forces on the free degrees of freedom [N]
  Eigen::Matrix3Xd node_loads;  // factored node forces on every node, supports included [N]
};

struct TrussDisplacementLimit {
  int node = 0;    // 0-based
  int axis = 1;    // 0 x, 1 y, 2 z
  int dof = 0;     // its free degree of freedom
  double max = 0;  // [m]
};

struct TrussModel {
  int dim = 2;              // 2: the x-y plane; 3
  Eigen::Matrix3Xd nodes;   // [m]
  std::vector<bool> fixed;  // per node: pinned
  std::vector<int> dof;     // per node and axis (node * dim + axis): free index, or -1
  int num_free = 0;
  std::vector<TrussMember> members;
  std::vector<TrussGroup> groups;
  std::vector<TrussCase> cases;
  std::vector<TrussDisplacementLimit> displacement_limits;
  std::vector<double> min_frequencies_hz;
  Eigen::VectorXd node_mass;   // per free degree of freedom [kg]: structure.node_masses
  double youngs_modulus = 0;   // [Pa]
  double density = 0;          // [kg/m^3]
  double gravity = 0;          // [m/s^2]; 0 where design.self_weight is off
  double buckling_factor = 1;  // design.buckling_safety_factor on the Euler load
  TrussAnalysisKind analysis = TrussAnalysisKind::kLinear;
  // Where structure.prestress is "variable": an orthonormal basis (members x states) of the
  // member forces in equilibrium with no load at every node, the supports' included (E t = 0):
  // the strings carry the prestress, no support does; no columns otherwise. The sizing's variables
  // are the group areas [m^2], then the amplitudes [N] of these states.
  Eigen::MatrixXd self_stress;

  int num_members() const { return static_cast<int>(members.size()); }
  int num_groups() const { return static_cast<int>(groups.size()); }
  int num_prestress() const { return static_cast<int>(self_stress.cols()); }
  int num_variables() const { return num_groups() + num_prestress(); }
  // Linear statics without prestress: an FE program reproduces it by a linear step; otherwise
  // its stiffness is partly the prestress's, or its statics nonlinear, and it needs
  // geometrically nonlinear steps (the CalculiX and OpenSees exports).
  bool LinearAndUnstressed() const {
    return analysis == TrussAnalysisKind::kLinear && num_prestress() == 0;
  }
  // Each member's prestress force [N] at the sizing's variables: zero without prestress.
  Eigen::VectorXd Prestress(const Eigen::VectorXd& variables) const;
  // The equilibrium matrix E (dim x nodes rows, node by node, x members): E t is the net force
  // on each node, supports included, of member forces t (tension > 0) [N].
  Eigen::MatrixXd Equilibrium() const;
  // The members' mass [kg] at the groups' areas (the first num_groups() entries of a sizing's
  // variables).
  double Mass(const Eigen::VectorXd& group_areas) const;
  // Each member's area from its group's (the same).
  Eigen::VectorXd MemberAreas(const Eigen::VectorXd& group_areas) const;
  // The members' mass [kg] at each member's own area.
  double MassOfMembers(const Eigen::VectorXd& member_areas) const;
  // Adds `area` times member e's weight per unit area to the load vector `f` on the free degrees
  // of freedom: half of its weight at each end, along -y; nothing without gravity.
  void AddWeight(int e, double area, Eigen::VectorXd& f) const;
  // Case c's load vector on the free degrees of freedom: its factored loads and the members'
  // factored weight at `member_areas`.
  Eigen::VectorXd CaseLoads(int c, const Eigen::VectorXd& member_areas) const;
  // The self-weight's load vector per unit area of group g, unfactored.
  Eigen::VectorXd WeightPerArea(int g) const;
  // Member e's Euler load at `area` [N]: pi^2 E I / L^2 of a solid round section, I = A^2 / (4 pi).
  double EulerLoad(int e, double area) const;
  // "i-j" with 1-based node numbers.
  std::string MemberName(int e) const;
};

// Throws ConfigError where the config is not a structure to design (structure.members).
TrussModel BuildTrussModel(const Config& config);

}  // namespace tbridge
