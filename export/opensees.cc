#include "export/opensees.h"

#include <cstdio>
#include <string>

#include "export/calculix.h"

namespace tbridge {

namespace {

std::string Num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v + 0.0);
  return text;
}

void Pattern(std::ostream& os, const std::string& tag, const Structure& s, const Eigen::Matrix3Xd& loads) {
  os << "pattern Plain " << tag << " Linear {\n";
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (s.fixed[v] || loads.col(v).isZero(0)) continue;
    os << "  load " << v + 1 << " " << Num(loads(0, v)) << " " << Num(loads(1, v)) << " " << Num(loads(2, v)) << "\n";
  }
  os << "}\n";
}

}  // namespace

void WriteOpenSees(const FeModel& fe, bool rigid_bars, std::ostream& os) {
  const Structure& s = fe.statics.structure;
  const int nn = s.num_nodes(), nb = s.num_bars(), ns = s.num_strings();
  os << "# tbridge export: " << nn << " nodes, " << nb << " bars, " << ns << " strings; SI units (m, N, kg, s)\n";
  os << "wipe\nmodel BasicBuilder -ndm 3 -ndf 3\n";
  for (int v = 0; v < nn; ++v) {
    os << "node " << v + 1 << " " << Num(s.nodes(0, v)) << " " << Num(s.nodes(1, v)) << " " << Num(s.nodes(2, v)) << "\n";
  }
  for (int v = 0; v < nn; ++v) {
    // A planar bridge moves in its own plane.
    if (s.fixed[v] || s.planar) os << "fix " << v + 1 << (s.fixed[v] ? " 1 1 1\n" : " 0 0 1\n");
    if (!s.fixed[v] && fe.modal.node_mass[v] > 0) {
      const std::string m = Num(fe.modal.node_mass[v]);
      os << "mass " << v + 1 << " " << m << " " << m << " " << m << "\n";
    }
  }
  // Materials 2e-1 and 2e (elastic law, its prestrained wrapper) for element e.
  for (int k = 0; k < ns; ++k) {
    const Member& m = s.strings[k];
    const double length = s.Length(m), rest = fe.statics.string_rest_length[k];
    const double modulus = fe.statics.string_stiffness[k] * length / fe.string_area[k];
    const int e = k + 1;
    os << "uniaxialMaterial Elastic " << 2 * e - 1 << " " << Num(modulus) << " 0.0 0.0\n";
    os << "uniaxialMaterial InitStrainMaterial " << 2 * e << " " << 2 * e - 1 << " " << Num((length - rest) / length) << "\n";
    os << "element corotTruss " << e << " " << m.i + 1 << " " << m.j + 1 << " " << Num(fe.string_area[k]) << " " << 2 * e
       << "\n";
  }
  for (int b = 0; b < nb; ++b) {
    const Member& m = s.bars[b];
    const double modulus = fe.youngs_modulus * (rigid_bars ? kRigidBarFactor : 1.0);
    const int e = ns + b + 1;
    os << "uniaxialMaterial Elastic " << 2 * e - 1 << " " << Num(modulus) << "\n";
    os << "uniaxialMaterial InitStrainMaterial " << 2 * e << " " << 2 * e - 1 << " "
       << Num(-fe.reference.bar_compression[b] / (modulus * fe.bar_area[b])) << "\n";
    os << "element corotTruss " << e << " " << m.i + 1 << " " << m.j + 1 << " " << Num(fe.bar_area[b]) << " " << 2 * e
       << " -rho " << Num(fe.modal.bars[b].mass / s.Length(m)) << " -cMass 1\n";
  }
  os << "# the reference state's loads\n";
  Pattern(os, "1", s, fe.reference_loads);
  for (size_t c = 0; c < fe.cases.size(); ++c) {
    os << "# " << fe.cases[c].label << "\nproc case_" << c + 1 << " {tag} {\n";
    Pattern(os, "$tag", s, fe.cases[c].loads);
    os << "}\n";
  }
}

}  // namespace tbridge
