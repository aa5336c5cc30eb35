// The dynamic check of a sized design: its dynamic loads run on the bridge at service level.
// The permanent load and the payload stand (their weight in the loads, the deck's and the
// payload's mass at the deck nodes), and the bridge starts at rest in its static equilibrium
// under them. The loads (checks/load_scenarios.h):
// - the paper's travelling load (eqs 50-51), with the paper's switches or the
//   "paper_travelling" case: f on each inner deck station for 0.25 s;
// - with the "travelling" case, Q_t crossing the deck at loads.travelling_speed_m_s;
// - with the "wind" case on a 3D bridge, the wind W as a gust rising over loads.wind_rise_s.
// The walking load runs by modal superposition where loads.dynamic_method is "modal" (the
// default; checks/modal_run.h): the quasi-static response from a nonlinear static solve at
// each station, the dynamic excess from the modes to loads.dynamic_modal_cutoff_hz, done where
// the bridge is linear over the load to loads.dynamic_modal_max_nonlinearity and no string that
// must stay taut goes slack. Elsewhere, and for the other loads, the nonlinear run: RK4 at
// loads.dynamic_dt_s (1e-4 s), or at the largest whole fraction of it within 0.9 of RK4's
// stability limit, the bar lengths stabilised (eqs 24-26; over a crossing of 8 s their drift
// failed the run from n = 6). The run's note says why a modal run was not done. SDIRK3
// under-reports the member peaks (the paper's load: string peaks up to 22 % low; the walking
// load: 1.1-2.3 % of the resistance at n = 6, and slower than RK4 there; BENCHMARKS.md), so
// the check does not use it.
//
// A member's dynamic demand is P + gamma_G (F_G - P) + gamma max(F_peak - F_G, 0): F_G its
// force in the reference state, P the prestress in it (PrestressForces, not factored),
// gamma_G gamma_G,sup where the permanent load adds to the force and gamma_G,inf where it
// relieves it, F_peak its peak in the run and gamma the load's factor (gamma_Q for the
// travelling loads, gamma_W for wind; all 1 with the paper's switches); its utilisation is that
// over its resistance. A string that must stay taut and goes slack in a run fails with mode
// "slack". Each run's
// peaks are compared per member group with its static counterpart (the load standing at each
// station, or the full wind) for the dynamic amplification.
#pragma once

#include <optional>

#include "core/progress.h"
#include "design/design.h"
#include "dynamics/model.h"

namespace tbridge {

// Runs the check and reports each member's largest dynamic utilisation (DynamicCheck::members,
// mode "dynamic" or "slack", case "dynamic: <run>"). Skips a nonlinear run, saying why in its
// note, when it would take more than `max_member_steps` member-steps: the check is then not run
// (CheckStatus::kNotRun). A run over that at its asked step is skipped before anything is
// built for it (no dynamic model, no static counterpart). With no dynamic load among the cases it
// is done with no run. Changes nothing in `design`. `progress` (optional) is told each run's
// simulated time against its duration, as stage "dynamic check: <run>". `max_member_steps`:
// loads.dynamic_max_member_steps of the design's config where not given. `prestrain`: strings whose
// rest length is set apart from the design (dynamics.prestrain, the sweep's keep_area), in the
// dynamic model and the static solves alike. The options of the dynamic model the check runs on:
// the members' weight where the design counts it, the deck's and payload's inertia except under the
// paper's switches, and `prestrain` (as CheckDynamics's).
ModelOptions DynamicCheckModelOptions(const Design& design,
                                      const std::vector<StringPrestrain>& prestrain = {});

DynamicCheck CheckDynamics(const Design& design,
                           std::optional<double> max_member_steps = std::nullopt,
                           ProgressReporter* progress = nullptr,
                           const std::vector<StringPrestrain>& prestrain = {});

// The check not carried out on `design`: each run it would do, not done, with `why` as its
// note, and every member without a finding. The sizing's record of a design it does not run
// (sizing/verified_design.cc).
DynamicCheck DynamicCheckNotRun(const Design& design, const std::string& why);

}  // namespace tbridge
