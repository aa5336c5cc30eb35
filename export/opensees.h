// A design as an OpenSees Tcl script: the bridge tbridge analyses, for a second opinion from
// an FE program (README.md, "Export").
//
// Every member is a corotTruss on its own material. A string is `uniaxialMaterial Elastic`
// with zero compression modulus, wrapped in InitStrainMaterial for its prestrain: with the
// modulus E' = E s / L0 and the initial strain (s - L0) / s, where s is its drawn length and
// L0 its rest length, its force E' A (l - L0) / s is tbridge's k (l - L0), zero below L0. A bar
// is Elastic (E, or kRigidBarFactor E with rigid bars) with the initial strain of its reference
// compression. Masses: each bar's (string shares included) as its density per length with
// the consistent mass matrix, and the modal model's node masses. The model is a proc
// `tbridge_model`; the reference loads are a proc `reference TAG`, each load case (each travelling
// station its own) a proc `case_K TAG`, each defining its pattern of the case's whole load. The
// script then runs every one of them (WriteOpenSeesRuns).
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "export/fe_model.h"

namespace tbridge {

void WriteOpenSees(const FeModel& model, bool rigid_bars, std::ostream& os);

// A number as the scripts print it: 17 significant digits, the double read back exactly.
std::string OpenSeesNumber(double v);

// One analysis of an OpenSees script: the proc that defines its pattern (`NAME TAG`) and what it
// is, for the comment.
struct OpenSeesRun {
  std::string proc;
  std::string label;
};

// The analyses of a script whose model is the proc `tbridge_model`: for each run, the model built
// afresh (wipe), its pattern, recorders of every node's displacement (NAME.disp.out) and of the
// supports' reactions (NAME.reactions.out, `supports` 1-based), and a static analysis of the
// whole load at once from the drawn state, as the CalculiX deck's steps: one linear solve
// (`linear`), or Newton until the unbalance is within `tolerance_n` [N]. A run that does not
// converge is named on stderr and the script exits 1 after the others.
void WriteOpenSeesRuns(const std::vector<OpenSeesRun>& runs, int num_nodes,
                       const std::vector<int>& supports, bool linear, double tolerance_n,
                       std::ostream& os);

}  // namespace tbridge
