// Each key of the `bridge`, `material` and `design` sections described once: its name, unit,
// allowed range and what it controls; its default is the struct member's initial value
// (core/config.h, core/material.h). From this one description come the strict parse, the
// echo into every output, Validate() for configs built in code and the key tables of
// configs/README.md (core/config_visitors.h; tests/core/config_fields_test.cc holds the README
// to it). The `dynamics` and `structure` sections are described the same way in
// core/dynamics_fields.h and core/structure_fields.h, `sweep` in sweep/sweep_fields.h.
// Adding a key is one line of description and the struct member.
#pragma once

#include <string>
#include <type_traits>
#include <vector>

#include "core/config.h"
#include "core/config_visitors.h"
#include "core/dynamics_fields.h"
#include "core/json_reader.h"
#include "core/structure_fields.h"

namespace tbridge {

inline const SectionInfo kBridgeSection{"bridge", "geometry and load",
                                        "`p` must be 1 when `planes` = 2 (the 3D bridge couples two p = 1 planes)."};
inline const SectionInfo kMaterialSection{"material", "one material for bars, strings and deck beams", ""};
inline const SectionInfo kDesignSection{"design", "minimum-mass problem and sizing", ""};

template <class B, class V>
void DescribeFields(B& b, V& v) requires std::is_same_v<std::remove_const_t<B>, BridgeConfig> {
  v.Integer(KeyInfo{"n", "–",
                    "complexity: levels of self-similar subdivision. The deck has 2^n sections of length l = L/2^n; "
                    "for p = 1, n_b = 2^n − 1 bars, n_s = 3·2^n − 2 strings, n_n = 2·n_b + 2 nodes",
                    true},
            b.n, 1, kMaxComplexity);
  v.Integer(KeyInfo{"p", "–",
                    "bars per substructure module (eq. 2): n_b = p(2^n − 1), n_s = (p+1)(2^n − 1) + 2^n. p ≥ 2 makes "
                    "bars share nodes (class k)"},
            b.p, 1, kMaxBarsPerModule);
  v.Number(KeyInfo{"beta_deg", "deg",
                   "aspect angle beta. Every cable of a module slopes at beta/2 from the horizontal: the node below a "
                   "sub-span [a, b] lies (b − a)/2 · tan(beta/2) under the deck"},
           b.beta_deg, Range::Open(0.0, 90.0));
  v.Number(KeyInfo{"span", "m", "L, distance between the two hinged supports"}, b.span, Range::Positive());
  v.Number(KeyInfo{"payload", "N", "F, total external payload on the deck (eq. 9: F_tot = F + 2^n·m_d·g)"},
           b.payload, Range::Positive());
  v.Number(KeyInfo{"deck_width", "m",
                   "w_d, width of a deck beam (eqs 6–7: m_d and the deck thickness) and, for `planes` = 2, the "
                   "distance between the two planes"},
           b.deck_width, Range::Positive());
  v.Integer(KeyInfo{"planes", "–",
                    "1 = planar bridge; 2 = 3D bridge of two planar bridges coupled by transverse bars and strings "
                    "(paper Sect. 7.3), each plane carrying half of the deck load"},
            b.planes, 1, 2);
}

template <class M, class V>
void DescribeFields(M& m, V& v) requires std::is_same_v<std::remove_const_t<M>, Material> {
  v.Number(KeyInfo{"density", "kg/m³", "rho: member mass rho·A·l, deck beam mass m_d (eq. 7)"}, m.density,
           Range::Positive());
  v.Number(KeyInfo{"yield_stress", "Pa",
                   "sigma_yield. The working stress of every member and of the deck is sigma_w = `yield_stress` / "
                   "`yield_safety_factor`"},
           m.yield_stress, Range::Positive());
  v.Number(KeyInfo{"youngs_modulus", "Pa",
                   "E: string rest length L0 = s/(1 + sigma/E), stiffness k_s = E·A/L0, Euler buckling of bars"},
           m.youngs_modulus, Range::Positive());
}

template <class D, class V>
void DescribeFields(D& d, V& v) requires std::is_same_v<std::remove_const_t<D>, DesignConfig> {
  v.Number(KeyInfo{"yield_safety_factor", "–",
                   "sigma_w = sigma_yield / this, for members and deck. Strings: A = T/sigma_w. Bars: A ≥ C/sigma_w. "
                   "Deck: sigma_d = sigma_w in eq. 7"},
           d.yield_safety_factor, Range::Closed(1, 1000));
  v.Number(KeyInfo{"buckling_safety_factor", "–",
                   "SF in the Euler check of a solid circular pinned–pinned bar: A ≥ 2·l·sqrt(SF·C/(pi·E))"},
           d.buckling_safety_factor, Range::Closed(1, 1000));
  v.Number(KeyInfo{"deck_string_min_radius", "m",
                   "minimum radius of the deck strings. They are prestressed at sigma_w, so their tension is at least "
                   "sigma_w·pi·r² (the paper's \"fully stretched\" deck cables). 0 = no floor, which leaves each bar "
                   "of a planar bridge an inverted pendulum: the design is refused as unstable"},
           d.deck_string_min_radius, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"transverse_string_min_radius", "m",
                   "the same floor for the transverse strings of the 3D bridge (`planes` = 2), which carry nothing "
                   "under symmetric vertical load and would otherwise vanish, leaving a mechanism. No effect on "
                   "planar bridges"},
           d.transverse_string_min_radius, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"bar_min_radius", "m",
                   "minimum bar radius: A ≥ pi·r². A bar held at this floor reports `governed_by` = `min_radius`. "
                   "0 = no floor"},
           d.bar_min_radius, Range::Closed(0.0, 1.0));
  v.Number(KeyInfo{"gravity", "m/s²",
                   "g, for the deck self-weight in eqs 7–9. 9.81 reproduces the paper's tables; 9.80665 changes 18 "
                   "of their printed numbers"},
           d.gravity, Range::Closed(0.0, 100.0));
  v.Choice(KeyInfo{"solver", "–",
                   "how the minimum-mass problem is solved in its self-stress coefficients (every equilibrium "
                   "solution is a particular solution plus a combination of the self-stresses, from one sparse QR "
                   "of the equilibrium matrix). `\"direct\"`: no iteration, where there is at most one self-stress "
                   "and it loads no bar (every planar bridge: the deck chain, set to its prestress floor); it is "
                   "refused, naming this key, elsewhere. `\"ipopt\"` (interior point, sparse) or `\"nlopt\"` "
                   "(SLSQP, dense): the program that remains (the 3D bridge), in the self-stress coefficients "
                   "while that form's constraint Jacobian is no larger than the full problem's (non-zeros for "
                   "Ipopt, which factorises sparsely; rows x variables for NLopt, which holds it dense), else in "
                   "every member force. For the 3D bridge Ipopt gets the full problem (its self-stresses fill the "
                   "reduced rows) and NLopt the self-stress form (fewer variables); SLSQP's cubic cost limits "
                   "NLopt to small 3D bridges (n <= 5 in seconds). `\"auto\"`: direct where it "
                   "applies, else Ipopt (NLopt in a build without Ipopt). Depends on the build: `\"ipopt\"` and "
                   "`\"nlopt\"` exist only when built in (CMake `TBRIDGE_WITH_IPOPT`, `TBRIDGE_WITH_NLOPT`; "
                   "`tbridge --version` lists them), and naming one the build lacks is an error naming this key. "
                   "All solve the same problem; the output's `solver.name` says which did"},
           d.solver, {"auto", "direct", "ipopt", "nlopt"});
  v.Number(KeyInfo{"tolerance", "–",
                   "relative optimality and constraint tolerance passed to the iterative solvers (Ipopt `tol` and "
                   "`constr_viol_tol`; NLopt `ftol_rel`, `xtol_rel` and the constraint tolerances)"},
           d.tolerance, Range::Closed(1e-14, 1e-3));
  v.Integer(KeyInfo{"max_iterations", "–",
                    "solver iteration limit (Ipopt `max_iter`; NLopt maximum evaluations). Reaching it is an error "
                    "(exit 3) naming the solver's status, never a silent answer"},
            d.max_iterations, 1, 1000000);
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
