// Each key of the `bridge`, `material` and `design` sections described once: its name, unit,
// allowed range and what it controls; its default is the struct member's initial value
// (core/config.h, core/material.h). From this one description come the strict parse, the
// echo into every output, Validate() for configs built in code and the key tables of
// configs/README.md (core/config_visitors.h; tests/core/config_fields_test.cc holds the README
// to it). The `dynamics` and `structure` sections are described the same way in
// core/dynamics_fields.h and core/structure_fields.h, `sweep` in sweep/sweep_fields.h.
// Adding a key is one line of description and the struct member.
#pragma once

#include <numbers>
#include <string>
#include <type_traits>
#include <vector>

#include "core/config.h"
#include "core/config_visitors.h"
#include "core/dynamics_fields.h"
#include "core/json_reader.h"
#include "core/structure_fields.h"

namespace tbridge {

inline const SectionInfo kBridgeSection{
    "bridge", "geometry and load",
    "`p` must be 1 when `planes` = 2 (the 3D bridge couples two p = 1 planes)."};
inline const SectionInfo kMaterialSection{
    "material", "the bridge's material; the strings' and bars' own where they differ",
    "`youngs_modulus` > `yield_stress` (a strain at yield of 1 or more is no structural material), "
    "for "
    "`material` and for each member kind as resolved; `strings.breaking_stress` > "
    "`strings.yield_stress` (a "
    "cable's proof strength is below its breaking strength); `strings.end_efficiency` only with "
    "`strings.breaking_stress`."};
inline const SectionInfo kDesignSection{
    "design", "minimum-mass problem and sizing",
    "`beta_range_deg` has two angles, the first below the second; `bridge.beta_deg` `\"auto\"` "
    "needs a "
    "verified design, so not with `loads.cases` `[\"paper\"]` (the paper's angle is fixed); "
    "`deck_section` `\"girders\"` neither (the paper's deck is eq 7's plate)."};
inline const SectionInfo kLoadsSection{
    "loads", "actions and their combinations",
    "`cases` lists no name twice; `\"paper\"` stands alone (the paper's one case replaces the "
    "others); `gamma_g_inf` <= `gamma_g_sup`; a planar bridge (`bridge.planes` = 1) needs a case "
    "other than `\"wind\"`; `\"temperature\"` needs `temperature_delta_k` > 0, another case to "
    "accompany, and `temperature_delta_k` > 0 needs `\"temperature\"`."};

inline const SectionInfo kComfortSection{
    "comfort", "footbridge comfort under pedestrians (Sétra 2006, HiVoSS 2008, EN 1990 A2.4.3.2)",
    ""};

inline const SectionInfo kSupportsSection{
    "supports", "the abutments' capacities (unset: rigid hinges of unlimited capacity)", ""};

// Ranges whose ends catch unit slips: a value beyond them is no bridge in the key's unit, and
// the refusal says which unit it was likely given in (configs/README.md, "Plausibility
// warnings"). 2000 m is about the longest span ever built (suspension bridges); 1 deg of beta,
// 100 kg/m^3, 1e6 Pa of yield stress and 1e9 Pa of modulus are below any structural material.
inline const Range kBetaDegRange = Range{1.0, 90.0, false, true}.Below(
    {"under 1 deg: was it given in radians? {v} rad is {as} deg", 180.0 / std::numbers::pi});
inline const Range kSpanRange = Range{0.0, 2000.0, true, false}.Above(
    {"longer than any bridge span: was it given in mm? {v} mm is {as} m", 1e-3});
inline const Range kDensityRange = Range::AtLeast(100.0).Below(
    {"lighter than any structural material: was it given in t/m^3 or g/cm^3? {v} t/m^3 is {as} "
     "kg/m^3",
     1e3});
inline const Range kYieldStressRange = Range::AtLeast(1e6).Below(
    {"weaker than any structural material: was it given in MPa (N/mm^2)? {v} MPa is {as} Pa", 1e6});
inline const Range kModulusRange = Range::AtLeast(1e9).Below(
    {"softer than any structural material: was it given in GPa (steel: 210) or in MPa = N/mm^2 "
     "(steel: 210000)? The key is in Pa (steel: 2.1e+11)"});
// 1e-3 /K is 50 times steel's: a larger value was given in 1e-6/K.
inline const Range kThermalExpansionRange = Range::Closed(0.0, 1e-3).Above(
    {"larger than any structural material's: was it given in 1e-6/K (steel: 12)? {v} x 1e-6/K is "
     "{as} 1/K",
     1e-6});
// A partial factor of 0 would leave its action out of the ultimate cases: no design for it.
inline const Range kPartialFactorRange = Range{0.0, 10.0, true, false}.Below(
    {"a partial factor of 0 leaves its action out of every ultimate combination"});

template <class B, class V>
void DescribeFields(B& b, V& v) requires std::is_same_v<std::remove_const_t<B>, BridgeConfig> {
  v.Integer(KeyInfo{"n", "–",
                    "complexity: levels of self-similar subdivision. The deck has 2^n sections of "
                    "length l = L/2^n; "
                    "for p = 1, n_b = 2^n − 1 bars, n_s = 3·2^n − 2 strings, n_n = 2·n_b + 2 nodes",
                    true},
            b.n, 1, kMaxComplexity);
  v.Integer(KeyInfo{"p", "–",
                    "bars per substructure module (eq. 2): n_b = p(2^n − 1), n_s = (p+1)(2^n − 1) "
                    "+ 2^n. p ≥ 2 makes "
                    "bars share nodes (class k)"},
            b.p, 1, kMaxBarsPerModule);
  v.NumberOrAuto(
      KeyInfo{
          "beta_deg", "deg",
          "aspect angle beta. Every cable of a module slopes at beta/2 from the horizontal: the "
          "node "
          "below a sub-span [a, b] lies (b − a)/2 · tan(beta/2) under the deck. `\"auto\"`: the "
          "verified design chooses it in `design.beta_range_deg` by its verified mass: a scan "
          "every "
          "5 deg, ends included, then a golden section about the best to 0.5 deg (masses within "
          "5e-4 count as equal, the smaller angle kept; `angle_search` lists every angle tried); "
          "`topology.beta_deg` then holds the angle chosen and the summary the masses either side"},
      b.beta_deg, b.beta_auto, kBetaDegRange);
  v.Number(KeyInfo{"span", "m", "L, distance between the two hinged supports"}, b.span, kSpanRange);
  v.Number(KeyInfo{"payload", "N",
                   "F, total external payload on the deck (eq. 9: F_tot = F + 2^n·m_d·g)"},
           b.payload, Range::Positive());
  v.Number(KeyInfo{"deck_width", "m",
                   "w_d, width of a deck beam (eqs 6–7: m_d and the deck thickness) and, for "
                   "`planes` = 2, the "
                   "distance between the two planes"},
           b.deck_width, Range::Positive());
  v.Integer(KeyInfo{"planes", "–",
                    "1 = planar bridge; 2 = 3D bridge of two planar bridges coupled by transverse "
                    "bars and strings "
                    "(paper Sect. 7.3), each plane carrying half of the deck load"},
            b.planes, 1, 2);
}

// The keys of `material.bars` and `material.strings`: each absent value is `material`'s (the
// partial factor: design.yield_safety_factor).
template <class M, class V>
void DescribeMemberMaterial(M& m, V& v) {
  v.OptionalNumber(
      KeyInfo{"density", "kg/m³",
              "rho of these members (a cable's: its mass per metre over its metallic area)", false,
              nullptr, "`material.density`"},
      m.density, kDensityRange, Absent::kOmitted);
  v.OptionalNumber(
      KeyInfo{"yield_stress", "Pa",
              "f_y (a cable: its 0.2 % proof strength f_k = F_k / A, EN 1993-1-11 6.3.2)", false,
              nullptr, "`material.yield_stress`"},
      m.yield_stress, kYieldStressRange, Absent::kOmitted);
  v.OptionalNumber(
      KeyInfo{
          "youngs_modulus", "Pa",
          "E of these members (a cable: its modulus as a tension component, EN 1993-1-11 Annex B: "
          "spiral strand about 1.5e11, full locked coil 1.6e11)",
          false, nullptr, "`material.youngs_modulus`"},
      m.youngs_modulus, kModulusRange, Absent::kOmitted);
  v.OptionalNumber(KeyInfo{"partial_factor", "–",
                           "gamma_M0 on their yield resistance A·f_y/gamma_M0 (a cable: gamma_R of "
                           "EN 1993-1-11 6.3.2, "
                           "0.9 where the ends limit bending, else 1.0)",
                           false, nullptr, "`design.yield_safety_factor`"},
                   m.partial_factor, Range::Closed(0.5, 1000), Absent::kOmitted);
  v.OptionalNumber(KeyInfo{"thermal_expansion", "1/K", "alpha_T of these members", false, nullptr,
                           "`material.thermal_expansion`"},
                   m.thermal_expansion, kThermalExpansionRange, Absent::kOmitted);
}

template <class M, class V>
void DescribeFields(M& m, V& v) requires std::is_same_v<std::remove_const_t<M>, BarMaterialConfig> {
  DescribeMemberMaterial(m, v);
}

template <class M, class V>
void DescribeFields(M& m,
                    V& v) requires std::is_same_v<std::remove_const_t<M>, StringMaterialConfig> {
  DescribeMemberMaterial(m, v);
  v.OptionalNumber(
      KeyInfo{
          "breaking_stress", "Pa",
          "f_uk: makes the strings cables of EN 1993-1-11, F_Rd = min(k_e·f_uk/1.5, f_k)·A/gamma_R "
          "(6.3.2), f_uk the minimum breaking force over the metallic area",
          false, nullptr, "none (steel rods: A·f_y/gamma_M0)"},
      m.breaking_stress, kYieldStressRange, Absent::kOmitted);
  v.OptionalNumber(
      KeyInfo{"end_efficiency", "–",
              "k_e, the loss factor of the cable's end terminations on its breaking strength (EN "
              "1993-1-11 "
              "Table 6.2: metal or resin sockets 1.0, swaged 0.9); only with `breaking_stress`",
              false, nullptr, "1"},
      m.end_efficiency, Range{0.0, 1.0, true, false}, Absent::kOmitted);
}

template <class M, class V>
void DescribeFields(M& m, V& v) requires std::is_same_v<std::remove_const_t<M>, Material> {
  v.Number(KeyInfo{"density", "kg/m³", "rho: member mass rho·A·l, deck beam mass m_d (eq. 7)"},
           m.density, kDensityRange);
  v.Number(KeyInfo{"yield_stress", "Pa",
                   "sigma_yield. The working stress of the deck, and of the members unless "
                   "`strings` or `bars` give their "
                   "own, is sigma_w = `yield_stress` / `yield_safety_factor`"},
           m.yield_stress, kYieldStressRange);
  v.Number(KeyInfo{"youngs_modulus", "Pa",
                   "E: string rest length L0 = s/(1 + sigma/E), stiffness k_s = E·A/L0, Euler "
                   "buckling of bars"},
           m.youngs_modulus, kModulusRange);
  v.Number(
      KeyInfo{
          "thermal_expansion", "1/K",
          "alpha_T, the members' strain per kelvin under the `\"temperature\"` case "
          "(`loads.cases`): "
          "steel 1.2e-5 (EN 1993-1-1 3.2.6), aluminium 2.4e-5 (EN 1999-1-1 3.2.5), a steel cable "
          "1.2e-5 (EN 1993-1-11 Table B.1)"},
      m.thermal_expansion, kThermalExpansionRange);
  v.Section("strings", m.strings);
  v.Section("bars", m.bars);
}

template <class D, class V>
void DescribeFields(D& d, V& v) requires std::is_same_v<std::remove_const_t<D>, DesignConfig> {
  v.Number(
      KeyInfo{
          "yield_safety_factor", "–",
          "gamma_M: sigma_w = sigma_yield / this, for members and deck. Strings: A ≥ T/sigma_w. "
          "Bars: A ≥ "
          "C/sigma_w. Deck: sigma_d = sigma_w in eq. 7. The default 1.1 is EN 1993-2's recommended "
          "gamma_M1 for steel bridges, applied to the strings too because a string that yields "
          "loses the "
          "prestress the bridge's stability rests on; the loads carry their own factors (`loads`). "
          "The "
          "paper's runs use 10, which stands in for the loads it did not check"},
      d.yield_safety_factor, Range::Closed(1, 1000));
  v.Number(
      KeyInfo{
          "buckling_safety_factor", "–",
          "the factor on a bar's buckling resistance: gamma_M1 in N ≤ chi·A·sigma_yield/gamma_M1 "
          "(`bar_resistance` = `\"column_curve\"`, default 1.1 after EN 1993-2), or SF in the "
          "paper's "
          "Euler check A ≥ 2·l·sqrt(SF·C/(pi·E)) (`\"euler\"`, the paper's 1)"},
      d.buckling_safety_factor, Range::Closed(1, 1000));
  v.Number(KeyInfo{"deck_string_min_radius", "m",
                   "minimum radius of the deck strings. They are prestressed at sigma_w, so their "
                   "tension is at least "
                   "sigma_w·pi·r² (the paper's \"fully stretched\" deck cables). 0 = no floor, "
                   "which leaves each bar "
                   "of a planar bridge an inverted pendulum: the design is refused as unstable"},
           d.deck_string_min_radius, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"transverse_string_min_radius", "m",
                   "the same floor for the transverse strings of the 3D bridge (`planes` = 2), "
                   "which carry nothing "
                   "under symmetric vertical load and would otherwise vanish, leaving a mechanism. "
                   "No effect on "
                   "planar bridges"},
           d.transverse_string_min_radius, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"bar_min_radius", "m",
                   "minimum bar radius: A ≥ pi·r². A bar held at this floor reports `governed_by` "
                   "= `min_radius`. "
                   "0 = no floor"},
           d.bar_min_radius, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"gravity", "m/s²",
                   "g, for the deck self-weight in eqs 7–9. 9.81 reproduces the paper's tables; "
                   "9.80665 changes 18 "
                   "of their printed numbers"},
           d.gravity, Range::Closed(0.0, 100.0));
  EnumChoice(
      v,
      KeyInfo{
          "solver", "–",
          "how the minimum-mass problem is solved in its self-stress coefficients (every "
          "equilibrium "
          "solution is a particular solution plus a combination of the self-stresses, from one "
          "sparse QR "
          "of the equilibrium matrix). `\"direct\"`: no iteration, where there is at most one "
          "self-stress "
          "and it loads no bar (every planar bridge: the deck chain, set to its prestress floor); "
          "it is "
          "refused, naming this key, elsewhere. `\"ipopt\"` (interior point, sparse) or "
          "`\"nlopt\"` "
          "(SLSQP, dense): the program that remains (the 3D bridge), in the self-stress "
          "coefficients "
          "while that form's constraint Jacobian is no larger than the full problem's (non-zeros "
          "for "
          "Ipopt, which factorises sparsely; rows x variables for NLopt, which holds it dense), "
          "else in "
          "every member force. For the 3D bridge Ipopt gets the full problem (its self-stresses "
          "fill the "
          "reduced rows) and NLopt the self-stress form (fewer variables); SLSQP's cubic cost "
          "limits "
          "NLopt to small 3D bridges (n <= 5 in seconds). `\"auto\"`: direct where it "
          "applies, else Ipopt (NLopt in a build without Ipopt). Depends on the build: `\"ipopt\"` "
          "and "
          "`\"nlopt\"` exist only when built in (CMake `TBRIDGE_WITH_IPOPT`, `TBRIDGE_WITH_NLOPT`; "
          "`tbridge --version` lists them), and naming one the build lacks is an error naming this "
          "key. "
          "All solve the same problem; the output's `solver.name` says which did. The verified "
          "sizing "
          "(the engineering defaults) solves its own program by its own sequential quadratic "
          "programming "
          "(`solver.name` `\"sqp\"`, always built in) under `\"auto\"` and `\"direct\"`; "
          "`\"ipopt\"` "
          "and `\"nlopt\"` take those solvers for it too (docs/verified_sizing.md)"},
      d.solver, kSolverChoiceNames);
  v.Number(
      KeyInfo{"tolerance", "–",
              "relative optimality and constraint tolerance passed to the iterative solvers (Ipopt "
              "`tol` and "
              "`constr_viol_tol`; NLopt `ftol_rel`, `xtol_rel` and the constraint tolerances)"},
      d.tolerance, Range::Closed(1e-14, 1e-3));
  v.Integer(KeyInfo{"max_iterations", "–",
                    "solver iteration limit (Ipopt `max_iter`; NLopt maximum evaluations). "
                    "Reaching it is an error "
                    "(exit 3) naming the solver's status, never a silent answer"},
            d.max_iterations, 1, 1000000);
  v.Bool(KeyInfo{"self_weight", "–",
                 "the members' own weight (half of each at each end node) in the permanent load, "
                 "iterated with the "
                 "sizing until the mass changes by less than 1e-12 of itself. The paper leaves it "
                 "out (false)"},
         d.self_weight);
  EnumChoice(
      v,
      KeyInfo{"bar_resistance", "–",
              "`\"column_curve\"`: a bar of a solid circular section resists "
              "chi(lambda)·A·sigma_yield / "
              "`buckling_safety_factor` with the EN 1993-1-1 6.3.1.2 curve (Phi = 0.5[1 + "
              "alpha(lambda − 0.2) + "
              "lambda²], chi = 1/(Phi + sqrt(Phi² − lambda²)) ≤ 1, lambda = "
              "sqrt(A·sigma_yield/N_cr)) and A·sigma_w "
              "in yield. `\"euler\"`: the paper's bare Euler load. Either way the 3D bridge's "
              "program prices "
              "bars by Euler and the bars are then sized by this rule"},
      d.bar_resistance, kBarResistanceNames);
  EnumChoice(v,
             KeyInfo{"deck_section", "–",
                     "what carries the deck between two deck stations (a section of length "
                     "l = L/2^n), simply supported on them, sized to the lightest that passes "
                     "its bending (ultimate cases) and its sag (`loads.deck_sag_limit`). "
                     "`\"plate\"`: the paper's solid steel plate of the deck's width (eqs 6-7); "
                     "its weight grows as l^3/4 or faster, so sections longer than a few metres "
                     "carry a plate no footbridge has. `\"girders\"`: two steel I-girders under "
                     "the deck's edges, each of a rolled I-section's proportions (A = 10.0 cm² "
                     "(h / 100 mm)^1.53 within 3 % and I = 0.17·A·h² within 4.1 % of the IPE "
                     "100-600 series), "
                     "sized by their depth h (at least 80 mm, IPE 80's, the smallest rolled), "
                     "braced by the decking, which is part of "
                     "`loads.superimposed_dead_n_per_m`; in plan the pair bends about the deck's "
                     "centre line. The paper's switches keep eq 7's plate"},
             d.deck_section, kDeckSectionNames);
  v.Number(KeyInfo{"imperfection_factor", "–",
                   "alpha of the column curve: 0.49 (curve c, solid sections), 0.34 (b), 0.21 (a), "
                   "0.76 (d)"},
           d.imperfection_factor, Range::Closed(0.0, 2.0));
  v.Integer(
      KeyInfo{
          "max_sizings", "–",
          "the verified sizing's designs at most (its outer iterations: a sizing, then the checks, "
          "then "
          "the corrections). It stops earlier when a sizing from a passing design's corrections is "
          "within 5e-4 of that design's mass; at the limit it keeps the lightest design that "
          "passed and "
          "says it did not converge (`resizing.converged` false)"},
      d.max_sizings, 1, 1000);
  v.Number(KeyInfo{"dynamic_screen", "–",
                   "the static utilisation (a member's, or the deflection over its limit) above "
                   "which the verified "
                   "sizing does not run the dynamic runs on one of its own designs: it fails "
                   "whatever they find, "
                   "and the sizing corrects it by the static findings first (the first sizing's "
                   "design, which knows "
                   "no dynamic amplification yet, at n = 5 to 7 of the default; its walking load "
                   "would fall to RK4). "
                   "Such a design's record says the runs were not run and why. A design that "
                   "passes has every run "
                   "done, whatever this is; `tbridge check` runs every check. 1e9: run them on "
                   "every design"},
           d.dynamic_screen, Range::AtLeast(1.0));
  v.Numbers(
      KeyInfo{
          "beta_range_deg", "deg",
          "[low, high]: where `bridge.beta_deg` `\"auto\"` searches. 10 deg is the paper's angle, "
          "below "
          "which the substructure is so shallow that its thrust on the abutments grows as 1 / "
          "tan(beta/2); "
          "above 60 deg the substructure is deeper than a third of the span and its long bars "
          "buckle, "
          "so the verified mass rises again (the 30 m steel footbridge: lightest near 45-60 deg)"},
      d.beta_range_deg, kBetaDegRange);
  v.Number(KeyInfo{"rod_gamma_m_ser", "–",
                   "gamma_M,ser: a string of steel rod (no `material.strings.breaking_stress`) "
                   "keeps its stress "
                   "under every characteristic (serviceability) combination at most f_y / "
                   "gamma_M,ser (EN 1993-2 "
                   "7.3(1), recommended 1.0), a row of the verified sizing and a finding of the "
                   "static check"},
           d.rod_gamma_m_ser, Range::Closed(1.0, 10.0));
  v.Number(KeyInfo{"cable_f_const_ratio", "–",
                   "f_const / f_uk: a cable string (`material.strings.breaking_stress` given) "
                   "keeps its stress under "
                   "every characteristic (serviceability) combination at most f_const = this x "
                   "f_uk (EN 1993-1-11 "
                   "7.2(2), Table 7.1's recommended 0.50 for the persistent situation; national "
                   "annexes may set "
                   "less), a row of the verified sizing and a finding of the static check"},
           d.cable_f_const_ratio, Range{0.0, 1.0, true, false});
  v.Number(
      KeyInfo{
          "prestress_loss", "–",
          "the fraction of the prestress lost over the bridge's life (the strings' relaxation and "
          "creep, "
          "the anchorages' set): the verified sizing poses every row again with the self-stress "
          "coefficients reduced by it (the forces that carry the permanent load kept), and the "
          "static "
          "check runs again on the bridge so relaxed; the design passes with and without it. 0.05 "
          "is "
          "of the order of a low-relaxation strand's long-term relaxation with a few millimetres "
          "of "
          "anchorage set. Not with the paper's one case"},
      d.prestress_loss, Range{0.0, 1.0, false, true});
  v.Number(KeyInfo{"rest_length_tolerance", "–",
                   "each string's fabricated rest length may be off by up to this fraction of its "
                   "length: the "
                   "verified sizing poses every row again with the prestress at its highest (every "
                   "string the "
                   "prestress tensions short by it) and at its lowest (long by it, after "
                   "`prestress_loss`), the "
                   "worst-sign sum over the strings (docs/verified_sizing.md), and the static "
                   "check runs on the "
                   "bridge with its rest lengths so changed, as built. 5e-4 is 1 mm on a 2 m "
                   "string; set it from "
                   "the fabricator's stated cut-length tolerance. 0 (the default): the rest "
                   "lengths as designed. "
                   "Not with the paper's one case"},
           d.rest_length_tolerance, Range{0.0, 0.1, false, true});
  v.OptionalNumber(
      KeyInfo{"memory_limit_bytes", "B",
              "the most memory a design may take: one whose estimated peak (members x "
              "combinations x states of the prestress, about fourfold per level of `bridge.n`: "
              "the static check's solutions, the verified sizing's rows) is over it is refused "
              "before any work, exit 2, naming the estimate (`tbridge sweep`: the candidate is "
              "not designed, its note says why). Null: the memory available when the design "
              "starts (`MemAvailable` of /proc/meminfo; no limit where that cannot be read). The "
              "estimate is a little above the peaks measured at n <= 6 and grows 4x per level "
              "beyond, an upper bound there (docs/verified_sizing.md, \"Memory\")",
              false, nullptr, "the memory available"},
      d.memory_limit_bytes, Range::Positive(), Absent::kNull);
}

