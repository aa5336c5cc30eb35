// The states of the prestress a design must pass in (docs/verified_sizing.md, "The prestress's
// states"): as designed; at its highest, every string the prestress tensions fabricated short by
// design.rest_length_tolerance of its length; at its lowest, after design.prestress_loss and with
// those strings fabricated long by the tolerance. The verified sizing poses its rows in each
// state, and the static check runs in each.
//
// The rule of the rest-length errors is the worst-sign sum over the strings: to first order a
// rest-length error moves the forces only through the self-stresses (a statically determinate
// part takes it as a displacement), N^T F N d_alpha = N^T delta (F the members' flexibilities
// l / (E A), bars rigid, delta the shortenings), so every string shortened where the prestress
// tensions it raises the prestress most and every one lengthened lowers it most: on a planar
// bridge (one self-stress) each member's worst-sign sum exactly. The pattern is the design's
// (the signs of its prestress), held within a sizing; the static check confirms it nonlinearly
// on the bridge with its rest lengths so changed (as built).
//
// The temperature (the "temperature" case, loads.temperature_delta_k) is a change of every
// member's stress-free length, alpha_T Delta T its length, which the same compatibility turns
// into self-stress between the fixed supports; which way raises the prestress depends on the
// bridge, so each state above is posed warmer and colder, at gamma_t psi_0 Delta T_N.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "design/design.h"

namespace tbridge {

enum class PrestressState { kAsDesigned, kHighest, kLowest };

struct PrestressStateSpec {
  PrestressState state = PrestressState::kAsDesigned;
  double alpha_factor = 1;   // the share of the self-stress kept: 1, or 1 - prestress_loss
  int tolerance_sign = 0;    // +1: the strings short by the tolerance, -1: long, 0: as designed
  double temperature_k = 0;  // the uniform temperature change [K] from that built at (0: none)
  std::string suffix;        // appended to a case's label in this state ("" as designed)
};

// The states `config` asks for: as designed first, then the highest where a tolerance is given,
// the lowest where a tolerance or a loss is, each warmer and then colder with the "temperature"
// case (as designed warmer and colder where there is neither); only as designed with the
// paper's switches.
std::vector<PrestressStateSpec> PrestressStatesOf(const Config& config);
// The states a design is checked in: its config's, but without the tolerance where strings of
// it were edited in its file and its state re-derived as built (AsBuilt::edited): its rest
// lengths are then those built, or measured, and the tolerance would count their error twice.
std::vector<PrestressStateSpec> PrestressStatesOf(const Design& design);

// The design's rest-length changes of the highest state [m], per string (positive: shorter):
// rest_length_tolerance x its length where the design's prestress tensions it (PrestressForces
// above 1e-9 of the largest), else 0.
std::vector<double> ToleranceShortenings(const Design& design);

// The shortening [m] of every member's stress-free length in state `spec` ([bars; strings]):
// tolerance_sign x ToleranceShortenings for the strings, less alpha_T x temperature_k x its
// stress-free length (a string's rest length, a bar's length) for every member.
std::vector<double> StateShortenings(const Design& design, const PrestressStateSpec& spec);

// `design` in state `spec`: its prestress reduced by the loss (WithPrestressLoss), then each
// string's rest length changed by tolerance_sign x ToleranceShortenings (with its stiffness, the
// reference state then re-derived as built, design/as_built.h), then warmed by temperature_k
// (WithTemperature). Throws ConfigError where the bridge so changed has no reference state.
Design DesignInState(const Design& design, const PrestressStateSpec& spec);

// The design in each of its other states (PrestressStatesOf(design) after the first), made once
// for the static and the dynamic checks: the state and its design, or, where the bridge so
// changed does not stand, why (DesignInState's ConfigError).
struct DesignState {
  PrestressStateSpec spec;
  std::optional<Design> design;
  std::string failure;
};
std::vector<DesignState> OtherStates(const Design& design);

}  // namespace tbridge
