// What governs a member, as an enum with its texts: a member's governing mode (MemberSizing::mode,
// MemberFinding::mode, the sizing's row kinds) and what bounds its area
// (MemberSizing::governed_by). The design file, the printed tables and the scripts that read them
// spell these as text; the code compares the values. One table gives both ways.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "core/named_choice.h"

namespace tbridge {

enum class LimitMode {
  kNone,            // "": nothing found yet (a member no check has reached)
  kYield,           // "yield": A sigma_w (strings), A f_y / gamma_M0 (bars)
  kBuckling,        // "buckling": the column curve's or the Euler load
  kTension,         // "tension": a bar pulled in some case
  kSlack,           // "slack": a string that must stay taut went slack (measured by its strain)
  kDynamic,         // "dynamic": a run's peak against the static resistances
  kTaut,            // "taut": the sizing's row that keeps a string taut under a case
  kReferenceTaut,   // "reference_taut": the same in the reference state
  kDeflection,      // "deflection": the deck's deflection limit
  kServiceability,  // "serviceability": a string's stress in a characteristic combination
  kSupports,        // "supports": an abutment's capacity
  kComfort,         // "comfort": a deck mode's comfort limit
  // Only what bounds an area (governed_by):
  kMinRadius,  // "min_radius": the minimum radius
  kStiffness,  // "stiffness": the stiffness it gives, its strength not used up
  kResized,    // "resized": held at the area floor the verification's resizing gave it
  kPrestress,  // "prestress": grown to carry the deck strings' prestress (the last value)
};

inline constexpr std::array<Named<LimitMode>, 16> kLimitModeNames{
    {{LimitMode::kNone, ""},
     {LimitMode::kYield, "yield"},
     {LimitMode::kBuckling, "buckling"},
     {LimitMode::kTension, "tension"},
     {LimitMode::kSlack, "slack"},
     {LimitMode::kDynamic, "dynamic"},
     {LimitMode::kTaut, "taut"},
     {LimitMode::kReferenceTaut, "reference_taut"},
     {LimitMode::kDeflection, "deflection"},
     {LimitMode::kServiceability, "serviceability"},
     {LimitMode::kSupports, "supports"},
     {LimitMode::kComfort, "comfort"},
     {LimitMode::kMinRadius, "min_radius"},
     {LimitMode::kStiffness, "stiffness"},
     {LimitMode::kResized, "resized"},
     {LimitMode::kPrestress, "prestress"}}};

inline const char* NameOf(LimitMode mode) { return NameIn(kLimitModeNames, mode); }

// The mode a text names ("" is kNone); nullopt for a text outside the table.
inline std::optional<LimitMode> LimitModeNamed(std::string_view text) {
  return ValueIn(kLimitModeNames, text);
}

}  // namespace tbridge
