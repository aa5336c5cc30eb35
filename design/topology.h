// Parametric tensegrity bridge topologies (paper Sect. 4, SPEC.md §2).
#pragma once

#include <vector>

#include "core/config.h"
#include "core/structure.h"

namespace tbridge {

// A generated bridge: the structure plus what the loads and reports need to know about it.
struct BridgeTopology {
  Structure structure;
  // Free deck nodes that carry the deck load, 0-based, in order of x (plane by plane).
  std::vector<int> deck_nodes;
  int planes = 1;
  // Deck stations per plane that carry load: 2^n - 1.
  int loaded_stations = 0;
};

// Planar substructure bridge (n, p, beta) in the x-y plane, deck at y = 0, supports at x = 0
// and x = span. p = 1 follows SPEC.md §2 exactly (numbering included). Throws ConfigError
// for parameters out of range.
BridgeTopology PlanarSubstructure(int n, int p, double beta_deg, double span);

// Planar bridge with p >= 2 bars per module (class k): called by PlanarSubstructure.
BridgeTopology PlanarMultiBar(int n, int p, double beta_deg, double span);

// 3D bridge: two planar modules (n, p = 1) at z = 0 and z = deck_width, coupled by transverse
// bars and strings into a class-2 tensegrity (paper Sect. 7.3).
BridgeTopology CoupledBridge3D(int n, double beta_deg, double span, double deck_width);

// Dispatches on config.planes.
BridgeTopology MakeBridge(const BridgeConfig& config);

}  // namespace tbridge
