// The comfort check's part of a design's outputs: the design JSON's `comfort` section and the
// summary's comfort lines (checks/comfort_check.h fills the report they read).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "design/design.h"

namespace tbridge {

// `comfort`: status, required, traffic_class, comfort_level, damping_ratio, the crowd, the
// comfort class reached, `modes[]` (direction, frequency_hz, modal_mass_kg, range,
// acceleration_m_s2, limit_m_s2, with the load model and its numbers) and pass.
nlohmann::json ComfortJson(const Design& design);
// The units of its numeric fields.
nlohmann::json ComfortUnits();

// One line for the check, then one per relevant mode.
std::vector<std::string> ComfortSummaryLines(const Design& design);

// The worst Sétra comfort level the modes reach ("maximum" ... "unacceptable"; "maximum" when
// no mode is relevant).
std::string ComfortClassReached(const ComfortCheck& check);

}  // namespace tbridge
