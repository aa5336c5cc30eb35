// A bridge as built: its reference state re-derived from what its members are (their areas and
// rest lengths, the bars' lengths), where they are no longer what the design gave them: an edited
// design file (design_reader.h), a fabrication tolerance, a temperature (prestress_states.h).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/design.h"

namespace tbridge {

// The reference state the members carry as built, for a file whose members were edited (an
// area, with its radius, mass and stiffness, or a rest length): the strings keep their rest
// lengths and the bars their lengths, each member weighs what its area gives, and the state
// is the nonlinear static solve (statics/static_solve.h) from the file's geometry under the
// reference loads. A string's weight follows its length (rho A s), so the solve is repeated
// with the weight at the solved geometry until the loads change by less than 1e-12 of the
// largest (two or three solves: a string's length moves by its strain, ~1e-4). `bar_scale`
// makes every bar that much longer (a temperature): the model's geometry, from which the solve
// takes the bars' lengths, is scaled, while the supports stay where they are. `d.as_built` is
// this state's alone: `edited`, and the largest move of a node from `drawn` and change of a
// member's force. Throws ConfigError naming the edited members when the structure as built does
// not stand.
void SolveAsBuilt(Design& d, std::vector<std::string> edited, Eigen::Matrix3Xd drawn,
                  double bar_scale = 1.0);

// `design` with its strings' rest lengths shortened by `shortenings` [m] (one per string, in the
// file's order; negative: longer), each string's stiffness E A / L0 with it, as an engineer edits
// the design file, and the reference state re-derived as built (SolveAsBuilt; the strings changed
// are its `as_built.edited`). Throws ConfigError naming the key for a rest length that would not
// be positive, or `shortenings` of the wrong size.
Design WithRestLengths(const Design& design, const std::vector<double>& shortenings);

// `design` at a uniform temperature `delta_k` [K] from that at which it was built: each
// string's rest length and each bar's length longer by its material's thermal_expansion x
// delta_k, the supports where they are, and the reference state re-derived as built (as
// WithRestLengths). Throws ConfigError naming loads.temperature_delta_k where it does not stand.
Design WithTemperature(const Design& design, double delta_k);

}  // namespace tbridge
