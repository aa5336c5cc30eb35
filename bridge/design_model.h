// The dynamic model of a designed bridge: what a Design hands to dynamics/ (SPEC.md §8), its
// deck inertia, its starting equilibrium under the run's loads and what a prestrain implies.
#pragma once

#include <vector>

#include "design/design.h"
#include "dynamics/model.h"

namespace tbridge {

// The dynamic model of `design`, handed over directly:
// - bars: design mass and length; strings: design rest length, stiffness and area, mass
//   rho A L0 (SPEC.md §8);
// - kOnBars (eq 27): half of each string's mass goes to the bars at each end node, shared
//   equally among them and spread uniformly along each bar; the half at a node without bars
//   becomes a point mass there; kAtNodes: half of each string's mass is a point mass at each
//   end node; kOff: none. In every mode the share at a support is carried by the support
//   (pinned nodes get no mass);
// - prestrain: L0 = ratio x design length, k = E A / L0; the mass stays rho A L0 of the
//   design string (what SPEC.md §9's prestrained frequencies assume);
// - loads: the design's constant loads and options.payload_share of the payload (1: all of
//   it), each weight once (the members' own added when asked and the design did not count it);
// - dim 2 for planar designs (x-y), 3 otherwise; supports are the fixed nodes.
// Throws ConfigError for a prestrain group that names no string or a negative damping.
DynamicModel BuildDynamicModel(const Design& design, const ModelOptions& options = {});

// The model options of a config's modal analysis (`tbridge modes`): its "dynamics" section's,
// else the paper's model, with the deck's inertia unless the config keeps the paper's switches
// (its one load case).
ModelOptions ModalModelOptions(const Config& config);

// Adds the deck beams' mass (and the superimposed dead load's) at the deck nodes of a designed
// bridge, and `payload_factor` times the payload's: mass, not weight, which the loads carry.
// BuildDynamicModel's loads carry options.payload_share of the payload, and so does its mass.
void AddDeckInertia(DynamicModel& model, const Design& design, double payload_factor);

// Moves `model.positions` to the static equilibrium under `model.loads` (statics/), from the
// design's reference state; throws ModelError when there is none. A no-op when the loads are
// the design's own.
void SettleAtEquilibrium(DynamicModel& model, const Design& design);

// The implied stress of each prestrained group of `options` in `model` (built with them).
std::vector<PrestrainReport> ReportPrestrain(const DynamicModel& model, const Design& design,
                                             const ModelOptions& options);

}  // namespace tbridge
