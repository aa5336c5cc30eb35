#include "verify/comfort_sizing.h"

#include <algorithm>
#include <sstream>

#include "verify/comfort_check.h"

namespace tbridge {

namespace {

// The frequency scales tried: steps of 0.2 %, up to 3 (nine times the stiffness): a mode that
// passes nowhere below asks for the largest, and the next design is corrected again.
constexpr double kScaleStep = 1.002;
constexpr double kLargestScale = 3.0;
// The frequency follows the stiffness the sizing asks for only roughly (the deflection rows are
// not the mode): 2 % more stiffness than the scale squared keeps the corrections from creeping.
constexpr double kStiffnessMargin = 1.02;

}  // namespace

ComfortCorrection ComfortCorrectionOf(const Design& d) {
  ComfortCorrection out;
  double scale = 1.0;
  for (const ComfortMode& failing : d.comfort.modes) {
    if (failing.pass) continue;
    double s = kScaleStep;
    ComfortMode moved = failing;
    for (; s < kLargestScale; s *= kScaleStep) {
      RespondAt(moved, d.comfort, d, failing.frequency_hz * s, failing.frequency_empty_hz * s);
      if (moved.pass) break;
    }
    if (s <= scale) continue;
    scale = s;
    std::ostringstream why;
    why << failing.direction << " mode " << failing.index << " from " << failing.frequency_hz << " Hz to "
        << moved.frequency_hz << " Hz: ";
    if (!moved.pass) {
      why << "no frequency up to " << kLargestScale << " times passes";
    } else if (moved.acceleration_m_s2 > 0) {
      why << "acceleration " << moved.acceleration_m_s2 << " m/s^2 within the limit " << moved.limit_m_s2
          << " m/s^2 (range " << moved.range << ", psi " << moved.psi << ")";
    } else {
      why << "out of the risk ranges (range " << moved.range << ", " << moved.load_model << ")";
    }
    out.governs = why.str();
  }
  if (scale > 1.0) out.stiffness_factor = scale * scale * kStiffnessMargin;
  return out;
}

void CorrectForComfort(const Design& d, SizingCorrections& corrections, Resizing& record) {
  if (!d.config.comfort.sizing_constraint) return;
  const ComfortCorrection c = ComfortCorrectionOf(d);
  if (c.stiffness_factor == 1.0) return;
  corrections.stiffness_factor *= c.stiffness_factor;
  record.comfort_stiffness_factor = corrections.stiffness_factor;
  record.comfort_governs = c.governs;
}

}  // namespace tbridge
