// A design read back from the JSON file `tbridge design` writes (design_report.h), so that
// its checks can be run again on the design as written (`tbridge check`).
//
// The file's `config` gives the topology, the deck, the actions and the load cases; its
// `members` give each member's area and, for strings, rest length, which define the
// structure (stiffness E A / L0, mass rho A l, self-weight), and its reference force. The
// file must be self-consistent: nodes and members as the config draws them, each string's
// tension k (s - L0) at the drawn geometry its reference force, and the reference forces in
// equilibrium with the reference loads; each member's length, radius, mass and (strings)
// stiffness what its nodes, area and rest length give (bars: stiffness null). An area edited
// without re-deriving the rest lengths and forces (tbridge design does that), or a radius,
// mass or stiffness edited at all, is refused with the member, the key and the mismatch.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "design/design.h"

namespace tbridge {

// Throws ConfigError naming the key ("members[4].rest_length", "nodes[2]", "config.bridge.n")
// for a file that is malformed, not a tbridge design, or not self-consistent.
Design ReadDesign(const nlohmann::json& file);

// `design` with its members' areas replaced by `areas` [m^2] (bars first, then strings, in
// the file's order), as an engineer edits the design file: each member's radius, mass and
// stiffness from its new area, the rest lengths kept; then read back by ReadDesign, which
// re-derives the reference state as built. Throws ConfigError naming the member and key for
// an area < 0 or not finite, or `areas` of the wrong size.
Design WithAreas(const Design& design, const std::vector<double>& areas);

}  // namespace tbridge
