// Each key of the `structure` section described once (protocol: core/config_visitors.h); its
// default is the struct member's initial value (core/structure_config.h). Node numbers are
// bounded by the node count, known once `nodes` is read: the descriptions below read it
// from the config when they are visited, after `nodes`.
#pragma once

#include <type_traits>

#include "core/config_visitors.h"
#include "core/structure_config.h"

namespace tbridge {

inline const SectionInfo kStructureSection{
    "structure",
    "a custom scene (`tbridge simulate` and `modes`), or a structure to design (`tbridge design`)",
    "with `dim` = 2 every node's z and every load's z is 0; `pinned`, `deck_nodes` and "
    "`node_masses[].node` name each node at most once, and deck nodes are not pinned; a bar or "
    "string joins two different nodes at different positions, and no two bars (or strings) join "
    "the same pair; each string gives exactly one of `rest_length_m` and `rest_ratio`, and its "
    "rest length is > 0; `allowed_stress_pa` is required when a string has `area_m2`. A structure "
    "to design gives `members` instead of `bars` and `strings` (never both; `loads`, "
    "`deck_nodes` and `allowed_stress_pa` belong to the scene), with `groups` and at least one of "
    "`load_cases` (or frequency limits); beside it the config may give `material` (`density`, "
    "`youngs_modulus`) and "
    "`design` (`self_weight`, `gravity`, `buckling_safety_factor`, `solver`, `tolerance`, "
    "`max_iterations`), no other section. Each member names a group; each group has members, a "
    "name given once, `min_area_m2` <= `max_area_m2`, and, where there are load cases, the "
    "allowed stresses its kind needs (strings tension, bars compression, trusses both); never one "
    "its kind does not carry; a string takes no "
    "buckling. Load case names are given once; a displacement limit is on a free node, along z "
    "only with `dim` = 3, each node and axis once."};

// Bounds the scene before any array is sized from it (hostile input, the fuzz target).
inline constexpr int kMaxStructureNodes = 1 << 20;

template <class S, class V>
void DescribeFields(S& c, V& v) requires std::is_same_v<std::remove_const_t<S>, StructureLimits> {
  v.List(KeyInfo{"displacements", "–",
                 "displacement limits of a designed structure, in every load case"},
         c.displacements, [&](auto& d, auto& e) {
           e.Integer(KeyInfo{"node", "–", "a free node", true, "integer in [1, node count]"},
                     d.node, 1, kMaxStructureNodes);
           EnumChoice(e, KeyInfo{"axis", "–", "the displacement's direction"}, d.axis, kAxisNames);
           e.Number(KeyInfo{"max_m", "m", "the displacement's magnitude at most this", true},
                    d.max_m, Range::Positive());
         });
  v.Numbers(KeyInfo{"min_frequencies_hz", "Hz",
                    "the k-th lowest natural frequency at least the k-th entry (consistent mass "
                    "of the members, `node_masses` lumped)"},
            c.min_frequencies_hz, Range::NonNegative());
}

// The designable form's keys (`tbridge design` of a structure: truss/): members in groups, load
// cases and limits. `nodes()` is the node count.
template <class S, class V, class N>
void DescribeDesignable(S& c, V& v, const N& nodes) {
  constexpr const char* kNodeNumber = "integer in [1, node count]";
  v.List(KeyInfo{"members", "–",
                 "the members of a structure to design (`tbridge design`), instead of `bars` and "
                 "`strings`; each member's area is its group's"},
         c.members, [&](auto& m, auto& e) {
           e.NodePair(KeyInfo{"nodes", "–", "end nodes", true,
                              "`[i, j]`, node numbers in [1, node count]; i ≠ j at different "
                              "positions, each pair once"},
                      m.nodes, nodes());
           e.Text(KeyInfo{"group", "–", "the `groups[].name` it belongs to", true}, m.group);
         });
  v.List(KeyInfo{"groups", "–", "families of members designed to one area each"}, c.groups,
         [&](auto& g, auto& e) {
           e.Text(KeyInfo{"name", "–", "the group's name, each once", true}, g.name);
           EnumChoice(e,
                      KeyInfo{"kind", "–",
                              "`\"string\"`: tension only (a row keeps it taut); `\"bar\"`: "
                              "compression only; `\"truss\"`: either sign. All elastic, E·A / L"},
                      g.kind, kTrussKindNames);
           e.Number(KeyInfo{"min_area_m2", "m²", "the smallest area the design may give", true},
                    g.min_area_m2, Range::Positive());
           e.OptionalNumber(KeyInfo{"max_area_m2", "m²", "the largest area; none: unbounded"},
                            g.max_area_m2, Range::Positive(), Absent::kOmitted);
           e.OptionalNumber(KeyInfo{"allowed_tension_pa", "Pa",
                                    "the allowed tensile stress; required for strings and trusses, "
                                    "not given for bars"},
                            g.allowed_tension_pa, Range::Positive(), Absent::kOmitted);
           e.OptionalNumber(
               KeyInfo{"allowed_compression_pa", "Pa",
                       "the allowed compressive stress (a magnitude); required for bars "
                       "and trusses, not given for strings"},
               g.allowed_compression_pa, Range::Positive(), Absent::kOmitted);
           EnumChoice(e,
                      KeyInfo{"buckling", "–",
                              "`\"euler\"`: the compression is held to a solid round section's "
                              "Euler load π²·E·I / L², I = A² / (4π), over "
                              "`design.buckling_safety_factor`; `\"none\"`; `\"auto\"`: Euler for "
                              "bars, none for trusses (strings take none)"},
                      g.buckling, kBucklingRuleNames);
         });
  v.List(KeyInfo{"load_cases", "–",
                 "the design's load cases; each member's weight (`design.self_weight`) is in "
                 "every case, times its factor"},
         c.load_cases, [&](auto& l, auto& e) {
           e.Text(KeyInfo{"name", "–", "the case's name, each once", true}, l.name);
           e.Number(KeyInfo{"factor", "–", "the factor on the case's loads and the self-weight"},
                    l.factor, Range::Positive());
           e.List(KeyInfo{"loads", "–", "node forces", true}, l.loads, [&](auto& f, auto& x) {
             x.Integer(KeyInfo{"node", "–", "the node", true, kNodeNumber}, f.node, 1, nodes());
             x.Vector3(KeyInfo{"force_n", "N", "the force [fx, fy, fz]", true}, f.force_n);
           });
         });
  v.Section("limits", c.limits);
  EnumChoice(v,
             KeyInfo{"prestress", "–",
                     "`\"none\"`: each member's rest length is its drawn length; `\"variable\"`: "
                     "the amplitudes of the structure's self-stress states (member forces that "
                     "balance at every node without load, no support taking any) are sized with "
                     "the areas, their geometric stiffness N0 / L in every analysis; the design "
                     "file gives each member's `prestress_n` and `rest_length_m`"},
             c.prestress, kStructurePrestressNames);
  EnumChoice(
      v,
      KeyInfo{"analysis", "–",
              "each load case's statics in the sizing and the check: `\"linear\"`, small "
              "displacements about the drawn (prestressed) state, as the classic sizing "
              "problems assume; `\"nonlinear\"`, geometrically nonlinear (each member's "
              "force N0 + E·A·(l − L) / L along its turned direction, Newton in load steps), "
              "with its own derivatives. The modes are the drawn state's either way"},
      c.analysis, kTrussAnalysisNames);
}

template <class S, class V>
void DescribeFields(S& c, V& v) requires std::is_same_v<std::remove_const_t<S>, StructureConfig> {
  v.Integer(
      KeyInfo{
          "dim", "–",
          "2: motion in the x-y plane, every node's z and every load's z must be 0; 3: full 3D"},
      c.dim, 2, 3);
  v.Points(KeyInfo{"nodes", "m",
                   "initial node positions; node k is entry k − 1. Bar lengths are held at their "
                   "length here",
                   true},
           c.nodes, kMaxStructureNodes);
  const auto nodes = [&c] { return static_cast<int>(c.nodes.size()); };
  constexpr const char* kNodeNumber = "integer in [1, node count]";
  constexpr const char* kNodeSet = "node numbers in [1, node count], each once";
  v.Integers(KeyInfo{"pinned", "–",
                     "supports: prescribed, not integrated; a string's or a node's mass there is "
                     "carried by the support",
                     false, kNodeSet},
             c.pinned, 1, nodes());
  v.List(KeyInfo{"node_masses", "–", "point masses, on top of the string mass the node gets"},
         c.node_masses, [&](auto& m, auto& e) {
           e.Integer(KeyInfo{"node", "–", "the node; each node once", true, kNodeNumber}, m.node, 1,
                     nodes());
           e.Number(KeyInfo{"mass_kg", "kg", "point mass", true}, m.mass_kg, Range::NonNegative());
         });
  constexpr const char* kEnds =
      "`[i, j]`, node numbers in [1, node count]; i ≠ j at different positions, each pair once";
  v.List(
      KeyInfo{"bars", "–",
              "rigid bars (eq. 21 mass matrix). Bars sharing a node make the scene class k: "
              "`dynamics.engine` `\"auto\"` then takes the class-k engine"},
      c.bars, [&](auto& b, auto& e) {
        e.NodePair(KeyInfo{"nodes", "–", "end nodes", true, kEnds}, b.nodes, nodes());
        e.Number(KeyInfo{"mass_kg", "kg", "the bar's mass", true}, b.mass_kg, Range::NonNegative());
      });
  v.List(
      KeyInfo{"strings", "–", "elastic strings, slack below their rest length"}, c.strings,
      [&](auto& t, auto& e) {
        e.NodePair(KeyInfo{"nodes", "–", "end nodes", true, kEnds}, t.nodes, nodes());
        e.Number(KeyInfo{"stiffness_n_m", "N/m", "k: tension k·(s − L0) while s >= L0", true},
                 t.stiffness_n_m, Range::NonNegative());
        e.Number(KeyInfo{"damping_n_s_m", "N·s/m",
                         "c: force density term c·(s·ṡ)/s² (eq. 16), per string"},
                 t.damping_n_s_m, Range::NonNegative());
        e.OptionalNumber(KeyInfo{"rest_length_m", "m",
                                 "L0. Give exactly one of `rest_length_m` and `rest_ratio`"},
                         t.rest_length_m, Range::Positive(), Absent::kOmitted);
        e.OptionalNumber(
            KeyInfo{"rest_ratio", "–",
                    "L0 = ratio × the string's length at `nodes` (< 1: pretensioned, > 1: slack)"},
            t.rest_ratio, Range::Positive(), Absent::kOmitted);
        e.Number(KeyInfo{"mass_kg", "kg",
                         "the string's mass, shared as `dynamics.string_mass` says: `\"bars\"` "
                         "half to the bars at each end (eq. 27; a point mass at an end without "
                         "bars), `\"nodes\"` half lumped at each end, `\"off\"` none"},
                 t.mass_kg, Range::NonNegative());
        e.OptionalNumber(KeyInfo{"area_m2", "m²",
                                 "cross-section for the stress report (tension / area); without it "
                                 "the string's stress is not reported"},
                         t.area_m2, Range::Positive(), Absent::kOmitted);
      });
  v.List(KeyInfo{"loads", "–", "constant node forces from t = 0 (timed ones: `dynamics.loads`)"},
         c.loads, [&](auto& l, auto& e) {
           e.Integer(KeyInfo{"node", "–", "the node", true, kNodeNumber}, l.node, 1, nodes());
           e.Vector3(KeyInfo{"force_n", "N", "the force [fx, fy, fz]", true}, l.force_n);
         });
  v.Integers(KeyInfo{"deck_nodes", "–",
                     "nodes whose summed vertical (y) displacement gives `dynamics.frequency` and "
                     "the peak displacement report; none = no frequency (the summary says why)",
                     false, "free node numbers in [1, node count], each once"},
             c.deck_nodes, 1, nodes());
  v.OptionalNumber(KeyInfo{"allowed_stress_pa", "Pa",
                           "the allowed stress the reported string stress is compared with; "
                           "required when a string has `area_m2`"},
                   c.allowed_stress_pa, Range::Positive(), Absent::kOmitted);
  v.Number(
      KeyInfo{"gravity_m_s2", "m/s²",
              "g of `dynamics.gravity_on_structure` (weight of bars and node masses along −y)"},
      c.gravity_m_s2, Range::Closed(0.0, 100.0));
  DescribeDesignable(c, v, nodes);
}

// The rules across keys of kStructureSection; throws ConfigError naming the key path.
void CheckStructureRules(const StructureConfig& config);

}  // namespace tbridge
