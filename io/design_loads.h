// The loads a design was sized for that `tbridge check` may change on the bridge as built: the
// payload, the superimposed dead load, the travelling load, the wind, the comfort class and the
// abutments' capacities. Every other key of the config draws or sizes the bridge itself (its
// topology, members, deck plates and rest lengths), so an edit of one is another design.
//
// The design file records them under "designed_for" beside "config"; check reads the bridge as
// designed (the deck plates sized for the loads recorded) and checks it under the config's.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/config.h"

namespace tbridge {

// {"bridge.payload": 12000, ..., "supports.vertical_capacity_n": null}: the load keys of
// `config` by their dotted names.
nlohmann::json DesignLoadsJson(const Config& config);

// `config` with the load keys `record` gives (DesignLoadsJson's form; a key absent keeps
// config's value). Throws ConfigError naming "designed_for.KEY" for a key that is not a load key
// or a value of the wrong type.
Config WithDesignLoads(const Config& config, const nlohmann::json& record);

// One phrase per load key whose value in `now` differs from `designed` ("bridge.payload 12000 ->
// 14400 N"), in DesignLoadsJson's order; empty when none.
std::vector<std::string> ChangedLoads(const Config& designed, const Config& now);

}  // namespace tbridge
