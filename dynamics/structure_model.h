// The dynamic model of a custom scene (the config's "structure" section), built directly from
// its nodes, bars and strings: no design, no material.
#pragma once

#include "core/structure_config.h"
#include "dynamics/model.h"

namespace tbridge {

// The model of `structure` (1-based node numbers become 0-based):
// - bars: their mass, length at the given node positions; strings: k, c, L0 (rest_length_m or
//   rest_ratio x length), mass, area (0 when not given: no stress reported), group "string";
// - string mass shared per options.string_mass exactly as for a designed bridge (eq 27 for
//   kOnBars), plus the configured node masses; loads: the constant structure loads, plus
//   the weight along -y (g = gravity_m_s2) when options.gravity_on_structure;
// - tensegrity class = most bars at one node; deck nodes and allowed stress as configured.
// Throws ConfigError naming the key for what only a designed bridge has (options.prestrain:
// "dynamics.prestrain"; options.damping != 0: "dynamics.damping_c", a structure gives c per
// string) and for a free node left without mass (no bar with mass, no node mass; with the
// shared string mass counted), which no engine can move.
DynamicModel BuildStructureModel(const StructureConfig& structure,
                                 const ModelOptions& options = {});

}  // namespace tbridge
