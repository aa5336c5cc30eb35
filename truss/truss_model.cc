#include "truss/truss_model.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "core/member_area.h"

namespace tbridge {

namespace {

TrussGroup GroupOf(const StructureGroupConfig& g) {
  TrussGroup out;
  out.name = g.name;
  out.kind = g.kind;
  out.min_area = g.min_area_m2;
  out.max_area = g.max_area_m2 ? *g.max_area_m2 : std::numeric_limits<double>::infinity();
  out.allowed_tension = g.allowed_tension_pa.value_or(0.0);
  out.allowed_compression = g.allowed_compression_pa.value_or(0.0);
  out.euler = g.buckling == BucklingRule::kEuler ||
              (g.buckling == BucklingRule::kAuto && out.kind == TrussKind::kBar);
  return out;
}

// The free degrees of freedom, node by node and axis by axis.
void NumberDofs(const StructureConfig& s, TrussModel& m) {
  const int nn = static_cast<int>(s.nodes.size());
  m.nodes.resize(3, nn);
  m.fixed.assign(static_cast<size_t>(nn), false);
  for (int k = 0; k < nn; ++k) {
    for (int a = 0; a < 3; ++a)
      m.nodes(a, k) = s.nodes[static_cast<size_t>(k)][static_cast<size_t>(a)];
  }
  for (const int p : s.pinned) m.fixed[static_cast<size_t>(p - 1)] = true;
  m.dof.assign(static_cast<size_t>(nn * m.dim), -1);
  for (int k = 0; k < nn; ++k) {
    for (int a = 0; a < m.dim && !m.fixed[static_cast<size_t>(k)]; ++a) {
      m.dof[static_cast<size_t>(k * m.dim + a)] = m.num_free++;
    }
  }
}

// An orthonormal basis of the self-stress states: the null space of the equilibrium matrix.
Eigen::MatrixXd SelfStressStates(const TrussModel& m) {
  if (m.num_members() > kTrussMaxSelfStressMembers) {
    throw ConfigError("structure.prestress", "\"variable\"",
                      "\"none\" for a structure of " + std::to_string(m.num_members()) +
                          " members: the self-stress states are found for at most " +
                          std::to_string(kTrussMaxSelfStressMembers));
  }
  const Eigen::MatrixXd e = m.Equilibrium();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(e, Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  // A singular value this far below the largest is round-off of a zero one (the equilibrium
  // matrix's entries are direction cosines, of order 1).
  const double tiny = 1e-10 * std::max(1.0, sv.size() ? sv[0] : 0.0) * std::sqrt(e.rows());
  int rank = 0;
  while (rank < sv.size() && sv[rank] > tiny) ++rank;
  const Eigen::MatrixXd states = svd.matrixV().rightCols(m.num_members() - rank);
  if (states.cols() == 0) {
    throw ConfigError("structure.prestress", "\"variable\"",
                      "\"none\": the structure has no self-stress state (no member forces are "
                      "in equilibrium among themselves without load or support; add members that "
                      "close a prestressable circuit)");
  }
  return states;
}

}  // namespace

TrussModel BuildTrussModel(const Config& config) {
  if (!config.structure || !config.structure->Designable()) {
    throw ConfigError("structure.members", "(missing)",
                      "`tbridge design` designs a \"bridge\" or a structure's members in groups "
                      "(configs/README.md); "
                      "a scene of bars and strings is for simulate and modes");
  }
  const StructureConfig& s = *config.structure;
  TrussModel m;
  m.dim = s.dim;
  NumberDofs(s, m);
  m.youngs_modulus = config.material.youngs_modulus;
  m.density = config.material.density;
  m.gravity = config.design.self_weight ? config.design.gravity : 0.0;
  m.buckling_factor = config.design.buckling_safety_factor;
  for (const StructureGroupConfig& g : s.groups) m.groups.push_back(GroupOf(g));
  for (const StructureMemberConfig& c : s.members) {
    TrussMember e;
    e.i = c.nodes[0] - 1;
    e.j = c.nodes[1] - 1;
    for (int g = 0; g < m.num_groups(); ++g) {
      if (m.groups[static_cast<size_t>(g)].name == c.group) e.group = g;
    }
    const Eigen::Vector3d d = m.nodes.col(e.j) - m.nodes.col(e.i);
    e.length = d.norm();
    e.direction = d / e.length;
    TrussGroup& group = m.groups[static_cast<size_t>(e.group)];
    group.members.push_back(m.num_members());
    group.length_sum += e.length;
    m.members.push_back(e);
  }
  m.node_mass = Eigen::VectorXd::Zero(m.num_free);
  for (const StructureNodeMass& nm : s.node_masses) {
    for (int a = 0; a < m.dim; ++a) {
      const int f = m.dof[static_cast<size_t>((nm.node - 1) * m.dim + a)];
      if (f >= 0) m.node_mass[f] += nm.mass_kg;
    }
  }
  for (const StructureLoadCase& c : s.load_cases) {
    TrussCase tc{c.name, c.factor, Eigen::VectorXd::Zero(m.num_free),
                 Eigen::Matrix3Xd::Zero(3, m.nodes.cols())};
    for (const StructureLoad& l : c.loads) {
      for (int a = 0; a < 3; ++a)
        tc.node_loads(a, l.node - 1) += c.factor * l.force_n[static_cast<size_t>(a)];
      for (int a = 0; a < m.dim; ++a) {
        const int f = m.dof[static_cast<size_t>((l.node - 1) * m.dim + a)];
        // A load on a support goes straight into it: it moves nothing and stresses no member.
        if (f >= 0) tc.loads[f] += c.factor * l.force_n[static_cast<size_t>(a)];
      }
    }
    m.cases.push_back(std::move(tc));
  }
  for (const StructureDisplacementLimit& d : s.limits.displacements) {
    TrussDisplacementLimit limit{d.node - 1, static_cast<int>(d.axis), 0, d.max_m};
    limit.dof = m.dof[static_cast<size_t>(limit.node * m.dim + limit.axis)];
    m.displacement_limits.push_back(limit);
  }
  m.min_frequencies_hz = s.limits.min_frequencies_hz;
  if (s.prestress == StructurePrestress::kVariable) m.self_stress = SelfStressStates(m);
  m.analysis = s.analysis;
  return m;
}

Eigen::VectorXd TrussModel::Prestress(const Eigen::VectorXd& variables) const {
  if (num_prestress() == 0) return Eigen::VectorXd::Zero(num_members());
  return self_stress * variables.tail(num_prestress());
}

Eigen::MatrixXd TrussModel::Equilibrium() const {
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(dim * nodes.cols(), num_members());
  for (int k = 0; k < num_members(); ++k) {
    const TrussMember& m = members[static_cast<size_t>(k)];
    for (int a = 0; a < dim; ++a) {
      // A tension pulls node i towards j, and j towards i.
      e(m.i * dim + a, k) += m.direction[a];
      e(m.j * dim + a, k) -= m.direction[a];
    }
  }
  return e;
}

double TrussModel::Mass(const Eigen::VectorXd& group_areas) const {
  double mass = 0;
  for (int g = 0; g < num_groups(); ++g)
    mass += MassOfArea(density, group_areas[g], groups[static_cast<size_t>(g)].length_sum);
  return mass;
}

Eigen::VectorXd TrussModel::MemberAreas(const Eigen::VectorXd& group_areas) const {
  Eigen::VectorXd a(num_members());
  for (int e = 0; e < num_members(); ++e) a[e] = group_areas[members[static_cast<size_t>(e)].group];
  return a;
}

double TrussModel::MassOfMembers(const Eigen::VectorXd& member_areas) const {
  double mass = 0;
  for (int e = 0; e < num_members(); ++e)
    mass += MassOfArea(density, member_areas[e], members[static_cast<size_t>(e)].length);
  return mass;
}

void TrussModel::AddWeight(int e, double area, Eigen::VectorXd& f) const {
  if (gravity == 0) return;
  const TrussMember& m = members[static_cast<size_t>(e)];
  const double half = 0.5 * density * gravity * m.length * area;
  for (const int node : {m.i, m.j}) {
    const int k = dof[static_cast<size_t>(node * dim + 1)];
    if (k >= 0) f[k] -= half;
  }
}

Eigen::VectorXd TrussModel::CaseLoads(int c, const Eigen::VectorXd& member_areas) const {
  const TrussCase& lc = cases[static_cast<size_t>(c)];
  Eigen::VectorXd f = lc.loads;
  for (int e = 0; e < num_members(); ++e) AddWeight(e, lc.factor * member_areas[e], f);
  return f;
}

Eigen::VectorXd TrussModel::WeightPerArea(int g) const {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(num_free);
  for (const int e : groups[static_cast<size_t>(g)].members) AddWeight(e, 1.0, w);
  return w;
}

double TrussModel::EulerLoad(int e, double area) const {
  const double length = members[static_cast<size_t>(e)].length;
  return std::numbers::pi * youngs_modulus * area * area / (4 * length * length);
}

std::string TrussModel::MemberName(int e) const {
  const TrussMember& m = members[static_cast<size_t>(e)];
  return std::to_string(m.i + 1) + "-" + std::to_string(m.j + 1);
}

}  // namespace tbridge
