// The footbridge comfort guides' load models and limits, each constant with its source:
// - Sétra, "Footbridges: assessment of vibrational behaviour of footbridges under pedestrian
//   loading", technical guide, 2006 (its Stages 1-4: class, comfort level, frequency ranges,
//   dynamic load cases);
// - HiVoSS, "Design of Footbridges" guideline (RFS2-CT-2007-00033, 2008), for what Sétra
//   leaves out (the traffic classes TC1-TC5 of its step 3, the damping of its step 4,
//   lock-in in its step 6), and named where it differs;
// - EN 1990 Annex A2, A2.4.3.2 (the triggers and limits, config keys `comfort.*`).
// Plain functions of frequencies and densities: no model, no dynamics.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/design_choices.h"

namespace tbridge {

// The direction a crowd load acts in and an acceleration is measured along. A torsional deck
// mode is loaded, and measured, vertically.
enum class LoadAxis { kVertical, kLongitudinal, kLateral };

// Sétra Stage 1: the crowd density d [pedestrians/m²] of a traffic class (I, II, III, IV):
// 1.0, 0.8, 0.5 and 0 (class IV, seldom used: no check). HiVoSS 4.3.1 names five classes
// instead (TC1-TC5: 15 pedestrians, 0.2, 0.5, 1.0, 1.5 /m²). Throws std::invalid_argument for a
// value outside the enum (the config refuses it first).
double TrafficDensity(TrafficClass traffic_class);

// Sétra Stage 3: the frequency range of resonance risk of f [Hz] (1 maximum, 2 medium, 3 low,
// 4 negligible). Vertical and longitudinal: 1 in [1.7, 2.1], 2 in [1, 1.7) and (2.1, 2.6],
// 3 in (2.6, 5], else 4. Lateral: 1 in [0.5, 1.1], 2 in [0.3, 0.5) and (1.1, 1.3], 3 in
// (1.3, 2.5], else 4.
int RiskRange(LoadAxis axis, double f_hz);
// The riskiest range met by a frequency anywhere in [f_lo, f_hi] (the deck's frequency moves
// there as the crowd builds up).
int RiskRangeOver(LoadAxis axis, double f_lo, double f_hi);
// Every range met by a frequency in [f_lo, f_hi], riskiest first.
std::vector<int> RiskRangesOver(LoadAxis axis, double f_lo, double f_hi);

// Sétra Stage 4: psi(f), the factor on the harmonic load for the chance that the pedestrians'
// pace meets f (a trapezoid: 0 outside, rising linearly to 1, 1 on its plateau: 1 over range 1
// of Stage 3, falling to 0 across range 2). Vertical and longitudinal, first harmonic: 0 up to
// 1 Hz, 1 over [1.7, 2.1], 0 from 2.6 Hz; second harmonic: 2.6, [3.4, 4.2], 5 Hz. Lateral
// (half the pace): first harmonic 0.3, [0.5, 1.1], 1.3 Hz; second: 1.3, [1.7, 2.1], 2.5 Hz.
// HiVoSS 4.5.1's narrower trapezoids are not used (pedestrian_loads.cc says why). `harmonic`
// is 1 or 2.
double Psi(LoadAxis axis, int harmonic, double f_hz);
// Its largest value over [f_lo, f_hi].
double PsiOver(LoadAxis axis, int harmonic, double f_lo, double f_hi);

// Sétra Stage 4: one pedestrian's harmonic force amplitude [N]. First harmonic (load cases 1
// and 2; HiVoSS 4.5.1 the same): 280 vertical, 140 longitudinal, 35 lateral; second (load
// case 3): 70, 35, 7.
double PedestrianForceN(LoadAxis axis, int harmonic);

// Sétra Stage 4 (HiVoSS 4.5.1): the number of pedestrians in step and in phase that stand for
// n random ones: 10.8 sqrt(xi n) in a sparse or dense crowd (d < 1 /m²: load cases 1 and 3),
// 1.85 sqrt(n) in a very dense one (d >= 1 /m²: case 2, and case 3 for class I).
double EquivalentPedestrians(double damping_ratio, double pedestrians, bool very_dense);

// Sétra's dynamic load case for a traffic class and a frequency range (its table of
// verifications): class III: case 1 in range 1; class II: case 1 in ranges 1 and 2, case 3 in
// range 3; class I: case 2 in ranges 1 and 2, case 3 in range 3; none otherwise.
struct CrowdLoadCase {
  int number = 0;           // Sétra's case 1, 2 or 3
  int harmonic = 1;         // 1; 2 for case 3
  bool very_dense = false;  // d >= 1: 1.85 sqrt(n), else 10.8 sqrt(xi n)
};
std::optional<CrowdLoadCase> LoadCaseFor(TrafficClass traffic_class, int range);

// Sétra Stage 2: the comfort level an acceleration reaches along `axis` (1 maximum, 2 mean,
// 3 minimum, 4 unacceptable). Vertical: < 0.5, 0.5-1, 1-2.5, above 2.5 m/s². Horizontal
// (lateral, longitudinal): < 0.15, 0.15-0.3, 0.3-0.8, above 0.8 m/s². A torsional mode
// counts as vertical.
int ComfortLevelReached(LoadAxis axis, double acceleration_m_s2);
const char* ComfortLevelName(int level);  // "maximum" | "mean" | "minimum" | "unacceptable"
// The upper acceleration bound of a comfort level asked for [m/s²].
double ComfortLevelBound(LoadAxis axis, ComfortLevel level);

// The damping ratio of a construction (Sétra's table of structural damping for the
// serviceability check, which are HiVoSS 4.4.2's mean values but for timber, 1.5 % there):
// steel 0.004, composite 0.006, prestressed_concrete 0.010, reinforced_concrete 0.013,
// timber 0.010. Throws std::invalid_argument for a value outside the enum.
double ConstructionDamping(Construction construction);

// Lateral lock-in (Sétra; HiVoSS 4.6): the critical number of pedestrians on the deck above
// which the lateral mode of frequency f [Hz], modal mass M* [kg] and damping ratio xi locks
// the crowd in, N_L = 8 pi xi f M* / k, with k = 300 N s/m (measured on the Millennium Bridge).
double LockInPedestrians(double damping_ratio, double f_hz, double modal_mass_kg);

}  // namespace tbridge
