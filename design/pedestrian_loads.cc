#include "design/pedestrian_loads.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tbridge {

namespace {

bool Horizontal(LoadAxis axis) { return axis == LoadAxis::kLateral; }

// psi's trapezoid: 0 below a, rising to 1 at b, 1 to c, falling to 0 at d [Hz].
struct Trapezoid {
  double a, b, c, d;
  double At(double f) const {
    if (f <= a || f >= d) return 0.0;
    if (f < b) return (f - a) / (b - a);
    if (f <= c) return 1.0;
    return (d - f) / (d - c);
  }
};

// Sétra Stage 4, the figures of psi of load cases 1-2 (first harmonic) and 3 (second): 1 over
// the first harmonic's range 1 of Stage 3 and falling to 0 across its range 2; the second
// harmonic's at twice those frequencies, over range 3. HiVoSS 4.5.1 draws narrower ones
// (vertical 1.25, [1.7, 2.1], 2.3 Hz; lateral 0.5, [0.7, 1.0], 1.2 Hz; no lateral second
// harmonic): with Sétra's ranges and load cases they would leave modes in range 2 unloaded,
// so the tool takes Sétra's throughout.
Trapezoid PsiShape(LoadAxis axis, int harmonic) {
  if (axis == LoadAxis::kLateral)
    return harmonic == 1 ? Trapezoid{0.3, 0.5, 1.1, 1.3} : Trapezoid{1.3, 1.7, 2.1, 2.5};
  return harmonic == 1 ? Trapezoid{1.0, 1.7, 2.1, 2.6} : Trapezoid{2.6, 3.4, 4.2, 5.0};
}

// Sétra Stage 3, the tables of frequency ranges [Hz]: range 1 [r1_lo, r1_hi]; range 2 down to
// r2_lo and up to r2_hi; range 3 up to r3_hi.
struct Ranges {
  double r2_lo, r1_lo, r1_hi, r2_hi, r3_hi;
};
Ranges RangesOf(LoadAxis axis) {
  return Horizontal(axis) ? Ranges{0.3, 0.5, 1.1, 1.3, 2.5} : Ranges{1.0, 1.7, 2.1, 2.6, 5.0};
}

}  // namespace

double TrafficDensity(TrafficClass traffic_class) {
  // Sétra Stage 1, the classes and their crowd densities (load cases 1 and 2).
  switch (traffic_class) {
    case TrafficClass::kI:
      return 1.0;
    case TrafficClass::kII:
      return 0.8;
    case TrafficClass::kIII:
      return 0.5;
    case TrafficClass::kIV:
      return 0.0;
  }
  throw std::invalid_argument("TrafficDensity: no traffic class " +
                              std::to_string(static_cast<int>(traffic_class)));
}

int RiskRange(LoadAxis axis, double f) {
  const Ranges r = RangesOf(axis);
  if (f >= r.r1_lo && f <= r.r1_hi) return 1;
  if (f >= r.r2_lo && f <= r.r2_hi) return 2;
  if (f > r.r2_hi && f <= r.r3_hi) return 3;
  return 4;
}

int RiskRangeOver(LoadAxis axis, double f_lo, double f_hi) {
  return RiskRangesOver(axis, f_lo, f_hi).front();
}

std::vector<int> RiskRangesOver(LoadAxis axis, double f_lo, double f_hi) {
  if (f_hi < f_lo) std::swap(f_lo, f_hi);
  const Ranges r = RangesOf(axis);
  std::vector<int> met = {RiskRange(axis, f_lo), RiskRange(axis, f_hi)};
  // The ranges are unions of intervals: each one met is met at an end or on either side of a
  // bound inside.
  for (const double f : {r.r2_lo, r.r1_lo, r.r1_hi, r.r2_hi, r.r3_hi}) {
    if (f > f_lo && f < f_hi) {
      met.push_back(RiskRange(axis, f));
      met.push_back(RiskRange(axis, std::nextafter(f, f_hi)));
    }
  }
  std::sort(met.begin(), met.end());
  met.erase(std::unique(met.begin(), met.end()), met.end());
  return met;
}

double Psi(LoadAxis axis, int harmonic, double f) { return PsiShape(axis, harmonic).At(f); }

