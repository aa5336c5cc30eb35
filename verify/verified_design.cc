#include "verify/verified_design.h"

#include <algorithm>
#include <cmath>

#include "verify/dynamic_check.h"
#include "verify/static_check.h"

namespace tbridge {

void RecordChecks(Design& d, StaticCheck statics, DynamicCheck dynamics) {
  const int nb = static_cast<int>(d.bars.size());
  for (const std::vector<MemberFinding>* found : {&statics.members, &dynamics.members}) {
    for (int j = 0; j < static_cast<int>(found->size()); ++j) {
      const MemberFinding& f = (*found)[j];
      MemberSizing& m = j < nb ? d.bars[j] : d.strings[j - nb];
      if (f.utilisation > 0) RaiseUtilisation(m, f.utilisation, f.governing_case, f.mode.c_str());
    }
  }
  d.statics = std::move(statics);
  d.dynamics = std::move(dynamics);
}

Design DesignAndVerify(const Config& config, ProgressReporter* progress, int max_iterations) {
  Resizing record;
  std::vector<double> floor;
  for (record.iterations = 1;; ++record.iterations) {
    Design d = RunDesign(config, record.iterations == 1 ? progress : nullptr, floor.empty() ? nullptr : &floor);
    RequireStable(d);
    RecordChecks(d, CheckStatics(d), CheckDynamics(d));
    record.structure_mass_kg.push_back(d.mass.structure);
    const Verdict verdict = DesignVerdict(d);
    record.converged = verdict.pass;
    // The paper's design is the paper's: with its switches the checks report, and resize nothing.
    const bool stop =
        KeepsPaperSwitches(config) || record.iterations >= max_iterations || d.unchecked_cases || !d.statics.all_converged;
    // Resizing mends what fails; a check that could not run is not mended by it.
    if (verdict.outcome != VerdictOutcome::kFail || stop) {
      if (!verdict.pass) record.why = verdict.summary;
      d.resizing = record;
      return d;
    }
    const int nb = static_cast<int>(d.bars.size());
    if (floor.empty()) floor.assign(d.bars.size() + d.strings.size(), 0.0);
    // Stiffness: slack in service or too much deflection stiffens every string alike.
    bool slack = false;
    for (const MemberSizing& m : d.strings) slack = slack || (m.mode == "slack" && m.utilisation > 1.0 + 1e-9);
    // The dynamic demand grows a member like a static one (by its utilisation, conservatively).
    const double excess = d.statics.deflection_max_m / d.statics.deflection_limit_m;
    const double stiffen = std::max(excess > 1.0 ? excess : 1.0, slack ? 1.1 : 1.0);
    for (int j = 0; j < static_cast<int>(floor.size()); ++j) {
      const MemberSizing& m = j < nb ? d.bars[j] : d.strings[j - nb];
      double grow = 1.0;
      if (m.utilisation > 1.0 + 1e-9 && m.mode != "slack") grow = m.mode == "buckling" ? std::sqrt(m.utilisation) : m.utilisation;
      if (j >= nb) grow = std::max(grow, stiffen);
      // 1e-6 above the need, so a member sized exactly to it is not left a rounding short.
      if (grow > 1.0) floor[j] = std::max(floor[j], m.area * grow * (1.0 + 1e-6));
    }
  }
}

}  // namespace tbridge
