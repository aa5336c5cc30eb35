// `tbridge check` of a design under loads it was not designed for (io/design_loads.h): the
// bridge as designed (members, rest lengths, deck plates) read back from its file with an edited
// payload or superimposed dead load, and checked under them.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

#include "checks/verdict.h"
#include "design/design.h"
#include "io/design_loads.h"
#include "io/design_reader.h"
#include "io/design_report.h"
#include "sizing/verified_design.h"

namespace tbridge {
namespace {

using json = nlohmann::json;

json FileOf(const Design& d) {
  std::ostringstream text;
  WriteDesignJson(d, text);
  return json::parse(text.str());
}

// The largest utilisation of the members the static check found.
double LargestStatic(const Design& d) {
  double out = 0;
  for (const MemberFinding& f : d.statics.members) out = std::max(out, f.utilisation);
  return out;
}

// The total vertical load of one base action over the nodes [N].
double Total(const Design& d, BaseAction action) { return d.actions.base[action].row(1).sum(); }

TEST_CASE("check of a design with a payload 20 % higher reports the bridge as designed under it",
          "[verify]") {
  // A crowd of 3.3 kPa on the default's 12 m x 1.5 m deck, so that the payload governs its members
  // (the default's 12 kN leaves the travelling load Q_t governing them) and its deck plates.
  Config config;
  config.bridge.n = 2;
  config.bridge.payload = 60000;
  config.comfort.check = false;  // not what is tested, and the run is shorter
  const Design designed = DesignAndVerify(config);
  REQUIRE(DesignVerdict(designed).pass);
  const json file = FileOf(designed);
  REQUIRE(file.at("designed_for").at("bridge.payload") == config.bridge.payload);
  REQUIRE(file.at("loads_changed").empty());

  // Checked under the loads it was designed for, it passes as it did.
  Design same = ReadDesign(file);
  CHECK_FALSE(same.designed_for.has_value());
  CheckAgain(same);
  CHECK(DesignVerdict(same).pass);

  json edited = file;
  edited["config"]["bridge"]["payload"] = 1.2 * config.bridge.payload;
  Design d = ReadDesign(edited);
  REQUIRE(d.designed_for.has_value());
  const std::vector<std::string> changed = ChangedLoads(*d.designed_for, d.config);
  REQUIRE(changed.size() == 1);
  CHECK(changed[0] == "bridge.payload 60000 N -> 72000 N");
  // As designed: the deck plates sized for 60 kN, the members and their reference forces as
  // written (the payload is no part of the permanent load, so nothing is re-derived).
  CHECK(d.deck.thickness == designed.deck.thickness);
  CHECK_FALSE(d.as_built.re_derived);
  for (size_t k = 0; k < d.strings.size(); ++k)
    CHECK(d.strings[k].rest_length == designed.strings[k].rest_length);
  // The payload's actions are the new payload's: the node loads scale with it exactly (the share
  // that goes straight to the supports is the same fraction); the deck's own load is unchanged.
  CHECK(Total(d, kPayloadFull) == Approx(1.2 * Total(designed, kPayloadFull)).epsilon(1e-12));
  CHECK(Total(d, kDeckDead) == Approx(Total(designed, kDeckDead)).epsilon(1e-12));

  CheckAgain(d);
  INFO(DesignVerdict(d).summary);
  // The bridge was sized to utilisation 0.9999 under its own payload: 20 % more puts its members
  // over (the payload's share of the demand grows by a fifth), and the verdict says so.
  CHECK(LargestStatic(d) > LargestStatic(same));
  CHECK(LargestStatic(d) > 1.0);
  CHECK_FALSE(DesignVerdict(d).pass);
  // The deck plates, as designed, are checked again under the new payload: under the full
  // payload the same plate sags in proportion to its line load (5 p l^4 / (384 E I), to
  // rounding), and past its limit (sized by the travelling load's sag, at 0.9999 of it).
  const auto full = [](const Design& x) {
    for (const LoadCase& c : x.cases) {
      if (c.name == "sls_payload_full") return c;
    }
    FAIL("no sls_payload_full case");
    return LoadCase{};
  };
  const double sag_now = CheckDeckBeams(d.config, d.deck, {full(d)}).sag_m;
  const double sag_before = CheckDeckBeams(same.config, same.deck, {full(same)}).sag_m;
  CHECK(sag_now / sag_before ==
        Approx(DeckBeamLoadOf(full(d), d.config, d.deck).vertical_n_per_m /
               DeckBeamLoadOf(full(same), same.config, same.deck).vertical_n_per_m)
            .epsilon(1e-12));
  CHECK(sag_now > sag_before);
  CHECK(DesignVerdict(same).deck_beams.SagRatio() <= 1 + 1e-9);
  CHECK(DesignVerdict(d).deck_beams.SagRatio() > 1);
  CHECK(DesignVerdict(d).deck_beams.sag_case == "sls_payload_full");

  // Its file says what changed and keeps what it was designed for; it reads back the same.
  const json out = FileOf(d);
  CHECK(out.at("designed_for") == file.at("designed_for"));
  CHECK(out.at("loads_changed") == json(changed));
  CHECK(out.at("config").at("bridge").at("payload") == 1.2 * config.bridge.payload);
  const Design again = ReadDesign(out);
  REQUIRE(again.designed_for.has_value());
  CHECK(ChangedLoads(*again.designed_for, again.config) == changed);
  CHECK_THAT(DesignSummary(d),
             Catch::Contains("loads changed from those designed for: bridge.payload"));
}

TEST_CASE("check under a heavier superimposed dead load re-derives the state as built",
          "[verify]") {
  Config config;
  config.bridge.n = 2;
  config.comfort.check = false;
  const Design designed = RunDesign(config);
  json edited = FileOf(designed);
  edited["config"]["loads"]["superimposed_dead_n_per_m"] = 500.0;
  const Design d = ReadDesign(edited);
  REQUIRE(d.designed_for.has_value());
  // The permanent load changed: the reference forces as written no longer balance it, so the
  // state the bridge carries as built is solved again from its rest lengths.
  CHECK(d.as_built.re_derived);
  CHECK(d.deck.thickness == designed.deck.thickness);
  CHECK(Total(d, kDeckDead) < Total(designed, kDeckDead));  // downward: more negative
}

TEST_CASE("a design file's record of its loads is read strictly", "[verify]") {
  Config config;
  config.bridge.n = 1;
  const json file = FileOf(RunDesign(config));
  json bad = file;
  bad["designed_for"]["bridge.span"] = 20.0;
  CHECK_THROWS_WITH(ReadDesign(bad), Catch::Contains("designed_for.bridge.span") &&
                                         Catch::Contains("not a load key"));
  bad = file;
  bad["designed_for"]["bridge.payload"] = "12 kN";
  CHECK_THROWS_WITH(ReadDesign(bad), Catch::Contains("designed_for.bridge.payload"));
  // The paper's one case ties the deck's load to the payload: not checked under another.
  Config paper = config;
  ApplyPaperSwitches(paper);
  json p = FileOf(RunDesign(paper));
  p["config"]["bridge"]["payload"] = 2 * config.bridge.payload;
  CHECK_THROWS_WITH(ReadDesign(p),
                    Catch::Contains("config.bridge.payload") && Catch::Contains("tbridge design"));
}

}  // namespace
}  // namespace tbridge
