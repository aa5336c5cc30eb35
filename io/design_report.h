// Reports of a finished design: the JSON document written by `tbridge design` and a text
// summary for the terminal. Both read a Design and change nothing.
#pragma once

#include <iosfwd>
#include <string>

#include "design/design.h"

namespace tbridge {

// The design as JSON (field list and units in README.md, "Reading a design"):
//   config                 resolved config, every default filled in (ToJson(Config))
//   topology               {n, p, beta_deg, planes, nodes, bars, strings, class, fixed_nodes}
//   deck                   {section_length, section_mass, thickness, node_load, total_load,
//                           beams_mass}
//   nodes                  [[x, y, z], ...]; node k (1-based) is entry k-1  [m]
//   members                bars first, then strings, in structure order; each
//                          {name, type, nodes [i, j] 1-based, length, force, force_density,
//                           area, radius, mass, rest_length, stiffness, governed_by, stress}.
//                          force is a magnitude (tension for strings, compression for bars);
//                          stiffness is null for bars (rigid).
//   mass                   {bars, strings, deck_strings, deck_beams, structure, total}  [kg]
//   solver                 {name, status, iterations}
//   equilibrium_residual_N largest node-force imbalance over the free DOFs  [N]
//   self_stress_states     n_b + n_s - rank(A)
//   stability              {stable, method, negative_pivots, zero_pivots, free_dofs, reduced_dofs,
//                           min_pivot [N/m], critical_load_factor (null: none or not computed),
//                           critical_load_factor_computed} (design/stability.h)
//   reactions              [{case, node (1-based), force [x, y, z] [N]}, ...]: per case
//                          (the reference state, then each statically solved case) and support
//   cases, deflection_max, dynamic_check, resizing, self_weight_iterations, utilisation_max,
//   verdict                the load cases and the checks (design/verification.h); members
//                          also carry force_min, reference_force, utilisation,
//                          governing_case and mode
//   units                  the unit of every numeric field above ("1" = dimensionless)
// Keys are in alphabetical order; nodes and members are written one per line as they are
// read from the design, so no copy of the document is held. Numbers are the shortest text
// that reads back to the same double. Non-finite numbers cannot occur in a Design that
// RunDesign returned; they would be written as null. Stream errors are the caller's to check.
void WriteDesignJson(const Design& design, std::ostream& os);

// Multi-line text: parameters, topology counts, deck, solver, a member table in the style of
// the paper's Tables 2-4 (r in mm, L0, k_s, m, governing mode) and the mass breakdown. At
// most `max_member_rows` members are listed; the rest are counted as omitted.
std::string DesignSummary(const Design& design, int max_member_rows = 30);

}  // namespace tbridge
