// Plausibility of a computed design: a design can be valid arithmetic and still no bridge
// (a 1 micrometre span, a payload of 1e12 N, n = 12 on a short span). These checks say so
// without refusing the design; `--strict` on the command line makes them errors.
// Thresholds and their reasons are listed in configs/README.md ("Plausibility warnings").
#pragma once

#include <string>
#include <vector>

#include "design/design.h"

namespace tbridge {

inline constexpr double kMinMemberLength = 1e-3;         // [m]: a member shorter than a millimetre
inline constexpr double kMinDeckThickness = 1e-3;        // [m]: a deck thinner than a millimetre
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
// The payload over the deck's area, bridge.payload / (span x deck_width). EN 1991-2 5.3.2.1
// asks 2.5 to 5 kPa of a footbridge and Load Model 1 (4.3.2) about 10 kPa on a road lane with
// its tandem spread out: below 0.5 kPa is less than a sparse crowd (the paper's 12 kN on 12 m by
// 1.5 m is 0.67 kPa), above 50 kPa ten times a footbridge crowd; both more likely a unit slip (a
// payload in kN is 1000 times too small).
inline constexpr double kMinPlausiblePayloadPressure = 500;    // [Pa]
inline constexpr double kMaxPlausiblePayloadPressure = 50000;  // [Pa]
// A motorway deck of six lanes with hard shoulders is about 30 m wide; a width in mm is 1000
// times too large.
inline constexpr double kMaxPlausibleDeckWidth = 30;  // [m]

// Results of a designed bridge (not with the paper's switches, whose blanket factor of 10 and
// one case are no engineering design):
// a string thicker than the largest spiral strands and locked-coil ropes made (about 180 mm).
inline constexpr double kMaxPlausibleStringDiameter = 0.2;  // [m]
// The whole bridge, deck beams included, per metre of span: a steel road girder bridge of
// 30-100 m weighs about 1-2 t/m, a footbridge a few hundred kg/m; above 3 t/m the loads or the
// materials are more likely wrong than the bridge heavy.
inline constexpr double kMaxPlausibleMassPerSpan = 3000;  // [kg/m]
// A solid plate deck heavier than this per square metre (design.deck_section "plate", an
// engineering design): 40 mm of steel. Steel deck plates are 10-20 mm on stiffeners or girders;
// at 314 kg/m^2 the plate weighs about as much as the crowd it carries (4 kPa), and it thickens
// as its section lengthens.
inline constexpr double kMaxPlausiblePlateDeckMass = 314;  // [kg/m^2]
// An abutment's horizontal reaction over the load path's own thrust W L / (8 d): a truss or
// cable of depth d that carries a uniform load W over the span L pushes or pulls its supports
// with the simply supported moment W L / 8 over its lever arm d, and the same load concentrated
// at mid-span with twice that, W L / (4 d). Above twice no distribution of the load explains
// the thrust: the supports are free in the minimum-mass problem, so prestress against them is
// the cheapest stiffness, and it sets the thrust; the abutments must be designed for it, as a
// stressed ribbon's anchorage is.
inline constexpr double kMaxAbutmentThrustRatio = 2;

// One sentence per implausible config value of a designed bridge, empty when none; each names
// the key, the value, the threshold and the likely slip. Throws nothing.
std::vector<std::string> ConfigWarnings(const Config& config);

// One sentence per kind of implausibility found, the config's (ConfigWarnings) first, empty when
// none; each names the count, the worst member or value, and the threshold. Throws nothing.
std::vector<std::string> PlausibilityWarnings(const Design& design);

}  // namespace tbridge