template <class L, class V>
void DescribeFields(L& l, V& v) requires std::is_same_v<std::remove_const_t<L>, LoadsConfig> {
  EnumChoices(
      v,
      KeyInfo{
          "cases", "–",
          "the actions the design is checked and sized for. `\"permanent\"`: G = deck beams + "
          "members' "
          "self-weight (`design.self_weight`) + `superimposed_dead_n_per_m`. `\"payload\"`: "
          "`bridge.payload` over the full span, and the same load per metre over each half span. "
          "`\"travelling\"`: Q_t at each deck node in turn (the lever rule puts its extremes "
          "there). "
          "`\"paper_travelling\"`: the paper's eqs 50–51, the deck node load f at each inner deck "
          "node "
          "on top of the payload, statically and as the dynamic check's run (the paper's load, not "
          "a "
          "code's action: not among the defaults). `\"wind\"`: `wind_n_per_m` across the deck (3D "
          "bridge only; ignored, "
          "and said so, for a planar bridge). Each enters the ultimate combinations (gamma_G G + "
          "gamma_Q Q, "
          "and with favourable G) and the serviceability ones (G + Q). `\"paper\"`: the paper's "
          "one "
          "unfactored case, deck load plus payload at the drawn geometry. `\"temperature\"`: a "
          "uniform change of `temperature_delta_k` either way (EN 1991-1-5 6.1.3), accompanying "
          "every "
          "other case (wind too: EN 1990 A2 lets a footbridge take them apart, so on the safe "
          "side): the prestress's states (`design.prestress_loss`, `design.rest_length_tolerance`) "
          "are posed again warmer and colder, as the bridge's rest lengths and bar lengths then "
          "are "
          "(`material.thermal_expansion`)"},
      l.cases, kLoadFamilyNames);
  v.Number(KeyInfo{"superimposed_dead_n_per_m", "N/m",
                   "surfacing and railings, part of G, spread over the deck"},
           l.superimposed_dead_n_per_m, Range::Closed(0.0, 1e8));
  v.Number(KeyInfo{"travelling_load_n", "N",
                   "Q_t, the travelling point load. 10 kN is EN 1991-2 5.3.2.2's Q_fwk for "
                   "footbridges; a road "
                   "bridge takes 300 kN (one axle of Load Model 1's tandem, EN 1991-2 4.3.2)"},
           l.travelling_load_n, Range::Closed(0.0, 1e9));
  v.Number(
      KeyInfo{"travelling_speed_m_s", "m/s",
              "v of the travelling point load: 1.5 m/s is walking pace; a road bridge takes its "
              "traffic "
              "speed (22 m/s = 80 km/h). With the `\"travelling\"` case the dynamic check runs Q_t "
              "crossing "
              "the deck at this speed, shared between deck nodes by the lever rule, for span / v"},
      l.travelling_speed_m_s, Range{0.0, 1000.0, true, false});
  v.Number(
      KeyInfo{"travelling_contact_length_m", "m",
              "c, the length along the deck over which Q_t bears as it crosses: 0.10 m is the "
              "side of the square EN 1991-2 5.3.2.2 puts Q_fwk on (a road axle's wheels: 0.40 m, "
              "4.3.2). The dynamic check's crossing spreads each deck node's lever-rule share "
              "over c / v (dynamics.loads[].spread_s) and lasts (span + c) / v: the share's slope "
              "then turns over c / v as the load passes a node instead of at once, a corner that "
              "would set the undamped model ringing at its highest modes (kHz, the shortest "
              "bars) at every node the load passes. 0: a point load"},
      l.travelling_contact_length_m, Range::Closed(0.0, 100.0));
  v.Number(KeyInfo{"wind_n_per_m", "N/m",
                   "W, transverse wind on the 3D bridge's deck per metre of span: 1200 N/m is a "
                   "peak velocity "
                   "pressure of 0.9 kPa on 1 m of exposed depth with a force coefficient of 1.3 "
                   "(EN 1991-1-4 8.3)"},
           l.wind_n_per_m, Range::Closed(0.0, 1e8));
  v.Number(KeyInfo{"wind_rise_s", "s",
                   "with the `\"wind\"` case on a 3D bridge, the dynamic check's gust: W rises "
                   "linearly from zero "
                   "over this time, then holds for as long again. 1 s is shorter than the 3 s gust "
                   "behind EN "
                   "1991-1-4's peak velocity pressure, so the run shows the overshoot a sudden "
                   "gust would cause"},
           l.wind_rise_s, Range{0.0, 100.0, true, false});
  v.Number(KeyInfo{"temperature_delta_k", "K",
                   "Delta T_N, the uniform temperature change from that at which the bridge's rest "
                   "lengths are "
                   "set, taken both ways with the `\"temperature\"` case: 25 K is EN 1991-1-5 "
                   "6.1.3.3's range "
                   "either way for a steel deck in a temperate climate (T_max 35 C, T_min -17 C, "
                   "set at 10 C, "
                   "rounded up); take it from the national annex's isotherms"},
           l.temperature_delta_k, Range::Closed(0.0, 100.0));
  v.Number(KeyInfo{"psi0_temperature", "–",
                   "psi_0 of the temperature accompanying the other actions (EN 1990 A2 table "
                   "A2.2: 0.6). The "
                   "states carry gamma_t x psi_0 x Delta T_N in every combination, the "
                   "serviceability ones too "
                   "(on the safe side of psi_0 alone); set 1 to cover the combinations the "
                   "temperature leads"},
           l.psi0_temperature, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"gamma_t", "–", "gamma_Q on the temperature (EN 1990 A2 table A2.4(B): 1.5)"},
           l.gamma_t, kPartialFactorRange);
  v.Number(
      KeyInfo{"gamma_g_sup", "–", "gamma_G,sup, unfavourable permanent action (EN 1990 A2, set B)"},
      l.gamma_g_sup, kPartialFactorRange);
  v.Number(
      KeyInfo{
          "gamma_g_inf", "–",
          "gamma_G,inf, favourable permanent action; the no-slack check uses it. 0 leaves G out of "
          "the favourable cases, which no code does (a plausibility warning)"},
      l.gamma_g_inf, Range::Closed(0.0, 10.0));
  v.Number(KeyInfo{"gamma_q", "–", "gamma_Q on the payload and the travelling loads"}, l.gamma_q,
           kPartialFactorRange);
  v.Number(KeyInfo{"gamma_w", "–", "gamma_Q on wind"}, l.gamma_w, kPartialFactorRange);
  v.Number(KeyInfo{"psi0_wind", "–",
                   "psi_0 of wind accompanying traffic (EN 1990 A2 table A2.2: 0.3 for "
                   "footbridges, 0.6 road)"},
           l.psi0_wind, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"deflection_limit", "–",
                   "serviceability: the largest deflection from the permanent state, under any "
                   "serviceability "
                   "case, must not exceed span / this"},
           l.deflection_limit, Range{0.0, 1e6, true, false});
  v.Number(
      KeyInfo{
          "deck_sag_limit", "–",
          "serviceability: a deck beam's own sag between its deck nodes, under any serviceability "
          "case (its weight, the superimposed dead load, the payload per metre and Q_t at its "
          "middle), "
          "must not exceed its length / this. The bridge's deflection (`deflection_limit`) is "
          "measured "
          "at the deck nodes and does not see it. 300 is a common limit for a deck plate between "
          "supports"},
      l.deck_sag_limit, Range{0.0, 1e6, true, false});
  v.Number(KeyInfo{"dynamic_dt_s", "s",
                   "the step the dynamic check's runs ask for (RK4, the bar lengths stabilised by "
                   "eqs 24-26). Each run takes it, or the largest whole "
                   "fraction of it within 0.9 of RK4's stability limit for the bridge, and a "
                   "quarter of that where "
                   "a run still blows up"},
           l.dynamic_dt_s, Range{0.0, 1.0, false, true});
  v.Number(
      KeyInfo{
          "dynamic_max_member_steps", "–",
          "the largest run the dynamic check does, in member-steps (RK4 steps x members). A run "
          "over it "
          "is not done, saying so: the dynamic check is then not run and the design is INCOMPLETE, "
          "never PASS. The default takes the default bridge's walking load (8 s) at every n up to "
          "8 (480 000 "
          "steps of 1021 members, 25 s, at n = 8); it is a guard against a run of hours, not a "
          "setting of "
          "the check"},
      l.dynamic_max_member_steps, Range::Positive());
  EnumChoice(
      v,
      KeyInfo{"dynamic_method", "–",
              "how the dynamic check runs the walking load (the `\"travelling\"` case). "
              "`\"modal\"`: by "
              "modal superposition about the bridge at rest, in the mode-acceleration form (the "
              "quasi-static "
              "response from a nonlinear static solve at each station, the dynamic excess from the "
              "modes up "
              "to `dynamic_modal_cutoff_hz`); where a string would change state (slack at the "
              "start or at "
              "a station, or going slack in the response) the nonlinear run takes over, and the "
              "run's note "
              "says why. `\"rk4\"`: the nonlinear run (RK4 at `dynamic_dt_s`) always. The paper's "
              "travelling load and the wind gust always run nonlinearly"},
      l.dynamic_method, kDynamicMethodNames);
  v.Number(KeyInfo{"dynamic_modal_cutoff_hz", "Hz",
                   "the modal run's modes: those at or below this frequency (at least the first). "
                   "A mode far "
                   "above the walking load's kinks answers quasi-statically, and the quasi-static "
                   "response is "
                   "in the run exactly; the response is sampled 20 times per period of the highest "
                   "mode kept"},
           l.dynamic_modal_cutoff_hz, Range{0.0, 1e6, true, false});
  v.Number(
      KeyInfo{"dynamic_modal_max_nonlinearity", "–",
              "the modal run is done only where the bridge is this close to linear over the "
              "walking load: the largest difference of the deck's linear response (the tangent "
              "at rest) to the load at a station from its nonlinear one, over the largest "
              "nonlinear response. Beyond it the nonlinear run. The modal run's dynamic excess "
              "is linear, and its error grows with this measure: with Q_t on its 10 cm "
              "(`travelling_contact_length_m`), the member peaks came within 0.41 % of their "
              "resistance of the nonlinear run's at 0.021 (the default's verified design at n = "
              "6) and within 0.86-1.12 % at 0.048-0.049 (its first designs at n = 3..5), the "
              "deck's peak within 0.22 % and 0.07-1.3 % (BENCHMARKS.md): 0.03 keeps both within "
              "about 0.7 %. As a point load (contact length 0) the member peaks were 3.2 % off "
              "already at 0.021: keep 0.015 or less there"},
      l.dynamic_modal_max_nonlinearity, Range::Closed(0.0, 1.0));
  v.Number(
      KeyInfo{
          "station_margin", "–",
          "which deck stations of a travelling family the static check solves nonlinearly. 1: "
          "every "
          "station. Below 1, every station is first solved linearly about the reference state (one "
          "factorisation, a solve per station), and nonlinearly only where its linear utilisation "
          "of a "
          "member, or its deflection over the limit, comes within this fraction of the largest the "
          "linear "
          "pass found for that member or deflection, or within it of the limit 1. The bridge is "
          "stiff "
          "through its prestress, so its response is far from linear (a member's utilisation 0.26 "
          "off at "
          "the full load): on the default bridge, n = 3 to 6, the station that governs a member "
          "lay up to "
          "0.27 of the largest below it in the linear pass, and 0.3 still solved 89 to 100 % of "
          "the "
          "stations nonlinearly, hence the default 1 (BENCHMARKS.md, the static check at every "
          "deck station)"},
      l.station_margin, Range::Closed(0.0, 1.0));
}

