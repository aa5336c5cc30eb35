// The angle chosen: bridge.beta_deg "auto" (core/config.h). The aspect angle sets the
// substructure's depth, and with it the thrust on the abutments and the members' forces; its
// verified mass is a function of one variable, searched here by golden section.
#pragma once

#include "core/progress.h"
#include "design/design.h"

namespace tbridge {

// The angle in design.beta_range_deg whose verified design (DesignAndVerify at that angle) is
// best: a passing design before any failing one, passing designs by their structure's mass
// (within 5e-4 they count as equal, and the smaller angle is kept), failing ones by their largest
// utilisation. A scan every 5 deg or closer, ends included, from the steepest down, that goes no
// lower once two angles in a row fail with an abutment over its horizontal capacity, the
// shallower the more (a shallower substructure carries the load with more thrust; the note says
// where it stopped), then a golden section within a step either side of the scan's best, until its
// bracket is under 0.5 deg (20 verified designs over the default 10-60 deg, each with its solver's
// iterations capped at 300, each started from the sizes of the nearest angle that passed:
// SizingStart), then the design at the angle chosen, fresh, with the config's own settings.
// The mass need not be unimodal in the angle: the scan finds the region, the section refines it,
// and a better angle between the scan's points outside that region is not sought. Returns that
// design with `config.bridge` echoing "auto" and beta_deg the angle chosen, and `angle` the record.
Design DesignAtBestAngle(const Config& config, ProgressReporter* progress = nullptr);

}  // namespace tbridge
