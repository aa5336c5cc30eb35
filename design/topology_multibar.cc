#include "core/error.h"
#include "design/topology.h"

namespace tbridge {

BridgeTopology PlanarMultiBar(int, int p, double, double) {
  throw ConfigError("bridge.p", std::to_string(p), "only p = 1 is available in this build");
}

}  // namespace tbridge
