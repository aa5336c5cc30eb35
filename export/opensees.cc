#include "export/opensees.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "export/calculix.h"

namespace tbridge {

std::string OpenSeesNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v + 0.0);
  return text;
}

namespace {

std::string Num(double v) { return OpenSeesNumber(v); }

void Pattern(std::ostream& os, const std::string& tag, const Structure& s,
             const Eigen::Matrix3Xd& loads) {
  os << "pattern Plain " << tag << " Linear {\n";
  for (int v = 0; v < s.num_nodes(); ++v) {
    if (s.fixed[v] || loads.col(v).isZero(0)) continue;
    os << "  load " << v + 1 << " " << Num(loads(0, v)) << " " << Num(loads(1, v)) << " "
       << Num(loads(2, v)) << "\n";
  }
  os << "}\n";
}

}  // namespace

namespace {

// `text` as a Tcl word in braces and a comment: no brace, backslash or line break.
std::string TclText(std::string text) {
  for (char& ch : text) {
    if (ch == '{' || ch == '}' || ch == '\\' || ch == '\n' || ch == '\r') ch = '_';
  }
  return text;
}

}  // namespace

void WriteOpenSeesRuns(const std::vector<OpenSeesRun>& runs, int num_nodes,
                       const std::vector<int>& supports, bool linear, double tolerance_n,
                       std::ostream& os) {
  os << "# each analysis from the drawn state: the model afresh, the whole load at once\n"
        "set tbridge_failed {}\n"
        "proc tbridge_run {name label} {\n"
        "  global tbridge_failed\n"
        "  wipe\n  tbridge_model\n  $name 1\n"
        "  recorder Node -file $name.disp.out -time -nodeRange 1 "
     << num_nodes << " -dof 1 2 3 disp\n";
  if (!supports.empty()) {
    os << "  recorder Node -file $name.reactions.out -time -node";
    for (const int v : supports) os << " " << v;
    os << " -dof 1 2 3 reaction\n";
  }
  os << "  constraints Plain\n  numberer RCM\n";
  if (linear) {
    os << "  system BandSPD\n  test NormUnbalance " << Num(tolerance_n) << " 1\n"
       << "  algorithm Linear\n";
  } else {
    os << "  system BandGeneral\n  test NormUnbalance " << Num(tolerance_n) << " 100\n"
       << "  algorithm Newton\n";
  }
  os << "  integrator LoadControl 1.0\n  analysis Static\n"
        "  if {[analyze 1] != 0} {\n"
        "    puts stderr \"tbridge: $label ($name) did not converge\"\n"
        "    lappend tbridge_failed $name\n  }\n"
        "  wipe\n}\n";
  for (const OpenSeesRun& r : runs)
    os << "tbridge_run " << r.proc << " {" << TclText(r.label) << "}\n";
  os << "if {[llength $tbridge_failed] > 0} { exit 1 }\n";
}

void WriteOpenSees(const FeModel& fe, bool rigid_bars, std::ostream& os) {
  const Structure& s = fe.statics.structure;
  const int nn = s.num_nodes(), nb = s.num_bars(), ns = s.num_strings();
  os << "# tbridge export: " << nn << " nodes, " << nb << " bars, " << ns
     << " strings; SI units (m, N, kg, s)\n";
  os << "proc tbridge_model {} {\nmodel BasicBuilder -ndm 3 -ndf 3\n";
  for (int v = 0; v < nn; ++v) {
    os << "node " << v + 1 << " " << Num(s.nodes(0, v)) << " " << Num(s.nodes(1, v)) << " "
       << Num(s.nodes(2, v)) << "\n";
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
    os << "uniaxialMaterial InitStrainMaterial " << 2 * e << " " << 2 * e - 1 << " "
       << Num((length - rest) / length) << "\n";
    os << "element corotTruss " << e << " " << m.i + 1 << " " << m.j + 1 << " "
       << Num(fe.string_area[k]) << " " << 2 * e << "\n";
  }
  for (int b = 0; b < nb; ++b) {
    const Member& m = s.bars[b];
    const double modulus = fe.youngs_modulus * (rigid_bars ? kRigidBarFactor : 1.0);
    const int e = ns + b + 1;
    os << "uniaxialMaterial Elastic " << 2 * e - 1 << " " << Num(modulus) << "\n";
    os << "uniaxialMaterial InitStrainMaterial " << 2 * e << " " << 2 * e - 1 << " "
       << Num(-fe.reference.bar_compression[b] / (modulus * fe.bar_area[b])) << "\n";
    os << "element corotTruss " << e << " " << m.i + 1 << " " << m.j + 1 << " "
       << Num(fe.bar_area[b]) << " " << 2 * e << " -rho "
       << Num(fe.modal.bars[b].mass / s.Length(m)) << " -cMass 1\n";
  }
  os << "}\n# the reference state's loads\nproc reference {tag} {\n";
  Pattern(os, "$tag", s, fe.reference_loads);
  os << "}\n";
  std::vector<OpenSeesRun> runs{{"reference", "the reference state"}};
  double largest = fe.reference_loads.cwiseAbs().maxCoeff();
  for (size_t c = 0; c < fe.cases.size(); ++c) {
    os << "# " << TclText(fe.cases[c].label) << "\nproc case_" << c + 1 << " {tag} {\n";
    Pattern(os, "$tag", s, fe.cases[c].loads);
    os << "}\n";
    runs.push_back({"case_" + std::to_string(c + 1), fe.cases[c].label});
    largest = std::max(largest, fe.cases[c].loads.cwiseAbs().maxCoeff());
  }
  std::vector<int> supports;
  for (int v = 0; v < nn; ++v) {
    if (s.fixed[v]) supports.push_back(v + 1);
  }
  // Newton to 1e-9 of the largest load, as the CalculiX deck's residual control.
  WriteOpenSeesRuns(runs, nn, supports, false, 1e-9 * std::max(largest, 1.0), os);
}

}  // namespace tbridge
