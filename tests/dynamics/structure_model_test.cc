// The dynamic model of a custom scene (dynamics/structure_model.h), checked on the MOTES
// scenes of configs/motes_*.json: the model holds what the config says, and its runs obey
// the physics they must (energy, engine agreement).

#include "dynamics/structure_model.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "config_expect.h"
#include "core/config.h"
#include "dynamics/simulation.h"

namespace tbridge {
namespace {

Config Scene(const std::string& name) {
  return LoadConfig(TBRIDGE_SOURCE_DIR "/configs/" + name + ".json");
}

DynamicModel ModelOf(const Config& c) {
  return BuildStructureModel(*c.structure, ModelOptionsOf(*c.dynamics));
}

double Mechanical(const EnergyBalance& e) { return e.kinetic_end + e.elastic_end; }

TEST_CASE("structure model: the prism holds the config's masses and rest lengths") {
  const DynamicModel m = ModelOf(Scene("motes_prism"));
  REQUIRE(m.num_nodes() == 24);
  REQUIRE(m.bars.size() == 3);
  REQUIRE(m.strings.size() == 27);
  CHECK(m.dim == 3);
  CHECK(m.tensegrity_class == 1);
  // 3 bars of 1 kg and 27 segments of 0.05 kg, all lumped at nodes: sums of 0.025 kg, so
  // only rounding (1e-12 kg is a thousand ulps of 4.35 kg).
  CHECK(MovingMass(m) == Approx(3 + 27 * 0.05).margin(1e-12));
  for (const DynamicBar& b : m.bars) CHECK(b.mass == 1.0);  // string mass stays at the nodes
  for (const DynamicString& s : m.strings) {
    const double length = (m.positions.col(s.j) - m.positions.col(s.i)).norm();
    CHECK(s.rest_length == Approx(0.95 * length).epsilon(1e-15));  // same product, same bits
    CHECK(s.stiffness == 100.0);
    CHECK(s.damping == 10.0);
  }
  // Every segment end carries half a segment: 0.025 kg per segment meeting there.
  for (int a = 0; a < m.num_nodes(); ++a) {
    int ends = 0;
    for (const DynamicString& s : m.strings) ends += (s.i == a) + (s.j == a);
    CHECK(m.node_mass(a) == Approx(0.025 * ends).margin(1e-15));
  }
}

TEST_CASE("structure model: string mass follows dynamics.string_mass and is conserved") {
  const Config c = Scene("motes_prism");
  ModelOptions options = ModelOptionsOf(*c.dynamics);
  options.string_mass = StringMassMode::kOnBars;
  const DynamicModel on_bars = BuildStructureModel(*c.structure, options);
  // Rounding of 27 x 2 shares only.
  CHECK(MovingMass(on_bars) == Approx(4.35).margin(1e-12));
  // Massless strings leave the split nodes of the prism without mass: the first is named.
  options.string_mass = StringMassMode::kOff;
  CHECK_THAT(test::ConfigErrorOf([&] { BuildStructureModel(*c.structure, options); }),
             Catch::Contains("'structure.nodes[6]'") && Catch::Contains("node 7"));
}

TEST_CASE("structure model: the D-bar") {
  const DynamicModel m = ModelOf(Scene("motes_dbar"));
  CHECK(m.dim == 2);
  CHECK(m.tensegrity_class == 2);
  CHECK(m.fixed == std::vector<bool>{true, false, false, false});
  REQUIRE(m.strings.size() == 2);
  CHECK(m.names.string_name[0] == "2-4");
  CHECK(m.strings[0].rest_length == 1.0);
  CHECK(m.strings[1].rest_length == 0.5);
  for (const DynamicBar& b : m.bars) CHECK(b.length == Approx(std::sqrt(2.0)).epsilon(1e-15));
}

TEST_CASE("structure model: options only a designed bridge has are rejected by key") {
  const Config c = Scene("motes_dbar");
  ModelOptions prestrain;
  prestrain.prestrain.push_back({MemberGroup::kDeck, 0.9});
  CHECK_THAT(test::ConfigErrorOf([&] { BuildStructureModel(*c.structure, prestrain); }),
             Catch::Contains("'dynamics.prestrain'"));
  ModelOptions damping;
  damping.damping = 5;
  CHECK_THAT(test::ConfigErrorOf([&] { BuildStructureModel(*c.structure, damping); }),
             Catch::Contains("'dynamics.damping_c'") && Catch::Contains("damping_n_s_m"));
}

TEST_CASE("structure model: a free node without mass is named") {
  StructureConfig s = *Scene("motes_dbar").structure;
  s.nodes.push_back({0, 0, 0});  // node 5, joined by a massless string only
  s.strings.push_back({{5, 2}, 100, 0, 1.0, std::nullopt, 0, std::nullopt});
  const std::string message = test::ConfigErrorOf([&] { BuildStructureModel(s); });
  CHECK_THAT(message, Catch::Contains("'structure.nodes[4]'") && Catch::Contains("node 5") &&
                          Catch::Contains("needs mass"));
  s.node_masses.push_back({5, 0.1});
  CHECK_NOTHROW(BuildStructureModel(s));
}

TEST_CASE("structure run: the undamped D-bar conserves energy") {
  const Config c = Scene("motes_dbar");
  const DynamicModel m = ModelOf(c);
  const SimulationResult r = Simulate(m, *c.dynamics);
  CHECK(r.summary.engine == "classk");
  CHECK(r.summary.energy.dissipated == 0.0);  // c = 0 on both strings
  INFO("max drift " << r.summary.energy.max_drift);
  // RK4 at dt = 1e-3 s on motion of a few rad/s (linearised 2.7 and 7.2 rad/s) drifts by
  // O((omega dt)^4) per period: 4e-8 of the initial energy over 5 s with 9 slack
  // transitions; 1e-6 leaves room for compilers and flags while any lost constraint or
  // sign error in a force would show at 1e-2 or more.
  CHECK(r.summary.energy.max_drift < 1e-6);
  CHECK(r.summary.max_bar_length_error < 1e-8);  // RK4 drift of the held lengths, 4e-10 seen
}

TEST_CASE("structure run: the damped prism loses mechanical energy at every sample") {
  Config c = Scene("motes_prism");
  const DynamicModel m = ModelOf(c);
  double previous = 0;
  for (int k = 1; k <= 10; ++k) {
    c.dynamics->duration = 0.5 * k;  // the same RK4 steps, stopped 0.5 s later each time
    const EnergyBalance e = Simulate(m, *c.dynamics).summary.energy;
    if (k == 1) previous = e.kinetic_start + e.elastic_start;
    INFO("t = " << c.dynamics->duration << " s: " << Mechanical(e) << " J after " << previous
                << " J");
    // Strict: the smallest loss over 0.5 s (3.5-4 s, most strings slack) is 2.6e-4 J.
    CHECK(Mechanical(e) < previous);
    CHECK(e.dissipated > 0);
    // The balance kinetic + elastic + dissipated = initial closes to RK4's accuracy across the
    // 66 slack kinks: 6.5e-5 of the initial 1.125 J seen (motes_peer_test.cc compares it with
    // the undamped prism's).
    CHECK(e.max_drift < 2e-4);
    previous = Mechanical(e);
  }
}

TEST_CASE("structure run: class-1 and class-k engines agree on the prism") {
  Config c = Scene("motes_prism");
  c.dynamics->duration = 2;
  const DynamicModel m = ModelOf(c);
  c.dynamics->engine = EngineKind::kClass1;
  const SimulationResult a = Simulate(m, *c.dynamics);
  c.dynamics->engine = EngineKind::kClassK;
  const SimulationResult b = Simulate(m, *c.dynamics);
  REQUIRE(a.history.rows() == b.history.rows());
  const double gap = (a.history - b.history).cwiseAbs().maxCoeff();
  INFO("largest position difference " << gap << " m");
  // Both engines solve the same equations exactly (class k with no shared node is the class-1
  // closed form); 4e-14 m seen after 2 s of slack chatter, so 1e-9 m flags any real change.
  CHECK(gap < 1e-9);
}

}  // namespace
}  // namespace tbridge
