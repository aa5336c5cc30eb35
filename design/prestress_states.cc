#include "design/prestress_states.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "design/design_reader.h"

namespace tbridge {

std::vector<PrestressStateSpec> PrestressStatesOf(const Config& config) {
  std::vector<PrestressStateSpec> out{{PrestressState::kAsDesigned, 1.0, 0, ""}};
  if (KeepsPaperSwitches(config)) return out;
  const double loss = config.design.prestress_loss, tolerance = config.design.rest_length_tolerance;
  if (tolerance > 0)
    out.push_back({PrestressState::kHighest, 1.0, +1, " with the rest lengths short"});
  if (loss > 0 || tolerance > 0) {
    const std::string suffix = loss > 0 && tolerance > 0
                                   ? " after the prestress loss, the rest lengths long"
                               : loss > 0 ? " after the prestress loss"
                                          : " with the rest lengths long";
    out.push_back({PrestressState::kLowest, 1.0 - loss, tolerance > 0 ? -1 : 0, suffix});
  }
  return out;
}

std::vector<PrestressStateSpec> PrestressStatesOf(const Design& design) {
  bool strings_edited = false;
  for (const MemberSizing& m : design.strings) {
    strings_edited =
        strings_edited || std::find(design.as_built.edited.begin(), design.as_built.edited.end(),
                                    m.name) != design.as_built.edited.end();
  }
  if (!strings_edited) return PrestressStatesOf(design.config);
  Config built = design.config;
  built.design.rest_length_tolerance = 0;
  return PrestressStatesOf(built);
}

std::vector<double> ToleranceShortenings(const Design& d) {
  const Eigen::VectorXd prestress = PrestressForces(d);
  const double largest = prestress.size() ? prestress.cwiseAbs().maxCoeff() : 0.0;
  const int nb = static_cast<int>(d.bars.size());
  std::vector<double> out(d.strings.size(), 0.0);
  for (size_t k = 0; k < d.strings.size(); ++k) {
    if (prestress[nb + static_cast<Eigen::Index>(k)] > 1e-9 * largest)
      out[k] = d.config.design.rest_length_tolerance * d.strings[k].length;
  }
  return out;
}

Design DesignInState(const Design& design, const PrestressStateSpec& spec) {
  Design d = spec.alpha_factor != 1.0 ? WithPrestressLoss(design, 1.0 - spec.alpha_factor) : design;
  if (spec.tolerance_sign == 0) return d;
  std::vector<double> shortenings = ToleranceShortenings(design);
  for (double& s : shortenings) s *= spec.tolerance_sign;
  return WithRestLengths(d, shortenings);
}

std::vector<DesignState> OtherStates(const Design& design) {
  const std::vector<PrestressStateSpec> states = PrestressStatesOf(design);
  std::vector<DesignState> out;
  for (size_t k = 1; k < states.size(); ++k) {
    DesignState state{states[k], std::nullopt, ""};
    try {
      state.design = DesignInState(design, states[k]);
    } catch (const ConfigError& e) {
      state.failure = e.what();
    }
    out.push_back(std::move(state));
  }
  return out;
}

}  // namespace tbridge
