#include "export/truss_calculix.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/member_area.h"
#include "export/calculix.h"

namespace tbridge {

namespace {

std::string Num(double v) { return CalculixNumber(v); }

// Each member a spring whose force is N0 + k e at elongation e (k = E A / L, N0 its prestress),
// in either sign, as tbridge's members are; in a geometrically nonlinear step CalculiX turns it
// with its chord, as tbridge's nonlinear statics does.
void Members(const TrussDesign& d, const Eigen::VectorXd& areas, std::ostream& os) {
  const TrussModel& m = d.model;
  for (int e = 0; e < m.num_members(); ++e) {
    const TrussMember& member = m.members[static_cast<size_t>(e)];
    const double k = AxialStiffness(m.youngs_modulus, areas[e], member.length),
                 half = 0.5 * member.length;
    const double n0 = d.check.prestress[e];
    os << "*ELEMENT, TYPE=SPRINGA, ELSET=E" << e + 1 << "\n"
       << e + 1 << ", " << member.i + 1 << ", " << member.j + 1 << "\n*SPRING, ELSET=E" << e + 1
       << ", NONLINEAR\n"
       << Num(n0 - k * half) << ", " << Num(-half) << "\n"
       << Num(n0 + k * half) << ", " << Num(half) << "\n";
  }
}

// The members' consistent mass through their midpoints (nodes nn + 1 ..), and the node masses.
void Masses(const TrussDesign& d, const Eigen::VectorXd& areas, std::ostream& os) {
  const TrussModel& m = d.model;
  const int nn = static_cast<int>(m.nodes.cols()), ne = m.num_members();
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(nn + ne);
  for (const StructureNodeMass& nm : d.config.structure->node_masses)
    mass[nm.node - 1] += nm.mass_kg;
  for (int e = 0; e < ne; ++e) {
    const TrussMember& member = m.members[static_cast<size_t>(e)];
    const double me = MassOfArea(m.density, areas[e], member.length);
    mass[member.i] += me / 6;
    mass[member.j] += me / 6;
    mass[nn + e] = 2 * me / 3;
  }
  int id = ne;
  for (int v = 0; v < nn + ne; ++v) {
    if (mass[v] <= 0 || (v < nn && m.fixed[static_cast<size_t>(v)])) continue;
    ++id;
    os << "*ELEMENT, TYPE=MASS, ELSET=E" << id << "\n"
       << id << ", " << v + 1 << "\n*MASS, ELSET=E" << id << "\n"
       << Num(mass[v]) << "\n";
  }
  os << "*EQUATION\n";
  for (int e = 0; e < ne; ++e) {
    const TrussMember& member = m.members[static_cast<size_t>(e)];
    for (int a = 0; a < m.dim; ++a) {
      os << "3\n"
         << nn + e + 1 << ", " << a + 1 << ", 1., " << member.i + 1 << ", " << a + 1 << ", -0.5, "
         << member.j + 1 << ", " << a + 1 << ", -0.5\n";
    }
  }
}

}  // namespace

void WriteTrussCalculix(const TrussDesign& d, int modes, std::ostream& os) {
  const TrussModel& m = d.model;
  const Eigen::VectorXd areas = d.check.Areas();
  const int nn = static_cast<int>(m.nodes.cols()), ne = m.num_members();
  os << "** tbridge export of a structure: " << nn << " nodes, " << ne
     << " members; SI units (m, N, kg, s)\n";
  os << "** nodes " << nn + 1 << "-" << nn + ne
     << " are the members' midpoints, which carry mass only\n";
  os << "*NODE, NSET=NALL\n";
  for (int v = 0; v < nn; ++v) {
    os << v + 1 << ", " << Num(m.nodes(0, v)) << ", " << Num(m.nodes(1, v)) << ", "
       << Num(m.nodes(2, v)) << "\n";
  }
  for (int e = 0; e < ne; ++e) {
    const TrussMember& member = m.members[static_cast<size_t>(e)];
    const Eigen::Vector3d mid = 0.5 * (m.nodes.col(member.i) + m.nodes.col(member.j));
    os << nn + e + 1 << ", " << Num(mid(0)) << ", " << Num(mid(1)) << ", " << Num(mid(2)) << "\n";
  }
  os << "*NSET, NSET=NODES, GENERATE\n1, " << nn << ", 1\n*NSET, NSET=SUPPORTS\n";
  for (int v = 0; v < nn; ++v) {
    if (m.fixed[static_cast<size_t>(v)]) os << v + 1 << ",\n";
  }
  Members(d, areas, os);
  Masses(d, areas, os);
  os << "*BOUNDARY\nSUPPORTS, 1, 3\n";
  if (m.dim == 2) os << "NALL, 3, 3\n";  // a planar structure moves in its own plane
  // A prestressed structure's stiffness is partly its prestress's, which CalculiX's linear step
  // leaves out (an infinitesimal mechanism is then singular): its steps are geometrically
  // nonlinear, as are a nonlinear design's. Equilibrium to 1e-9 of the average force (defaults
  // 5e-3 and 1e-2).
  const bool nlgeom = !m.LinearAndUnstressed();
  if (nlgeom) os << "*CONTROLS, PARAMETERS=FIELD\n1e-9, 1e-9, , , 1e-9\n";
  const std::string step =
      nlgeom ? "*STEP, NLGEOM, INC=1000\n*STATIC\n1., 1., 1e-6, 1.\n" : "*STEP\n*STATIC\n";
  for (int c = 0; c < static_cast<int>(m.cases.size()); ++c) {
    const Eigen::VectorXd f = m.CaseLoads(c, areas);
    os << "**\n** tbridge step: " << m.cases[static_cast<size_t>(c)].name << "\n"
       << step << "*CLOAD, OP=NEW\n";
    for (int v = 0; v < nn; ++v) {
      for (int a = 0; a < m.dim; ++a) {
        const int k = m.dof[static_cast<size_t>(v * m.dim + a)];
        if (k >= 0 && f[k] != 0) os << v + 1 << ", " << a + 1 << ", " << Num(f[k]) << "\n";
      }
    }
    os << "*NODE PRINT, NSET=NODES\nU\n*END STEP\n";
  }
  if (modes > 0 && !m.cases.empty()) {
    // Back to the unloaded structure: CalculiX's frequencies follow the last step's state, and
    // under the 10-bar truss's loads its first rises 0.085 %.
    int free_node = 0;
    while (m.fixed[static_cast<size_t>(free_node)]) ++free_node;
    os << "**\n** tbridge step: unloaded\n"
       << step << "*CLOAD, OP=NEW\n"
       << free_node + 1 << ", 1, 0.\n*END STEP\n";
  }
  if (modes > 0) {
    // ARPACK's basis is four times the modes asked and must stay below the free motions by more
    // than one: the 10-bar truss's 8 and the prism's 9 return zeros for 2 modes, their first
    // frequency for 1.
    os << "**\n** tbridge step: frequency\n*STEP" << (nlgeom ? ", PERTURBATION" : "")
       << "\n*FREQUENCY\n"
       << std::max(1, std::min(modes, (m.num_free - 2) / 4)) << "\n*END STEP\n";
  }
}

}  // namespace tbridge