template <class C, class V>
void DescribeFields(C& c, V& v) requires std::is_same_v<std::remove_const_t<C>, ComfortConfig> {
  v.Bool(KeyInfo{"check", "–",
                 "the comfort check: the deck's vertical, lateral, longitudinal and torsional "
                 "modes (the mode "
                 "shapes projected on the deck's motions), with the deck, the superimposed dead "
                 "load and the "
                 "class's pedestrians as mass, and the steady peak acceleration of each mode in a "
                 "frequency "
                 "range of resonance risk under the Sétra crowd load in the shape's sign pattern, "
                 "against the "
                 "limit. Never with the paper's switches (`loads.cases` `[\"paper\"]`)"},
         c.check);
  v.Bool(KeyInfo{"sizing_constraint", "–",
                 "the verified sizing designs to the comfort check: each deck mode the check "
                 "considers is a "
                 "row of the sizing, its frequency (an eigenvalue of the areas and the prestress, "
                 "with its "
                 "sensitivities) kept in the window where its Sétra acceleration is within the "
                 "limit, or sent "
                 "to the nearest frequency above where it is (mass_attribution's `comfort`); where "
                 "a row holding a mode above a failing band binds, the passing piece below the "
                 "band is tried too and the lighter passing design kept"},
         c.sizing_constraint);
  EnumChoice(
      v,
      KeyInfo{"traffic_class", "–",
              "Sétra Stage 1 class, and its crowd density d: `\"IV\"` seldom used (no check), "
              "`\"III\"` "
              "standard use (0.5 pedestrian/m², load case 1 in frequency range 1), `\"II\"` "
              "urban (0.8/m², "
              "case 1 in ranges 1 and 2, case 3 in range 3), `\"I\"` very dense crowds "
              "(1.0/m², case 2 in "
              "ranges 1 and 2, case 3 in range 3)"},
      c.traffic_class, kTrafficClassNames);
  EnumChoice(
      v,
      KeyInfo{"comfort_level", "–",
              "Sétra Stage 2 level asked for; its upper acceleration bound is a limit beside "
              "EN 1990's: "
              "`\"maximum\"` (vertical 0.5 m/s², horizontal 0.15), `\"mean\"` (1.0, 0.3), "
              "`\"minimum\"` "
              "(2.5, 0.8)"},
      c.comfort_level, kComfortLevelNames);
  EnumChoice(v,
             KeyInfo{"construction", "–",
                     "sets the structural damping ratio when `damping_ratio` is not given (Sétra; "
                     "HiVoSS 4.4.2 "
                     "mean values): steel 0.4 %, composite 0.6 %, prestressed concrete 1.0 %, "
                     "reinforced concrete "
                     "1.3 %, timber 1.0 % (HiVoSS 1.5 %)"},
             c.construction, kConstructionNames);
  v.OptionalNumber(
      KeyInfo{
          "damping_ratio", "–",
          "xi, the structural damping ratio of every mode (null: the `construction`'s). It enters "
          "the steady resonant acceleration a = F*/(2 xi M*) and the equivalent pedestrian numbers "
          "10.8 sqrt(xi n)",
          false, nullptr, "from `construction`"},
      c.damping_ratio, Range::Open(0.0, 1.0), Absent::kNull);
  v.Number(KeyInfo{"pedestrian_mass_kg", "kg",
                   "one pedestrian's mass (Sétra: 700 N): d · deck area · this is the crowd's mass "
                   "on the deck"},
           c.pedestrian_mass_kg, Range::Closed(0.0, 500.0));
  v.Number(KeyInfo{"vertical_trigger_hz", "Hz",
                   "EN 1990 A2.4.3.2(2): comfort is checked when a vertical or longitudinal deck "
                   "frequency is "
                   "below this"},
           c.vertical_trigger_hz, Range{0.0, 100.0, true, false});
  v.Number(KeyInfo{"horizontal_trigger_hz", "Hz",
                   "EN 1990 A2.4.3.2(2): the same for a lateral deck frequency"},
           c.horizontal_trigger_hz, Range{0.0, 100.0, true, false});
  v.Number(
      KeyInfo{"torsional_trigger_hz", "Hz",
              "the same for a torsional deck frequency: Sétra 2006 (2.3, 4.2) checks torsional "
              "modes in the "
              "vertical ranges (up to 5 Hz), stricter than EN 1990 A2.4.3.2(2)'s 2.5 Hz; a "
              "torsional mode "
              "below it is loaded, measured and limited as a vertical one at the deck's edge node"},
      c.torsional_trigger_hz, Range{0.0, 100.0, true, false});
  v.Number(
      KeyInfo{"vertical_limit_m_s2", "m/s²",
              "EN 1990 A2.4.3.2(1): largest vertical deck acceleration (torsional modes too); the "
              "smaller of this and the `comfort_level`'s bound applies"},
      c.vertical_limit_m_s2, Range{0.0, 100.0, true, false});
  v.Number(KeyInfo{"horizontal_limit_m_s2", "m/s²",
                   "EN 1990 A2.4.3.2(1): largest horizontal (lateral, longitudinal) deck "
                   "acceleration in normal "
                   "use (traffic class III)"},
           c.horizontal_limit_m_s2, Range{0.0, 100.0, true, false});
  v.Number(KeyInfo{"crowd_horizontal_limit_m_s2", "m/s²",
                   "EN 1990 A2.4.3.2(1): the same in exceptional crowd conditions (traffic classes "
                   "I and II)"},
           c.crowd_horizontal_limit_m_s2, Range{0.0, 100.0, true, false});
}

