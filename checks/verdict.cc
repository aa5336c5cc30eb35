#include "checks/verdict.h"

#include <sstream>
#include <string>
#include <vector>

namespace tbridge {

namespace {

// Each abutment's reactions against its capacities (supports.*) in the verdict: the governing
// utilisation where one is the largest, a failure where one exceeds 1.
void AbutmentVerdicts(const StaticCheck& statics, Verdict& v, std::vector<std::string>& fails) {
  for (const AbutmentFinding& a : statics.abutments) {
    const struct {
      const char* what;
      double utilisation, demand_n, capacity_n;
      const std::string& governing_case;
    } sides[] = {{"horizontal", a.HorizontalUtilisation(), a.horizontal_n, a.horizontal_capacity_n,
                  a.horizontal_case},
                 {"vertical", a.VerticalUtilisation(), a.vertical_n, a.vertical_capacity_n,
                  a.vertical_case}};
    for (const auto& side : sides) {
      if (side.capacity_n <= 0) continue;
      std::ostringstream name;
      name << "abutment at x = " << a.x_m << " m (" << side.what << " reaction, "
           << side.governing_case << ")";
      if (side.utilisation > v.utilisation_max) {
        v.utilisation_max = side.utilisation;
        v.governing = name.str();
      }
      if (side.utilisation > 1.0 + 1e-9) {
        std::ostringstream os;
        os << name.str() << ": " << side.demand_n / 1000 << " kN > capacity "
           << side.capacity_n / 1000 << " kN (supports." << side.what << "_capacity_n)";
        fails.push_back(os.str());
      }
    }
  }
}

}  // namespace

const char* VerdictName(VerdictOutcome outcome) {
  switch (outcome) {
    case VerdictOutcome::kPass:
      return "PASS";
    case VerdictOutcome::kFail:
      return "FAIL";
    case VerdictOutcome::kIncomplete:
      break;
  }
  return "INCOMPLETE";
}

Verdict DesignVerdict(const Design& d) {
  Verdict v;
  const MemberSizing* worst = nullptr;
  for (const auto* list : {&d.bars, &d.strings}) {
    for (const MemberSizing& m : *list) {
      if (worst == nullptr || m.utilisation > worst->utilisation) worst = &m;
    }
  }
  std::vector<std::string> fails, not_done;
  if (worst) {
    v.utilisation_max = worst->utilisation;
    v.governing =
        "member " + worst->name + " (" + NameOf(worst->mode) + ", " + worst->governing_case + ")";
    if (worst->utilisation > 1.0 + 1e-9) {
      std::ostringstream os;
      os << "utilisation " << worst->utilisation << " > 1 in " << v.governing;
      fails.push_back(os.str());
    }
  }
  // The deck beams: their bending at the ultimate cases and their sag between deck stations.
  v.deck_beams = CheckDeckBeams(d.config, d.deck, d.cases);
  const DeckBeamCheck& deck = v.deck_beams;
  if (!deck.governing_case.empty() && deck.utilisation > v.utilisation_max) {
    v.utilisation_max = deck.utilisation;
    v.governing = "deck beams (bending, " + deck.governing_case + ")";
  }
  if (deck.utilisation > 1.0 + 1e-9) {
    std::ostringstream os;
    os << "deck beams: bending utilisation " << deck.utilisation << " > 1 (" << deck.governing_case
       << ")";
    fails.push_back(os.str());
  }
  if (deck.SagRatio() > 1.0 + 1e-9) {
    std::ostringstream os;
    os << "deck beams: sag " << deck.sag_m << " m > l_d / " << d.config.loads.deck_sag_limit
       << " = " << deck.sag_limit_m << " m (" << deck.sag_case << ")";
    fails.push_back(os.str());
  }
  AbutmentVerdicts(d.statics, v, fails);
  if (!d.stability.stable) fails.push_back("unstable");
  if (d.statics.done && !d.statics.all_converged)
    fails.push_back("a static case found no equilibrium");
  if (d.statics.done && d.statics.deflection_max_m > d.statics.deflection_limit_m) {
    std::ostringstream os;
    os << "deflection " << d.statics.deflection_max_m << " m > span / "
       << d.config.loads.deflection_limit << " = " << d.statics.deflection_limit_m << " m ("
       << d.statics.deflection_case << ")";
    fails.push_back(os.str());
  }
  const CheckStatus comfort = d.comfort.Status();
  if (comfort == CheckStatus::kFailed) fails.push_back("comfort: " + d.comfort.Failures());
  const bool comfort_asked = d.config.comfort.check && !KeepsPaperSwitches(d.config);
  if (comfort_asked && comfort == CheckStatus::kNotRun) {
    not_done.push_back("comfort check not run" +
                       (d.comfort.note.empty() ? "" : " (" + d.comfort.note + ")"));
  }
  if (d.unchecked_cases) not_done.push_back("some asked-for cases were not checked (notes)");
  if (!d.statics.done) not_done.push_back("static check not run");
  if (!d.dynamics.done) not_done.push_back("dynamic check not run");
  const std::string runs_not_done = d.dynamics.NotDone();
  if (!runs_not_done.empty()) not_done.push_back("dynamic check: " + runs_not_done);
  v.outcome = !fails.empty()      ? VerdictOutcome::kFail
              : !not_done.empty() ? VerdictOutcome::kIncomplete
                                  : VerdictOutcome::kPass;
  v.pass = v.outcome == VerdictOutcome::kPass;
  std::ostringstream os;
  os << VerdictName(v.outcome) << ": utilisation_max " << v.utilisation_max << " (" << v.governing
     << ")";
  for (const std::string& f : fails) os << "; " << f;
  for (const std::string& f : not_done) os << "; " << f;
  v.summary = os.str();
  v.scope =
      d.topology.planes == 1
          ? "in-plane only: a planar bridge is checked in its own plane; its lateral system "
            "(bracing, "
            "wind, lateral-torsional motion) is not checked, nor its lateral and torsional comfort"
          : "both planes and the transverse strings, wind included where loads.cases asks for it";
  if (!comfort_asked) {
    v.scope += KeepsPaperSwitches(d.config) ? "; comfort not checked (the paper's switches)"
                                            : "; comfort not checked (comfort.check is false)";
  }
  return v;
}

}  // namespace tbridge
