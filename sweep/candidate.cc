#include "sweep/candidate.h"

#include <algorithm>
#include <cmath>

#include "bridge/design_model.h"
#include "checks/dynamic_check.h"
#include "checks/verdict.h"
#include "core/error.h"
#include "core/member_area.h"
#include "dynamics/model.h"
#include "sizing/memory_estimate.h"
#include "sizing/verified_design.h"
#include "sweep/first_frequency.h"

namespace tbridge {

namespace {

// grow_area (see candidate.h): the deck strings carry E A0 (1/r - 1) at an allowed stress.
// Returns the area factor; updates the members and the mass breakdown of `design`.
double GrowDeckStrings(Design& design, double ratio) {
  const MemberMaterial mat = StringMaterial(design.config);
  const double sigma_w = mat.DesignStress();
  double factor = 1;
  for (MemberSizing& s : design.strings) {
    if (s.kind != MemberKind::kDeckString) continue;
    const double tension = mat.youngs_modulus * s.area * (1 / ratio - 1);
    const double area = std::max(s.area, tension / sigma_w);
    factor = std::max(factor, area / s.area);
    if (area > s.area) s.governed_by = LimitMode::kPrestress;
    s.area = area;
    s.radius = RadiusOfArea(area);
    s.force = tension;
    s.force_density = tension / s.length;
    s.stress = tension / area;
    s.rest_length = RestLengthOfArea(mat.youngs_modulus, area, tension, s.length);
    s.stiffness = AxialStiffness(mat.youngs_modulus, area, s.rest_length);
    s.mass = MassOfArea(mat.density, area, s.length);
  }
  design.mass = MassesOf(design.bars, design.strings, design.mass.deck_beams);
  return factor;
}

// What the constraints read of the design's dynamic check (candidate.h).
// `num_bars`: the design's bars, which come first in check.members.
void ReadDynamicCheck(const DynamicCheck& check, size_t num_bars, CandidateRow& row) {
  double bars = 0, strings = 0;
  for (size_t j = 0; j < check.members.size(); ++j) {
    const MemberFinding& f = check.members[j];
    if (f.mode != LimitMode::kDynamic) continue;  // "slack" is counted below
    double& largest = j < num_bars ? bars : strings;
    largest = std::max(largest, f.utilisation);
  }
  row.dynamic_bar_utilisation = bars;
  row.dynamic_string_utilisation = strings;
  row.dynamic_check_done = check.done && check.NotDone().empty();
  double deck = 0;
  std::string runs;
  for (const DynamicRun& r : check.runs) {
    if (!runs.empty()) runs += "; ";
    runs += r.name + ": " + (r.done ? r.integrator : r.note);
    if (r.done) deck = std::max(deck, r.peak_deck_displacement);
  }
  row.peak_deck_displacement = deck;
  row.dynamic_runs = runs;
  row.slack_taut_strings = static_cast<int>(check.slack_strings.size());
  if (!*row.dynamic_check_done) {
    const std::string why =
        "dynamic check not complete: " + (check.done ? check.NotDone() : std::string("not run"));
    row.note = row.note.empty() ? why : row.note + "; " + why;
  }
}

double DeckStress(const Design& design) {
  double stress = 0;
  for (const MemberSizing& s : design.strings) {
    if (s.kind == MemberKind::kDeckString) stress = std::max(stress, s.force / s.area);
  }
  return stress;
}

}  // namespace

std::vector<Candidate> EnumerateCandidates(const SweepConfig& sweep) {
  std::vector<Candidate> out;
  for (const int n : sweep.n) {
    for (const int p : sweep.p) {
      for (const double beta : sweep.beta_deg) {
        for (const double r : sweep.deck_prestrain) {
          out.push_back({static_cast<int>(out.size()), n, p, beta, r});
        }
      }
    }
  }
  return out;
}

Config CandidateConfig(const SweepSpec& spec, const Candidate& candidate) {
  Config c = spec.base;
  c.bridge.n = candidate.n;
  c.bridge.p = candidate.p;
  c.bridge.beta_deg = candidate.beta_deg;
  c.dynamics.reset();
  return c;
}

double JointMass(const Design& design, const JointMassConfig& joint) {
  const Structure& st = design.topology.structure;
  std::vector<double> largest(st.num_nodes(), 0.0);
  auto meet = [&](const MemberSizing& m) {
    largest[m.i] = std::max(largest[m.i], m.force);
    largest[m.j] = std::max(largest[m.j], m.force);
  };
  for (const MemberSizing& b : design.bars) meet(b);
  for (const MemberSizing& s : design.strings) meet(s);
  double mass = 0;
  for (int v = 0; v < st.num_nodes(); ++v) {
    if (st.fixed[v]) continue;
    mass += joint.per_node_kg + joint.per_force_kg_per_N * largest[v];
  }
  return mass;
}

namespace {

// The sweep's constraints the row violates (row.violated), and whether it is feasible.
void CheckConstraints(const SweepSpec& spec, CandidateRow& row) {
  const SweepConfig& sw = spec.sweep;
  const SweepConstraints& con = sw.constraints;
  const double span = spec.base.bridge.span;
  auto check = [&](bool active, bool passed, const char* name) {
    if (active && !passed) row.violated.push_back(name);
  };
  check(sw.verified, row.verified.value_or(false), kVerifiedDesign);
  check(sw.constraints.Dynamic(), row.dynamic_check_done.value_or(false), kDynamicCheckDone);
  check(con.min_first_frequency_rad_s.has_value(),
        row.first_frequency_rad_s &&
            *row.first_frequency_rad_s >= con.min_first_frequency_rad_s.value_or(0),
        kMinFirstFrequency);
  check(con.max_deck_displacement.has_value(),
        row.peak_deck_displacement &&
            *row.peak_deck_displacement <= con.max_deck_displacement.value_or(0),
        kMaxDeckDisplacement);
  check(con.span_over_displacement.has_value(),
        row.peak_deck_displacement &&
            *row.peak_deck_displacement * con.span_over_displacement.value_or(0) <= span,
        kSpanOverDisplacement);
  check(con.no_slack_under_service, row.slack_taut_strings && *row.slack_taut_strings == 0,
        kNoSlack);
  check(con.max_dynamic_stress_ratio.has_value(),
        row.dynamic_string_utilisation &&
            *row.dynamic_string_utilisation <= con.max_dynamic_stress_ratio.value_or(0),
        kMaxDynamicStress);
  check(con.bar_capacity_during_motion,
        row.dynamic_bar_utilisation && *row.dynamic_bar_utilisation <= 1.0, kBarCapacity);
  // 1e-8 relative: the design state sits at sigma_w up to the solver's force tolerance
  // (design.tolerance, 1e-10 by default, seen as 2e-10 relative in the deck strings).
  check(con.prestress_within_allowed, row.prestress <= row.allowed_stress * (1 + 1e-8),
        kPrestressAllowed);
  row.feasible = row.violated.empty();
}

}  // namespace

CandidateRow EvaluateCandidate(const SweepSpec& spec, const Candidate& candidate) {
  const SweepConfig& sw = spec.sweep;
  CandidateRow row;
  row.candidate = candidate;
  try {
    const Config config = CandidateConfig(spec, candidate);
    // A candidate whose verified design would exceed design.memory_limit_bytes is a row not
    // designed, its note the refusal, and the grid goes on: the other candidates are what the
    // sweep is for, and `tbridge design` refuses the same config with exit 2.
    if (sw.verified) {
      if (std::string refusal = MemoryRefusal(config); !refusal.empty()) {
        row.ok = false;
        row.note = std::move(refusal);
        row.feasible = false;
        return row;
      }
    }
    // As tbridge design: an unstable candidate is no design (its note says why).
    Design design = sw.verified ? DesignAndVerify(config) : RunDesign(config);
    RequireStable(design);
    row.first_design = design.resizing.structure_mass_kg.empty()
                           ? design.mass.structure
                           : design.resizing.structure_mass_kg.front();
    row.designs = std::max(1, design.resizing.iterations);
    if (sw.verified) {
      const Verdict verdict = DesignVerdict(design);
      row.verified = verdict.pass;
      row.utilisation_max = verdict.utilisation_max;
      // The verdict says what failed, or which dynamic run was skipped and why.
      if (!verdict.pass || !design.dynamics.NotDone().empty()) row.note = verdict.summary;
    }
    // With bridge.beta_deg "auto" the candidate is at the angle its search chose.
    if (design.angle.done) {
      row.candidate.beta_deg = design.config.bridge.beta_deg;
      row.angle_note = design.angle.note;
      if (!design.angle.note.empty())
        row.note += (row.note.empty() ? "" : "; ") + ("angle: " + design.angle.note);
    }
    row.allowed_stress = StringMaterial(design.config).DesignStress();
    const bool prestrained = candidate.deck_prestrain < 1.0;
    // keep_area's rest lengths go to the models (dynamics.prestrain), as tbridge simulate takes
    // them.
    std::vector<StringPrestrain> prestrain;
    if (prestrained && sw.prestrain_sizing == PrestrainSizing::kGrowArea) {
      row.deck_string_area_factor = GrowDeckStrings(design, candidate.deck_prestrain);
      row.prestress = DeckStress(design);
    } else if (prestrained) {
      prestrain.push_back({MemberGroup::kDeck, candidate.deck_prestrain});
      row.prestress =
          StringMaterial(design.config).youngs_modulus * (1 / candidate.deck_prestrain - 1);
    } else {
      row.prestress = DeckStress(design);
    }
    const MassBreakdown& m = design.mass;
    row.bars = m.bars;
    row.strings = m.strings;
    row.deck_strings = m.deck_strings;
    row.deck_beams = m.deck_beams;
    row.structure = m.structure;
    row.total = m.total;
    row.joint_mass = JointMass(design, sw.joint_mass);
    row.objective = row.total + row.joint_mass;
    row.free_nodes = design.topology.structure.num_free_nodes();

    if (sw.NeedsModes()) {
      // The frequency of the model the dynamic check runs on.
      row.first_frequency_rad_s =
          LowestFrequency(BuildDynamicModel(design, DynamicCheckModelOptions(design, prestrain)))
              .omega_rad_s;
    }
    if (sw.NeedsDynamicCheck()) {
      // A verified design carries its own check of this bridge; a changed or unverified one is
      // checked here, by the same check.
      const bool own = sw.verified && !prestrained;
      ReadDynamicCheck(
          own ? design.dynamics : CheckDynamics(design, std::nullopt, nullptr, prestrain),
          design.bars.size(), row);
    }
  } catch (const ModelError& e) {
    row.ok = false;
    row.note = e.what();
    row.feasible = false;
    return row;
  }

  CheckConstraints(spec, row);
  return row;
}

}  // namespace tbridge