double PsiOver(LoadAxis axis, int harmonic, double f_lo, double f_hi) {
  if (f_hi < f_lo) std::swap(f_lo, f_hi);
  const Trapezoid t = PsiShape(axis, harmonic);
  double best = std::max(t.At(f_lo), t.At(f_hi));
  // Piecewise linear: its largest value is at an end or at a corner inside.
  for (const double f : {t.b, t.c}) {
    if (f > f_lo && f < f_hi) best = std::max(best, t.At(f));
  }
  return best;
}

double PedestrianForceN(LoadAxis axis, int harmonic) {
  // Sétra Stage 4, load cases 1 and 2 (first harmonic) and 3 (second harmonic). HiVoSS 4.5.1
  // has the same first harmonic; its second is psi's plateau 0.25 on 280 N, Sétra's 70 N.
  switch (axis) {
    case LoadAxis::kVertical:
      return harmonic == 1 ? 280.0 : 70.0;
    case LoadAxis::kLongitudinal:
      return harmonic == 1 ? 140.0 : 35.0;
    case LoadAxis::kLateral:
      break;
  }
  return harmonic == 1 ? 35.0 : 7.0;
}

double EquivalentPedestrians(double xi, double n, bool very_dense) {
  // Sétra Stage 4, load cases 1 and 2; HiVoSS 4.5.1: the 95th percentile of random phases.
  return very_dense ? 1.85 * std::sqrt(n) : 10.8 * std::sqrt(xi * n);
}

std::optional<CrowdLoadCase> LoadCaseFor(TrafficClass traffic_class, int range) {
  // Sétra Stage 4, its table of the load cases to check per class and range.
  const bool dense = TrafficDensity(traffic_class) >= 1.0;
  if (traffic_class == TrafficClass::kIII && range == 1) return CrowdLoadCase{1, 1, false};
  if (traffic_class == TrafficClass::kII || traffic_class == TrafficClass::kI) {
    if (range == 1 || range == 2) return CrowdLoadCase{dense ? 2 : 1, 1, dense};
    if (range == 3) return CrowdLoadCase{3, 2, dense};
  }
  return std::nullopt;
}

int ComfortLevelReached(LoadAxis axis, double a) {
  // Sétra Stage 2, the tables of acceleration ranges (vertical; horizontal).
  const std::array<double, 3> bounds = axis == LoadAxis::kVertical
                                           ? std::array<double, 3>{0.5, 1.0, 2.5}
                                           : std::array<double, 3>{0.15, 0.3, 0.8};
  for (int level = 0; level < 3; ++level) {
    if (a <= bounds[level]) return level + 1;
  }
  return 4;
}

const char* ComfortLevelName(int level) {
  switch (level) {
    case 1:
      return "maximum";
    case 2:
      return "mean";
    case 3:
      return "minimum";
    default:
      break;
  }
  return "unacceptable";
}

double ComfortLevelBound(LoadAxis axis, ComfortLevel level) {
  const bool vertical = axis == LoadAxis::kVertical;
  switch (level) {
    case ComfortLevel::kMaximum:
      return vertical ? 0.5 : 0.15;
    case ComfortLevel::kMean:
      return vertical ? 1.0 : 0.3;
    case ComfortLevel::kMinimum:
      return vertical ? 2.5 : 0.8;
  }
  throw std::invalid_argument("ComfortLevelBound: no comfort level " +
                              std::to_string(static_cast<int>(level)));
}

double ConstructionDamping(Construction construction) {
  // Sétra Stage 4, structural damping for the serviceability check (HiVoSS 4.4.2, mean).
  switch (construction) {
    case Construction::kSteel:
      return 0.004;
    case Construction::kComposite:
      return 0.006;
    case Construction::kPrestressedConcrete:
      return 0.010;
    case Construction::kReinforcedConcrete:
      return 0.013;
    case Construction::kTimber:
      return 0.010;
  }
  throw std::invalid_argument("ConstructionDamping: no construction " +
                              std::to_string(static_cast<int>(construction)));
}

double LockInPedestrians(double xi, double f_hz, double modal_mass_kg) {
  constexpr double kLateralGain = 300.0;  // k [N s/m]: Sétra; HiVoSS 4.6
  return 8.0 * std::numbers::pi * xi * f_hz * modal_mass_kg / kLateralGain;
}

}  // namespace tbridge
