#include "design/topology.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace tbridge {

namespace {

void CheckParameters(int n, int p, double beta_deg, double span) {
  if (n < 1 || n > kMaxComplexity) {
    throw ConfigError("bridge.n", std::to_string(n),
                      "must be an integer in [1, " + std::to_string(kMaxComplexity) + "]");
  }
  if (p < 1 || p > kMaxBarsPerModule) {
    throw ConfigError("bridge.p", std::to_string(p),
                      "must be an integer in [1, " + std::to_string(kMaxBarsPerModule) + "]");
  }
  if (!(beta_deg > 0.0 && beta_deg < 90.0)) {
    throw ConfigError("bridge.beta_deg", NumberText(beta_deg), "must be in (0, 90)");
  }
  if (!(span > 0.0) || !std::isfinite(span)) {
    throw ConfigError("bridge.span", NumberText(span), "must be a positive number");
  }
}

}  // namespace

BridgeTopology PlanarSubstructure(int n, int p, double beta_deg, double span) {
  CheckParameters(n, p, beta_deg, span);
  // One generator serves every p: with p = 1 it builds SPEC.md §2's geometry and numbering.
  return PlanarMultiBar(n, p, beta_deg, span);
}

BridgeTopology MakeBridge(const BridgeConfig& c) {
  if (c.planes == 2) {
    if (c.p != 1) {
      throw ConfigError("bridge.p", std::to_string(c.p), "must be 1 when bridge.planes = 2");
    }
    CheckParameters(c.n, c.p, c.beta_deg, c.span);
    return CoupledBridge3D(c.n, c.beta_deg, c.span, c.deck_width);
  }
  return PlanarSubstructure(c.n, c.p, c.beta_deg, c.span);
}

}  // namespace tbridge
