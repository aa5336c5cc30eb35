#include "sizing/angle_search.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <utility>

#include "checks/verdict.h"
#include "core/error.h"
#include "sizing/verified_design.h"

namespace tbridge {

namespace {

// The search stops once its bracket is narrower [deg]; masses this close count as equal.
constexpr double kAngleTolerance = 0.5;
constexpr double kEqualMass = 5e-4;
// The scan's spacing [deg]: the verified mass is not unimodal in the angle where a capacity cuts
// off the shallow angles (the 30 m footbridge at 1 MN: passing at 45 deg, failing at 40.9 with
// the sizing lost, so a golden section from 10-60 deg read its failures as the better side).
constexpr double kScanStep = 5.0;
// A trial's solver iterations at most: a sizing the capacity makes infeasible otherwise runs
// Ipopt's 3000 (561 s at 10 deg on that footbridge); the angle chosen is designed again with
// the config's own.
constexpr int kTrialIterations = 300;

std::string Format(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

// Whether trial a is better than b: passing before failing, then by mass or by utilisation.
bool Better(const AngleSearch::Trial& a, const AngleSearch::Trial& b) {
  if (a.pass != b.pass) return a.pass;
  return a.pass ? a.mass_kg < b.mass_kg : a.utilisation_max < b.utilisation_max;
}

// The angle chosen: of the trials within kEqualMass of the best's mass (the best alone where
// none passed), the smallest angle. Taken over every trial at the end: a tie rule applied pair by
// pair is not transitive, and drifted 7e-4 above the lightest on the 30 m footbridge.
const AngleSearch::Trial& Chosen(const std::vector<AngleSearch::Trial>& trials) {
  const AngleSearch::Trial* best = &trials.front();
  for (const AngleSearch::Trial& t : trials) {
    if (Better(t, *best)) best = &t;
  }
  if (!best->pass) return *best;
  const AngleSearch::Trial* chosen = best;
  for (const AngleSearch::Trial& t : trials) {
    if (t.pass && t.mass_kg <= best->mass_kg * (1 + kEqualMass) && t.beta_deg < chosen->beta_deg)
      chosen = &t;
  }
  return *chosen;
}

// Of the passing trials' sizes by angle, the nearest `beta`'s (null without one).
const SizingStart* NearestStart(const std::vector<std::pair<double, SizingStart>>& starts,
                                double beta) {
  const SizingStart* near = nullptr;
  double distance = std::numeric_limits<double>::infinity();
  for (const auto& [at, sizes] : starts) {
    if (std::abs(at - beta) < distance) {
      distance = std::abs(at - beta);
      near = &sizes;
    }
  }
  return near;
}

// The golden section within `step` either side of `best_deg`, the scan's best, inside the
// search's range; `trial` designs at an angle and records it.
template <typename TrialAt>
void GoldenSection(const AngleSearch& record, double best_deg, double step, const TrialAt& trial) {
  const double ratio = (std::sqrt(5.0) - 1) / 2;
  double a = std::max(record.low_deg, best_deg - step),
         b = std::min(record.high_deg, best_deg + step);
  double c = b - ratio * (b - a), e = a + ratio * (b - a);
  AngleSearch::Trial fc = trial(c), fe = trial(e);
  while (b - a > kAngleTolerance) {
    if (!Better(fe, fc)) {  // the best lies in [a, e]
      b = e;
      e = c;
      fe = fc;
      c = b - ratio * (b - a);
      fc = trial(c);
    } else {
      a = c;
      c = e;
      fc = fe;
      e = a + ratio * (b - a);
      fe = trial(e);
    }
  }
}

// The angle chosen among the trials, with a note where none passed or it is at an end of the
// range.
void ChooseAngle(AngleSearch& record) {
  const AngleSearch::Trial& chosen_trial = Chosen(record.trials);
  record.chosen_deg = chosen_trial.beta_deg;
  if (!chosen_trial.pass) {
    record.note += "no angle tried passed: the design at the least failing one is kept";
  } else if (record.chosen_deg - record.low_deg < kAngleTolerance ||
             record.high_deg - record.chosen_deg < kAngleTolerance) {
    record.note +=
        "the angle chosen is at an end of design.beta_range_deg: the best may lie beyond it";
  }
}

// Where the trial at the angle chosen, started from another angle's sizes, and the design kept
// there, started fresh, are not equal in mass, the record says so: the sizing's fixed point
// depends on its start, and the search's masses either side are its trials'.
void NoteTrialApart(AngleSearch& record, const Design& kept) {
  for (const AngleSearch::Trial& t : record.trials) {
    if (t.beta_deg != record.chosen_deg) continue;
    const double kept_kg = kept.mass.structure;
    if (std::abs(t.mass_kg - kept_kg) <= kEqualMass * kept_kg) return;
    const std::string& n = record.note;
    if (!n.empty() && n.compare(n.size() - std::min<size_t>(n.size(), 2), 2, "; ") != 0)
      record.note += "; ";
    record.note += Format("the trial at the angle chosen weighed %.6g kg, ", t.mass_kg) +
                   "this design of it (started fresh, as with the angle given) " +
                   Format("%.6g kg: ", kept_kg) + "the sizing's fixed point depends on its start";
    return;
  }
}

}  // namespace

Design DesignAtBestAngle(const Config& config, ProgressReporter* progress) {
  AngleSearch record;
  record.done = true;
  record.low_deg = config.design.beta_range_deg.at(0);
  record.high_deg = config.design.beta_range_deg.at(1);
  std::optional<AngleSearch::Trial> best;
  // Each trial's largest horizontal abutment utilisation (0 without a capacity), by trial.
  std::vector<double> thrust_use;
  // The passing trials' sizes by angle: each later trial starts from the nearest one's (a fresh
  // verified design took about 40 s per angle at n = 6 on the 30 m footbridge).
  std::vector<std::pair<double, SizingStart>> starts;
  // One verified design per angle tried, its solver's iterations capped (kTrialIterations); a
  // design that cannot be built or sized at an angle (a ModelError: unstable, no prestress)
  // fails there.
  const auto trial = [&](double beta) {
    for (const AngleSearch::Trial& t : record.trials) {
      if (t.beta_deg == beta) return t;
    }
    Config at = config;
    at.bridge.beta_auto = false;
    at.bridge.beta_deg = beta;
    at.design.max_iterations = std::min(at.design.max_iterations, kTrialIterations);
    AngleSearch::Trial t;
    double use = 0;
    t.beta_deg = beta;
    t.utilisation_max = std::numeric_limits<double>::infinity();
    // The search takes minutes at n = 6: each trial's stages say which angle they are at.
    if (progress != nullptr) {
      progress->SetOuterPrefix(Format("angle %g deg (trial ", beta) +
                               std::to_string(record.trials.size() + 1) + "): ");
    }
    try {
      const Design d =
          DesignAndVerify(at, progress, NearestStart(starts, beta), PieceBelowTrial::kNotTried);
      const Verdict verdict = DesignVerdict(d);
      t.mass_kg = d.mass.structure;
      t.pass = verdict.pass;
      if (t.pass) starts.emplace_back(beta, SizingStart{MemberAreas(d), PrestressForces(d)});
      t.utilisation_max = verdict.utilisation_max;
      for (const AbutmentFinding& a : d.statics.abutments)
        use = std::max(use, a.HorizontalUtilisation());
    } catch (const ModelError& e) {
      record.note += Format("beta = %g deg: ", beta) + e.what() + "; ";
    }
    if (!best || Better(t, *best)) best = t;
    record.trials.push_back(t);
    thrust_use.push_back(use);
    return t;
  };
  // The scan: every kScanStep or closer, both ends included, from the steepest down. A shallower
  // substructure carries the load with more thrust: once two angles in a row fail with an
  // abutment over its horizontal capacity, the shallower one the more, the scan goes no lower
  // (at 10 deg the 30 m footbridge's trial takes 690 s at n = 4 to fail at 48 times its 1 MN).
  const double span = record.high_deg - record.low_deg;
  const int steps = std::max(1, static_cast<int>(std::ceil(span / kScanStep - 1e-9)));
  for (int k = steps; k >= 0; --k) {
    const AngleSearch::Trial t = trial(record.low_deg + span * k / steps);
    const size_t last = thrust_use.size() - 1;
    const bool rising = last > 0 && !t.pass && !record.trials[last - 1].pass &&
                        thrust_use[last - 1] > 1 && thrust_use[last] > thrust_use[last - 1];
    if (rising && k > 0) {
      record.note +=
          Format("below %g deg not tried: ", t.beta_deg) +
          Format("the abutments' horizontal utilisation rose to %.3g ", thrust_use[last]) +
          Format("from %.3g at the angle above; ", thrust_use[last - 1]);
      break;
    }
  }
  // The golden section within a step either side of the scan's best.
  GoldenSection(record, best->beta_deg, span / steps, trial);
  ChooseAngle(record);
  // The design at the angle chosen, with the config's own solver settings: the same design as
  // the config with that angle given, the only one of the search that tries a binding comfort
  // row's piece below (the trials' masses are their first runs').
  Config chosen = config;
  chosen.bridge.beta_auto = false;
  chosen.bridge.beta_deg = record.chosen_deg;
  if (progress != nullptr)
    progress->SetOuterPrefix(Format("angle chosen, %g deg: ", record.chosen_deg));
  Design out = DesignAndVerify(chosen, progress);
  if (progress != nullptr) progress->SetOuterPrefix("");
  NoteTrialApart(record, out);
  out.config.bridge.beta_auto = true;
  out.angle = std::move(record);
  return out;
}

}  // namespace tbridge
