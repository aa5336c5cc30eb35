#include "design/prestress_states.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "design/as_built.h"

namespace tbridge {

namespace {

// Each state of `states` warmer and colder by `delta_k` (its design value, gamma_t psi_0 Delta T).
std::vector<PrestressStateSpec> WarmerAndColder(const std::vector<PrestressStateSpec>& states,
                                                double delta_k) {
  std::vector<PrestressStateSpec> out;
  for (const PrestressStateSpec& state : states) {
    for (const double sign : {+1.0, -1.0}) {
      PrestressStateSpec s = state;
      s.temperature_k = sign * delta_k;
      s.suffix += (s.suffix.empty() ? " " : ", ") + std::string(sign > 0 ? "warmer" : "colder") +
                  " by " + NumberText(delta_k) + " K";
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace

std::vector<PrestressStateSpec> PrestressStatesOf(const Config& config) {
  const PrestressStateSpec designed{PrestressState::kAsDesigned, 1.0, 0, 0.0, ""};
  if (KeepsPaperSwitches(config)) return {designed};
  std::vector<PrestressStateSpec> other;
  const double loss = config.design.prestress_loss, tolerance = config.design.rest_length_tolerance;
  if (tolerance > 0)
    other.push_back({PrestressState::kHighest, 1.0, +1, 0.0, " with the rest lengths short"});
  if (loss > 0 || tolerance > 0) {
    const std::string suffix = loss > 0 && tolerance > 0
                                   ? " after the prestress loss, the rest lengths long"
                               : loss > 0 ? " after the prestress loss"
                                          : " with the rest lengths long";
    other.push_back({PrestressState::kLowest, 1.0 - loss, tolerance > 0 ? -1 : 0, 0.0, suffix});
  }
  const LoadsConfig& l = config.loads;
  if (l.Asks(LoadFamily::kTemperature)) {
    other = WarmerAndColder(other.empty() ? std::vector<PrestressStateSpec>{designed} : other,
                            l.gamma_t * l.psi0_temperature * l.temperature_delta_k);
  }
  other.insert(other.begin(), designed);
  return other;
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

std::vector<double> StateShortenings(const Design& d, const PrestressStateSpec& spec) {
  const size_t nb = d.bars.size();
  std::vector<double> out(nb + d.strings.size(), 0.0);
  if (spec.tolerance_sign != 0) {
    const std::vector<double> tolerance = ToleranceShortenings(d);
    for (size_t k = 0; k < tolerance.size(); ++k) out[nb + k] = spec.tolerance_sign * tolerance[k];
  }
  if (spec.temperature_k != 0) {
    const double bar_strain = BarMaterial(d.config).thermal_expansion * spec.temperature_k;
    const double string_strain = StringMaterial(d.config).thermal_expansion * spec.temperature_k;
    for (size_t k = 0; k < nb; ++k) out[k] -= bar_strain * d.bars[k].length;
    for (size_t k = 0; k < d.strings.size(); ++k)
      out[nb + k] -= string_strain * d.strings[k].rest_length;
  }
  return out;
}

Design DesignInState(const Design& design, const PrestressStateSpec& spec) {
  Design d = spec.alpha_factor != 1.0 ? WithPrestressLoss(design, 1.0 - spec.alpha_factor) : design;
  if (spec.tolerance_sign != 0) {
    std::vector<double> shortenings = ToleranceShortenings(design);
    for (double& s : shortenings) s *= spec.tolerance_sign;
    d = WithRestLengths(d, shortenings);
  }
  return spec.temperature_k != 0 ? WithTemperature(d, spec.temperature_k) : d;
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