template <class S, class V>
void DescribeFields(S& s, V& v) requires std::is_same_v<std::remove_const_t<S>, SupportsConfig> {
  v.OptionalNumber(
      KeyInfo{
          "horizontal_capacity_n", "N",
          "the largest horizontal reaction one abutment takes: the in-plan vector sum of its "
          "support "
          "nodes' horizontal reactions (one node on a planar bridge, two on the 3D bridge). A row "
          "of the "
          "verified sizing in every ultimate case and station, and a finding of the static check "
          "(mass_attribution's `supports`); the dynamic runs' reactions are not limited. Null: "
          "unlimited, with a warning where prestress, not the load, sets the thrust",
          false, nullptr, "unlimited"},
      s.horizontal_capacity_n, Range::Positive(), Absent::kNull);
  v.OptionalNumber(
      KeyInfo{"vertical_capacity_n", "N",
              "the largest vertical reaction one abutment takes, bearing or uplift alike (its "
              "magnitude), the sum over its support nodes; a row and a finding as "
              "`horizontal_capacity_n`. Null: unlimited",
              false, nullptr, "unlimited"},
      s.vertical_capacity_n, Range::Positive(), Absent::kNull);
}

// The README's text of one section: SectionHeading, a blank line, then SectionBody: the rules
// across its keys when it has any, and its key table.
std::string ConfigSectionText(const SectionInfo& section);

// The Markdown key table of one section ("bridge", "material", "design", "dynamics" or
// "structure"): header, then one row per key: | `key` | unit | default | allowed | what it
// controls |, defaults taken from a default-constructed config. Throws
// std::invalid_argument for another name.
std::string ConfigKeyTable(const std::string& section);

}  // namespace tbridge
