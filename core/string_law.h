// The elastic string of every model here (statics, modes, dynamics, the design's rest
// lengths): it pulls k (s - L0) when stretched past its rest length and nothing when slack,
// and it never pushes.
#pragma once

#include <algorithm>

namespace tbridge {

// Tension [N] of a string of stiffness k [N/m] and rest length L0 [m] at length s [m].
// Written without a branch, so that a loop over strings runs in vector registers.
inline double StringTension(double stiffness, double rest_length, double length) {
  return stiffness * std::max(length - rest_length, 0.0);
}

}  // namespace tbridge
