#include "core/error.h"
#include "design/topology.h"

namespace tbridge {

BridgeTopology CoupledBridge3D(int, double, double, double) {
  throw ConfigError("bridge.planes", "2", "only planes = 1 is available in this build");
}

}  // namespace tbridge
