// The comfort check as rows of the verified sizing (sizing/sizing_problem.h, ComfortRow).
//
// At resonance a mode's steady acceleration F* / (2 xi M*) depends on its stiffness only through
// where its frequency lies: Sétra's psi (piecewise linear in f, with kinks at its range ends) and
// whether the traffic class has a load case in that range (a jump where it has none). With the
// mode's shape, and so M* and F*, held at the design the sizing starts from, the acceleration is a
// function of the frequency alone, and the mode passes on a window of frequencies. Each deck mode
// the check considers gets the rows that keep its frequencies in the window that holds:
// - a mode that passes keeps its crowded frequency above the window's lower end and its empty
//   frequency below its upper end (where the window has ends within a factor 3);
// - a mode that fails is sent up to the least frequency at which it passes (its acceleration
//   within the limit on a falling flank of psi, or out of the ranges its class is loaded in),
//   its crowded frequency above it.
// The frequencies are eigenvalues of the areas and the prestress, with their own sensitivities
// (dynamics/modal_sensitivity.h); the outer iterations rebuild the rows from each design's modes.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "checks/comfort_check.h"
#include "design/design.h"
#include "sizing/sizing_problem.h"

namespace tbridge {

// The comfort rows about `design` from its comfort analysis (AnalyseComfort(design)); none where
// comfort.sizing_constraint is false or the check was not done. A mode named in `below` (its
// direction and rank among the modes of that direction: "vertical 1", as ComfortRow::key begins)
// is held under the top of the passing piece below the one it is in or sent up to, where there is
// one (the sizing tries that piece when the mode's row binds, and keeps the lighter passing
// design); its row is marked `below`. With `passing` kHeldInItsWindow (the trial's later
// sizings) such a mode that passes is held in the window it reached, as any passing mode: sent
// below it again, it went on to the next piece down (the cables footbridge's vertical 1, passing
// at 2.63 Hz, was asked for 1.06 Hz, and the trial's next sizing weighed 16 t). Changes nothing.
enum class BelowPassing { kSentBelow, kHeldInItsWindow };
std::vector<ComfortRow> ComfortRowsOf(const Design& design, const ComfortAnalysis& analysis,
                                      const std::set<std::string>& below = {},
                                      BelowPassing passing = BelowPassing::kSentBelow);

// How far the last sizing's comfort rows foretold the design it gave, and the outer correction of
// the next rows: each row of `next` (built from that design's modes) whose mode the last sizing
// bounded (matched by key) asks for its target times what the last row foretold over what the
// design found, between 1 and kLargestCorrection: the quotient holds the shape, the static state
// and the members' weight, and falls short by a like share again (the default at n = 3: 0.5 %
// of omega^2 a sizing). The correction is the last step's alone, not a product over the steps:
// as the designs settle it stays what one step misses by. Returns the largest
// |omega^2 foretold / omega^2 found - 1| (0 where no row matches).
inline constexpr double kLargestCorrection = 1.02;
double CorrectComfortRows(const SizingProblem& problem, const Eigen::VectorXd& x,
                          std::vector<ComfortRow>& next);

// The top of the passing piece below the one `mode` is held in or sent up to, as a scale of both
// its frequencies (the mode passes at it and fails just above): for a failing mode the first
// passing scale under 1; for a passing one, the first under its window's lower end and the
// failing band beneath it. None down to a third. Changes nothing.
std::optional<double> PieceBelow(const ComfortMode& mode, const ComfortCheck& check,
                                 const Design& design);

// Halves each row's step from the mode's eigenvalue to its target (in log frequency), for a
// sizing that could not meet them; false where no row has a step to halve.
bool EaseComfortRows(std::vector<ComfortRow>& rows);

// One row's members' coefficients from a mode of `model` (a model of `design`, its members in the
// design's order): the eigenvalue's derivatives by each member's area (through its stiffness, a
// string's k = (E A + T_ref) / l), reference force (k and the state's forces follow it) and mass.
ComfortRow ComfortRowOf(const Design& design, const DynamicModel& model, const Mode& mode);

}  // namespace tbridge
