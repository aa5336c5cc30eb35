#include "export/calculix.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <utility>

#include "core/member_area.h"

namespace tbridge {

std::string CalculixNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.13e", v + 0.0);
  return text;
}

namespace {

std::string Num(double v) { return CalculixNumber(v); }

// One element (1-based `id`) in its own set, so that it carries its own table.
void Spring(std::ostream& os, int id, int i, int j,
            const std::vector<std::pair<double, double>>& table) {
  os << "*ELEMENT, TYPE=SPRINGA, ELSET=E" << id << "\n"
     << id << ", " << i + 1 << ", " << j + 1 << "\n";
  os << "*SPRING, ELSET=E" << id << ", NONLINEAR\n";
  for (const auto& [elongation, force] : table) os << Num(force) << ", " << Num(elongation) << "\n";
}

void StaticStep(std::ostream& os, const std::string& label, const Eigen::Matrix3Xd& loads,
                const std::set<std::pair<int, int>>& loaded) {
  os << "**\n** tbridge step: " << label
     << "\n*STEP, NLGEOM, INC=10000\n*STATIC\n1., 1., 1e-8, 1.\n";
  // Every DOF loaded in any step, zero included: a load absent from a step would keep its
  // previous value.
  os << "*CLOAD\n";
  for (const auto& [v, a] : loaded)
    os << v + 1 << ", " << a + 1 << ", " << Num(loads(a, v)) << "\n";
  os << "*NODE PRINT, NSET=NODES\nU\n*NODE PRINT, NSET=SUPPORTS\nRF\n*END STEP\n";
}

// The strings and bars as springs, each with its own table.
void WriteSprings(const FeModel& fe, const CalculixOptions& options, std::ostream& os) {
  const Structure& s = fe.statics.structure;
  const int nb = s.num_bars(), ns = s.num_strings();
  // Strings: no force below the rest length, k past it; elongation from the drawn length s.
  for (int k = 0; k < ns; ++k) {
    const Member& m = s.strings[k];
    const double length = s.Length(m), stiffness = fe.statics.string_stiffness[k];
    const double slack = fe.statics.string_rest_length[k] - length;
    Spring(os, k + 1, m.i, m.j,
           {{-length, 0.0},
            {slack, 0.0},
            {length, stiffness * (2 * length - fe.statics.string_rest_length[k])}});
  }
  // Bars: their reference compression at the drawn length, linear about it: a pin-jointed bar of
  // axial stiffness E A / l, as tbridge has it. Not T3D2: CalculiX 2.20 expands a truss element
  // into a C3D8I brick of section sqrt(A) x sqrt(A), hinged to its end nodes by nonlinear
  // constraints. Measured on small prestressed models (the prestress as *INITIAL CONDITIONS,
  // TYPE=STRESS with E + C/A for its St. Venant-Kirchhoff law): the displacements agree to
  // 1e-10 under small loads, but the brick bends (its own modes come first, and under its
  // compression with negative eigenvalues; the bridge's modes 7-19 % high with its mass), a
  // support at a bar's end prints the bar's force alone as its reaction, and Newton stalls at
  // 1e-3 N on a chain of ten cells with the 1e-5 controls below. A spring with this table is
  // the corotational pin-jointed bar exactly, and agrees with tbridge to 1e-7.
  for (int b = 0; b < nb; ++b) {
    const Member& m = s.bars[b];
    const double length = s.Length(m);
    const double stiffness = AxialStiffness(fe.youngs_modulus, fe.bar_area[b], length) *
                             (options.rigid_bars ? kRigidBarFactor : 1.0);
    const double force = -fe.reference.bar_compression[b];
    Spring(os, ns + b + 1, m.i, m.j,
           {{-0.5 * length, force - 0.5 * length * stiffness},
            {0.5 * length, force + 0.5 * length * stiffness}});
  }
}

// Masses: node masses, and each bar's consistent mass through its midpoint.
void WriteMasses(const FeModel& fe, std::ostream& os) {
  const Structure& s = fe.statics.structure;
  const int nn = s.num_nodes(), nb = s.num_bars(), ns = s.num_strings();
  Eigen::VectorXd mass = fe.modal.node_mass;
  mass.conservativeResize(nn + nb);
  mass.tail(nb).setZero();
  for (int b = 0; b < nb; ++b) {
    const DynamicBar bar = fe.modal.bars[b];
    mass[bar.i] += bar.mass / 6;
    mass[bar.j] += bar.mass / 6;
    mass[nn + b] = 2 * bar.mass / 3;
  }
  int id = ns + nb;
  for (int v = 0; v < nn + nb; ++v) {
    if (mass[v] <= 0 || (v < nn && s.fixed[v])) continue;
    ++id;
    os << "*ELEMENT, TYPE=MASS, ELSET=E" << id << "\n"
       << id << ", " << v + 1 << "\n*MASS, ELSET=E" << id << "\n"
       << Num(mass[v]) << "\n";
  }
}

}  // namespace

