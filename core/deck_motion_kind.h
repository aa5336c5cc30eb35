// The deck motions a mode shape is named after (dynamics/deck_motion.h reads them), with their
// texts: the comfort check's modes (design/verification.h) and tbridge modes name them so.
#pragma once

#include <array>

#include "core/named_choice.h"

namespace tbridge {

enum class DeckMotion { kVertical, kLateral, kLongitudinal, kTorsional, kLocal };
inline constexpr std::array<Named<DeckMotion>, 5> kDeckMotionNames{
    {{DeckMotion::kVertical, "vertical"},
     {DeckMotion::kLateral, "lateral"},
     {DeckMotion::kLongitudinal, "longitudinal"},
     {DeckMotion::kTorsional, "torsional"},
     {DeckMotion::kLocal, "local"}}};
inline const char* NameOf(DeckMotion k) { return NameIn(kDeckMotionNames, k); }

}  // namespace tbridge
