#include "export/truss_opensees.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/member_area.h"
#include "export/opensees.h"

namespace tbridge {

namespace {

std::string Num(double v) { return OpenSeesNumber(v); }

void Nodes(const TrussDesign& d, std::ostream& os) {
  const TrussModel& m = d.model;
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(m.nodes.cols());
  for (const StructureNodeMass& nm : d.config.structure->node_masses)
    mass[nm.node - 1] += nm.mass_kg;
  for (int v = 0; v < m.nodes.cols(); ++v) {
    os << "node " << v + 1 << " " << Num(m.nodes(0, v)) << " " << Num(m.nodes(1, v)) << " "
       << Num(m.nodes(2, v)) << "\n";
    const bool fixed = m.fixed[static_cast<size_t>(v)];
    // A planar structure moves in its own plane.
    if (fixed || m.dim == 2) os << "fix " << v + 1 << (fixed ? " 1 1 1\n" : " 0 0 1\n");
    if (!fixed && mass[v] > 0)
      os << "mass " << v + 1 << " " << Num(mass[v]) << " " << Num(mass[v]) << " " << Num(mass[v])
         << "\n";
  }
}

// Materials 2e - 1 (elastic) and 2e (its prestrain) of element e, 1-based.
void Members(const TrussDesign& d, bool corotational, std::ostream& os) {
  const TrussModel& m = d.model;
  const Eigen::VectorXd areas = d.check.Areas();
  for (int k = 0; k < m.num_members(); ++k) {
    const TrussMember& member = m.members[static_cast<size_t>(k)];
    const int e = k + 1;
    os << "uniaxialMaterial Elastic " << 2 * e - 1 << " " << Num(m.youngs_modulus) << "\n"
       << "uniaxialMaterial InitStrainMaterial " << 2 * e << " " << 2 * e - 1 << " "
       << Num(d.check.prestress[k] / (m.youngs_modulus * areas[k])) << "\n"
       << "element " << (corotational ? "corotTruss " : "truss ") << e << " " << member.i + 1 << " "
       << member.j + 1 << " " << Num(areas[k]) << " " << 2 * e << " -rho "
       << Num(MassOfArea(m.density, areas[k], 1.0)) << " -cMass 1\n";
  }
}

}  // namespace

void WriteTrussOpenSees(const TrussDesign& d, std::ostream& os) {
  const TrussModel& m = d.model;
  const Eigen::VectorXd areas = d.check.Areas();
  const bool linear = m.LinearAndUnstressed();
  os << "# tbridge export of a structure: " << m.nodes.cols() << " nodes, " << m.num_members()
     << " members; SI units (m, N, kg, s); " << (linear ? "linear" : "geometrically nonlinear")
     << " statics\n";
  os << "proc tbridge_model {} {\nmodel BasicBuilder -ndm 3 -ndf 3\n";
  Nodes(d, os);
  Members(d, !linear, os);
  os << "}\n";
  std::vector<OpenSeesRun> runs;
  double largest = d.check.prestress.size() ? d.check.prestress.cwiseAbs().maxCoeff() : 0.0;
  for (int c = 0; c < static_cast<int>(m.cases.size()); ++c) {
    const Eigen::VectorXd f = m.CaseLoads(c, areas);
    os << "# case " << c + 1 << "\nproc case_" << c + 1
       << " {tag} {\npattern Plain $tag Linear {\n";
    for (int v = 0; v < m.nodes.cols(); ++v) {
      Eigen::Vector3d load = Eigen::Vector3d::Zero();
      for (int a = 0; a < m.dim; ++a) {
        const int k = m.dof[static_cast<size_t>(v * m.dim + a)];
        if (k >= 0) load[a] = f[k];
      }
      if (load.isZero(0)) continue;
      os << "  load " << v + 1 << " " << Num(load[0]) << " " << Num(load[1]) << " " << Num(load[2])
         << "\n";
    }
    os << "}\n}\n";
    runs.push_back({"case_" + std::to_string(c + 1), m.cases[static_cast<size_t>(c)].name});
    largest = std::max(largest, f.size() ? f.cwiseAbs().maxCoeff() : 0.0);
  }
  std::vector<int> supports;
  for (int v = 0; v < m.nodes.cols(); ++v) {
    if (m.fixed[static_cast<size_t>(v)]) supports.push_back(v + 1);
  }
  WriteOpenSeesRuns(runs, static_cast<int>(m.nodes.cols()), supports, linear,
                    1e-9 * std::max(largest, 1.0), os);
}

}  // namespace tbridge