void WriteCalculix(const FeModel& fe, const CalculixOptions& options, std::ostream& os) {
  const Structure& s = fe.statics.structure;
  const int nn = s.num_nodes(), nb = s.num_bars(), ns = s.num_strings();
  const int dim = s.dim();
  os << "** tbridge export: " << nn << " nodes, " << nb << " bars, " << ns
     << " strings; SI units (m, N, kg, s)\n";
  os << "** bars " << (options.rigid_bars ? "near-rigid" : "elastic") << "; nodes " << nn + 1 << "-"
     << nn + nb << " are the bars' midpoints, which carry mass only\n";
  os << "*NODE, NSET=NALL\n";
  for (int v = 0; v < nn; ++v) {
    os << v + 1 << ", " << Num(s.nodes(0, v)) << ", " << Num(s.nodes(1, v)) << ", "
       << Num(s.nodes(2, v)) << "\n";
  }
  for (int b = 0; b < nb; ++b) {
    const Eigen::Vector3d mid = 0.5 * (s.nodes.col(s.bars[b].i) + s.nodes.col(s.bars[b].j));
    os << nn + b + 1 << ", " << Num(mid(0)) << ", " << Num(mid(1)) << ", " << Num(mid(2)) << "\n";
  }
  os << "*NSET, NSET=NODES, GENERATE\n1, " << nn << ", 1\n*NSET, NSET=SUPPORTS\n";
  for (int v = 0; v < nn; ++v) {
    if (s.fixed[v]) os << v + 1 << ",\n";
  }

  WriteSprings(fe, options, os);

  WriteMasses(fe, os);
  os << "*EQUATION\n";
  for (int b = 0; b < nb; ++b) {
    for (int a = 0; a < dim; ++a) {
      os << "3\n"
         << nn + b + 1 << ", " << a + 1 << ", 1., " << s.bars[b].i + 1 << ", " << a + 1
         << ", -0.5, " << s.bars[b].j + 1 << ", " << a + 1 << ", -0.5\n";
    }
  }
  os << "*BOUNDARY\nSUPPORTS, 1, 3\n";
  if (dim == 2) os << "NALL, 3, 3\n";  // a planar bridge moves in its own plane
  // Residual and correction within 1e-5 of the average force and of the increment (defaults
  // 5e-3 and 1e-2). Tighter would not converge with rigid bars: their stiffness times the
  // rounding of the coordinates leaves up to 6e-6 of the average force (3D n = 2); Newton's
  // last step lands there, far below what the criterion allows.
  os << "*CONTROLS, PARAMETERS=FIELD\n1e-5, 1e-5, , , 1e-5\n";

  std::set<std::pair<int, int>> loaded;
  auto collect = [&](const Eigen::Matrix3Xd& loads) {
    for (int v = 0; v < nn; ++v) {
      for (int a = 0; a < dim; ++a) {
        if (loads(a, v) != 0) loaded.insert({v, a});
      }
    }
  };
  collect(fe.reference_loads);
  collect(fe.modal.loads);
  for (const FeLoadStep& c : fe.cases) collect(c.loads);

  StaticStep(os, "reference", fe.reference_loads, loaded);
  for (const FeLoadStep& c : fe.cases) {
    StaticStep(os, c.label, c.loads, loaded);
    StaticStep(os, "reference", fe.reference_loads, loaded);
  }
  StaticStep(os, "modes", fe.modal.loads, loaded);
  // CalculiX's Lanczos basis (ARPACK) is about four times the modes asked, and may not exceed
  // the motions that keep the bar lengths (planar n = 3: 21 motions, at most 5 modes).
  const int motions =
      static_cast<int>(std::count(s.fixed.begin(), s.fixed.end(), false)) * dim - nb;
  os << "**\n** tbridge step: frequency\n*STEP, PERTURBATION\n*FREQUENCY\n"
     << std::max(1, std::min(options.modes, motions / 4)) << "\n*END STEP\n";
}

}  // namespace tbridge
