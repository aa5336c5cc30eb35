// The families a bridge's members belong to (core/structure.h's Member::group), with their
// texts: a config addresses strings by them (dynamics.prestrain[].group), and the design file,
// the dynamic check's amplification per group and a run's strings name them so.
#pragma once

#include <array>

#include "core/named_choice.h"

namespace tbridge {

// In the order of their texts, so that a map keyed by the group lists them as it did by text.
enum class MemberGroup {
  kNone,          // a member of no family (a hand-built model's)
  kDeck,          // the deck chain's strings: kept taut, prestressed at the working stress
  kString,        // a structure scene's strings (dynamics.structure), one family
  kSubstructure,  // the substructure's strings, and the leaning bars of p >= 2 modules
  kTransverse,    // the 3D bridge's members between its two planes
  kVertical,      // the bars that carry the deck down to the substructure
};
inline constexpr std::array<Named<MemberGroup>, 6> kMemberGroupNames{
    {{MemberGroup::kNone, ""},
     {MemberGroup::kDeck, "deck"},
     {MemberGroup::kString, "string"},
     {MemberGroup::kSubstructure, "substructure"},
     {MemberGroup::kTransverse, "transverse"},
     {MemberGroup::kVertical, "vertical"}}};
inline const char* NameOf(MemberGroup g) { return NameIn(kMemberGroupNames, g); }

// The string groups dynamics.prestrain[].group may name.
inline constexpr std::array<Named<MemberGroup>, 3> kPrestrainGroupNames{
    {{MemberGroup::kDeck, "deck"},
     {MemberGroup::kSubstructure, "substructure"},
     {MemberGroup::kTransverse, "transverse"}}};

}  // namespace tbridge
