// The one description of the bridge, material and design keys (core/config_fields.h) against
// what the parse accepts, what the echo writes, what Validate() refuses and what
// configs/README.md documents.
#include "core/config_fields.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "core/config.h"
#include "core/error.h"

namespace tbridge {
namespace {

using nlohmann::json;

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The keys of one Markdown table in the README: the first column of each row after the
// heading `## `section``, read from the README text itself (not from the description).
std::vector<std::string> ReadmeKeys(const std::string& readme, const std::string& section) {
  const size_t start = readme.find("## `" + section + "`");
  REQUIRE(start != std::string::npos);
  const size_t end = readme.find("\n## ", start + 1);
  const std::string part = readme.substr(start, end - start);
  std::vector<std::string> keys;
  const std::regex row(R"(\n\| `([a-z_]+)` \|)");
  for (std::sregex_iterator it(part.begin(), part.end(), row), stop; it != stop; ++it) keys.push_back((*it)[1]);
  return keys;
}

// For each described key: its name, and a value just outside its allowed range (or not
// allowed at all) together with a setter that puts that value into a config built in code.
struct OutOfRange {
  std::string name;
  json bad_json;
  std::function<void(Config&)> set_bad;
};

// Puts `value` into the one field named `target`.
template <class T>
struct Setter {
  const std::string& target;
  const T& value;
  void Number(const KeyInfo& k, double& f, Range) { Put(k, f); }
  void Integer(const KeyInfo& k, int& f, int, int) { Put(k, f); }
  void Choice(const KeyInfo& k, std::string& f, const std::vector<std::string>&) { Put(k, f); }
  template <class F>
  void Put(const KeyInfo& k, F& f) {
    if constexpr (std::is_convertible_v<T, F>) {
      if (target == k.name) f = static_cast<F>(value);
    }
  }
};

template <class Section>
struct Collect {
  std::string section;
  Section Config::*member;
  std::vector<OutOfRange> keys;
  void Number(const KeyInfo& key, double&, Range range) {
    // Above the upper end, or below the lower one when unbounded above (every range here has
    // one finite end); open ends are themselves outside.
    const double bad = std::isfinite(range.hi) ? (range.hi_open ? range.hi : std::nextafter(range.hi, 1e300))
                                               : (range.lo_open ? range.lo : std::nextafter(range.lo, -1e300));
    Add(key, bad);
  }
  void Integer(const KeyInfo& key, int&, int, int hi) { Add(key, hi + 1); }
  void Choice(const KeyInfo& key, std::string&, const std::vector<std::string>&) { Add(key, std::string("cplex")); }
  template <class T>
  void Add(const KeyInfo& key, T bad) {
    const std::string name = key.name;
    Section Config::*m = member;
    auto set = [m, name, bad](Config& c) {
      Setter<T> setter{name, bad};
      DescribeFields(c.*m, setter);
    };
    keys.push_back({section + "." + name, json(bad), set});
  }
};

template <class Section>
std::vector<OutOfRange> KeysOf(const std::string& section, Section Config::*member) {
  Config c;
  Collect<Section> collect{section, member, {}};
  DescribeFields(c.*member, collect);
  return collect.keys;
}

TEST_CASE("parse, echo, Validate and the README agree on every described key", "[config][fields]") {
  const std::string readme = ReadFile(std::string(TBRIDGE_SOURCE_DIR) + "/configs/README.md");
  std::vector<std::pair<std::string, std::vector<OutOfRange>>> sections = {
      {"bridge", KeysOf("bridge", &Config::bridge)},
      {"material", KeysOf("material", &Config::material)},
      {"design", KeysOf("design", &Config::design)}};
  const json echo = ToJson(ParseConfig(json::parse(R"({"bridge": {"n": 3}})")));
  // The echo reads back to itself: the parse accepts every key the echo writes, at its value.
  CHECK(ToJson(ParseConfig(echo)) == echo);
  for (const auto& [section, keys] : sections) {
    INFO("section " << section);
    // The README's table, as written there, is the table the description gives.
    const SectionInfo& info = section == "bridge" ? kBridgeSection : section == "material" ? kMaterialSection
                                                                                          : kDesignSection;
    CHECK(readme.find(ConfigSectionText(info)) != std::string::npos);
    // Its keys, read from the README's own rows, are the echo's keys, in the same order as
    // the description (the echo is a JSON object: compared as sets).
    std::vector<std::string> described;
    for (const OutOfRange& k : keys) described.push_back(k.name.substr(section.size() + 1));
    CHECK(ReadmeKeys(readme, section) == described);
    std::set<std::string> echoed;
    for (const auto& [key, value] : echo.at(section).items()) echoed.insert(key);
    CHECK(echoed == std::set<std::string>(described.begin(), described.end()));
    for (const OutOfRange& k : keys) {
      INFO("key " << k.name << " = " << k.bad_json.dump());
      const std::string key = k.name.substr(section.size() + 1);
      // Out of range in a file: the parse names the key.
      json bad = {{"bridge", {{"n", 3}}}};
      bad[section][key] = k.bad_json;
      try {
        ParseConfig(bad);
        FAIL("the parse accepted " << k.bad_json.dump());
      } catch (const ConfigError& e) {
        CHECK(e.key() == k.name);
      }
      // Out of range in code: Validate names the same key.
      Config c;
      c.bridge.n = 3;
      k.set_bad(c);
      try {
        Validate(c);
        FAIL("Validate accepted " << k.bad_json.dump());
      } catch (const ConfigError& e) {
        CHECK(e.key() == k.name);
      }
    }
  }
}

TEST_CASE("Validate: a default config passes, the rule across bridge keys holds in code too", "[config][fields]") {
  Config c;
  CHECK_NOTHROW(Validate(c));
  c.bridge.planes = 2;
  c.bridge.p = 2;
  try {
    Validate(c);
    FAIL("p = 2 with planes = 2 accepted");
  } catch (const ConfigError& e) {
    CHECK(e.key() == "bridge.p");
    CHECK_THAT(e.what(), Catch::Contains("planes = 2"));
  }
}

}  // namespace
}  // namespace tbridge
