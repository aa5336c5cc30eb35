#include "optim/kkt_json.h"

namespace tbridge {

nlohmann::json KktJson(const KktCertificate& k) {
  return {{"stationarity", k.stationarity},
          {"feasibility", k.feasibility},
          {"complementarity", k.complementarity},
          {"second_order", k.second_order},
          {"second_order_by", k.second_order_by},
          {"proved_local_optimum", k.proved_local_optimum},
          {"failed", k.failed},
          {"active_rows", k.active_rows},
          {"active_bounds", k.active_bounds},
          {"free_variables", k.free_variables},
          {"null_space_dimension", k.null_space_dimension}};
}

}  // namespace tbridge
