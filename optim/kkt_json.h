// A certificate of local optimality (kkt_certificate.h) as the design files write it: the
// bridge's `solver.kkt` and a structure's alike, from one writer.
#pragma once

#include <nlohmann/json.hpp>

#include "optim/kkt_certificate.h"

namespace tbridge {

// Its measures, tests and counts; not its multipliers (the design's mass attribution reads
// those).
nlohmann::json KktJson(const KktCertificate& k);

}  // namespace tbridge
