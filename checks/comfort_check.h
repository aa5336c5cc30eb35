// The footbridge comfort check of a sized design (EN 1990 A2.4.3.2 with the Sétra 2006 and
// HiVoSS load models, design/pedestrian_loads.h):
// 1. The mass model is the deck beams, the superimposed dead load and the traffic class's
//    pedestrians (d x deck area x comfort.pedestrian_mass_kg) at the deck nodes, not the design
//    payload; the bridge stands in its static equilibrium under their weight. Its modes are
//    found with the pedestrians (crowded) and without them (empty).
// 2. Each mode is named by the deck motion its shape projects on most (dynamics/deck_motion.h)
//    and scaled to a largest deck displacement of 1 along that motion's axis: its modal mass is
//    M* = 1 / phi_max^2 for the mass-normalised shape phi.
// 3. A mode is relevant when its frequency is below EN 1990 A2's trigger for its motion (5 Hz
//    vertical and longitudinal, 2.5 Hz lateral and torsional); comfort is required when one is.
//    Its Sétra range is the riskiest between its crowded and empty frequencies, and the class's
//    load case in that range, if any, loads every deck node with p x its deck area along the
//    axis, in the sign of the shape there: p = F_1 N_eq psi / S, with F_1 one pedestrian's force
//    of the case's harmonic, N_eq the equivalent pedestrians, psi its largest between the two
//    frequencies and S the deck area. The steady peak acceleration at resonance, from the modal
//    equation M* q'' + 2 xi omega M* q' + omega^2 M* q = F* sin(omega t), is
//    a = omega^2 F* / (2 xi omega^2 M*) = F* / (2 xi M*), with F* = sum p A_k |phi_k| / phi_max.
// 4. It passes when a is within the limit: the smaller of the comfort level's bound and EN 1990
//    A2's limit (vertical for torsion; for a lateral or longitudinal mode the crowd limit for
//    classes I and II); a lateral mode in range 1 or 2 must also carry fewer pedestrians than
//    its lock-in number.
// A planar bridge has vertical and longitudinal modes only; its lateral and torsional comfort is
// not checked (the verdict's scope says so). The check changes nothing in the design.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/design.h"
#include "design/pedestrian_loads.h"
#include "dynamics/deck_motion.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"

namespace tbridge {

// The mass model of step 1, with the pedestrians (`crowded`) or without. Throws ModelError
// when there is no static equilibrium under their weight.
DynamicModel ComfortModel(const Design& design, bool crowded);

// A model's modes and the deck motion of each: every mode up to 150 free DOFs, else the lowest
// 40 by the sparse solver, twice as many until one is above `above_hz` (the comfort check's
// highest trigger frequency) or every mode is found.
struct DeckModes {
  ModalResult modal;
  std::vector<DeckMotionReport> motions;  // one per mode
};
DeckModes ComputeDeckModes(const DynamicModel& model, double above_hz = 0);

// The axis a deck motion (any but kLocal) is loaded and
// measured along (torsion: vertical).
LoadAxis LoadAxisOf(DeckMotion direction);

// Steps 3-4 of one mode (its modal mass and load weight set) as if its frequencies were
// `crowd_hz` and `empty_hz`: its range, load model, psi, modal force, acceleration, limit,
// comfort class and pass. The check calls it at the mode's own frequencies, the sizing's comfort
// correction at shifted ones.
void RespondAt(ComfortMode& mode, const ComfortCheck& check, const Design& design, double crowd_hz,
               double empty_hz);

// The crowd load of one mode with pressure p [N/m²]: p times each deck node's deck area along
// the motion's axis, in the sign of the mode's shape there (3 x n_n [N]).
Eigen::Matrix3Xd CrowdModeLoad(const Design& design, const Mode& mode,
                               const DeckMotionReport& motion, double pressure_n_m2);

// Steps 1-4. Not done (and saying why in its note) with the paper's switches, with
// comfort.check false, or when the modes cannot be found.
ComfortCheck CheckComfort(const Design& design);

// The same check with the models and modes it read, for the comfort rows of the sizing
// (sizing/comfort_sizing.h): `modes`, the deck modes below kNearTrigger times their trigger
// assessed as the check assesses them (check.modes are those below the trigger), and per entry
// its mode among `crowded` and its match among `empty` (the mode of the same motion and rank; -1
// where there is none). The sizing bounds the modes near the trigger too: a sizing that stiffens
// the modes below it would otherwise bring down a shape it did not see.
inline constexpr double kNearTrigger = 1.25;
struct ComfortAnalysis {
  ComfortCheck check;
  DynamicModel crowded_model, empty_model;
  DeckModes crowded, empty;
  std::vector<ComfortMode> modes;
  std::vector<int> crowded_mode, empty_mode;
};
ComfortAnalysis AnalyseComfort(const Design& design);

}  // namespace tbridge
