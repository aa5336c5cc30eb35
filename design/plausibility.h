// Plausibility of a computed design: a design can be valid arithmetic and still no bridge
// (a 1 micrometre span, a payload of 1e12 N, n = 12 on a short span). These checks say so
// without refusing the design; `--strict` on the command line makes them errors.
// Thresholds and their reasons are listed in configs/README.md ("Plausibility warnings").
#pragma once

#include <string>
#include <vector>

#include "design/design.h"

namespace tbridge {

inline constexpr double kMinMemberLength = 1e-3;      // [m]: a member shorter than a millimetre
inline constexpr double kMinDeckThickness = 1e-3;     // [m]: a deck thinner than a millimetre
inline constexpr double kMaxDeckThicknessPerSpan = 0.1;  // deck thicker than span / 10
// l / r of a solid bar (r its radius; the radius of gyration is r / 2): 500 is l / r_g = 1000,
// five times the slenderness limit 200 of steel design codes for compression members.
inline constexpr double kMaxBarSlenderness = 500;
// Masses are printed with three decimals in kg: below half a gram a mass prints as 0.000.
inline constexpr double kMinPrintedMass = 5e-4;  // [kg]

// Config values inside their ranges that are still no bridge material or practice (the ranges'
// ends refuse the clear unit slips, core/config_fields.h):
// a density below water's: timber is about 450 kg/m^3, but a metal given in t/m^3 is 1000
// times too small.
inline constexpr double kMinPlausibleDensity = 1000;  // [kg/m^3]

// One sentence per implausible config value of a designed bridge, empty when none; each names
// the key, the value, the threshold and the likely slip. Throws nothing.
std::vector<std::string> ConfigWarnings(const Config& config);

// One sentence per kind of implausibility found, the config's (ConfigWarnings) first, empty when
// none; each names the count, the worst member or value, and the threshold. Throws nothing.
std::vector<std::string> PlausibilityWarnings(const Design& design);

}  // namespace tbridge
