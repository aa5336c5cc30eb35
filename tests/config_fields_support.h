// Holds one described config section (core/config_visitors.h) to what the parse accepts, what
// the echo writes, what Validate() refuses and what configs/README.md documents, key by key.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "core/config_visitors.h"
#include "core/error.h"

namespace tbridge::test {

inline std::string ReadmeText() {
  std::ifstream in(std::string(TBRIDGE_SOURCE_DIR) + "/configs/README.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The README's part under the heading of `section`, up to the next heading.
inline std::string ReadmePart(const std::string& readme, const std::string& section) {
  const size_t start = readme.find("## `" + section + "`");
  REQUIRE(start != std::string::npos);
  return readme.substr(start, readme.find("\n## ", start + 1) - start);
}

// The keys of the section's Markdown table, read from the README's own rows (the first
// column), not from the description.
inline std::vector<std::string> ReadmeKeys(const std::string& part) {
  std::vector<std::string> keys;
  const std::regex row(R"(\n\| `([A-Za-z_0-9.\[\]]+)` \|)");
  for (std::sregex_iterator it(part.begin(), part.end(), row), stop; it != stop; ++it)
    keys.push_back((*it)[1]);
  return keys;
}

// A value just outside `range`: above its upper end, or below the lower one when unbounded
// above (every range here has one finite end); open ends are themselves outside.
inline double OutsideOf(Range range) {
  return std::isfinite(range.hi) ? (range.hi_open ? range.hi : std::nextafter(range.hi, 1e300))
                                 : (range.lo_open ? range.lo : std::nextafter(range.lo, -1e300));
}

// One described key of a section: its path in the section ("loads[0].t_start"), a value it
// does not allow and where in that value the error points ("" or "[1]").
struct BadKey {
  std::string path;
  nlohmann::json bad;
  std::string at;
};

// Collects every key of a section as the README rows name it ("loads[].t_start", lists
// included) and, except for bools, as a BadKey; list keys are visited at element 0.
struct CollectKeys {
  std::string prefix, row;
  std::vector<std::string>* rows;
  std::vector<BadKey>* keys;
  CollectKeys At(const std::string& p, const std::string& r) const { return {p, r, rows, keys}; }
  void Add(const KeyInfo& key, const nlohmann::json& bad, const std::string& at) {
    rows->push_back(row + key.name);
    keys->push_back({prefix + key.name, bad, at});
  }
  void Number(const KeyInfo& key, double, Range range) { Add(key, OutsideOf(range), ""); }
  template <class I>
  void Integer(const KeyInfo& key, I, std::type_identity_t<I>, std::type_identity_t<I> hi) {
    Add(key, hi + 1, "");
  }
  void Bool(const KeyInfo& key, bool) { rows->push_back(row + key.name); }
  void Choice(const KeyInfo& key, const std::string&, const std::vector<std::string>&) {
    Add(key, "cplex", "");
  }
  void Text(const KeyInfo& key, const std::string&) { Add(key, "", ""); }
  void Choices(const KeyInfo& key, const std::vector<std::string>&,
               const std::vector<std::string>&) {
    Add(key, {"cplex"}, "[0]");
  }
  void OptionalNumber(const KeyInfo& key, const std::optional<double>&, Range range, Absent) {
    Add(key, OutsideOf(range), "");
  }
  void NumberOrAuto(const KeyInfo& key, double, bool, Range range) {
    Add(key, OutsideOf(range), "");
  }
  void Integers(const KeyInfo& key, const std::vector<int>&, int, int hi) {
    Add(key, {hi + 1}, "[0]");
  }
  void Numbers(const KeyInfo& key, const std::vector<double>&, Range range) {
    Add(key, {OutsideOf(range)}, "[0]");
  }
  void Vector3(const KeyInfo& key, const std::array<double, 3>&) {
    Add(key, {std::numeric_limits<double>::quiet_NaN(), 0, 0}, "[0]");
  }
  void Points(const KeyInfo& key, const std::vector<std::array<double, 3>>&, int) {
    Add(key, nlohmann::json::array(), "");
  }
  void NodePair(const KeyInfo& key, const std::array<int, 2>&, int n_nodes) {
    Add(key, {1, n_nodes + 1}, "[1]");
  }
  template <class T>
  void Section(const char* name, const T& field) {
    CollectKeys v = At(prefix + name + ".", row + name + ".");
    DescribeFields(field, v);
  }
  template <class T, class D>
  void List(const KeyInfo& key, const std::vector<T>& field, D describe) {
    rows->push_back(row + key.name);
    REQUIRE(!field.empty());  // the full section has an element in every list
    CollectKeys v = At(prefix + key.name + "[0].", row + key.name + "[].");
    describe(field[0], v);
  }
};

// Puts `value` into the one field whose path is `target`.
struct SetKey {
  std::string prefix;
  const std::string& target;
  const nlohmann::json& value;
  template <class F>
  void Put(const KeyInfo& key, F& field) {
    if (prefix + key.name == target) field = value.get<F>();
  }
  void Number(const KeyInfo& key, double& f, Range) { Put(key, f); }
  template <class I>
  void Integer(const KeyInfo& key, I& f, std::type_identity_t<I>, std::type_identity_t<I>) {
    Put(key, f);
  }
  void Bool(const KeyInfo&, bool&) {}
  void Choice(const KeyInfo& key, std::string& f, const std::vector<std::string>&) { Put(key, f); }
  void Text(const KeyInfo& key, std::string& f) { Put(key, f); }
  void Choices(const KeyInfo& key, std::vector<std::string>& f, const std::vector<std::string>&) {
    Put(key, f);
  }
  void OptionalNumber(const KeyInfo& key, std::optional<double>& f, Range, Absent) {
    if (prefix + key.name == target) f = value.get<double>();
  }
  void NumberOrAuto(const KeyInfo& key, double& f, bool& is_auto, Range) {
    if (prefix + key.name == target) f = value.get<double>(), is_auto = false;
  }
  void Integers(const KeyInfo& key, std::vector<int>& f, int, int) { Put(key, f); }
  void Numbers(const KeyInfo& key, std::vector<double>& f, Range) { Put(key, f); }
  void Vector3(const KeyInfo& key, std::array<double, 3>& f) { Put(key, f); }
  void Points(const KeyInfo& key, std::vector<std::array<double, 3>>& f, int) { Put(key, f); }
  void NodePair(const KeyInfo& key, std::array<int, 2>& f, int) { Put(key, f); }
  template <class T>
  void Section(const char* name, T& field) {
    SetKey v{prefix + name + ".", target, value};
    DescribeFields(field, v);
  }
  template <class T, class D>
  void List(const KeyInfo& key, std::vector<T>& field, D describe) {
    SetKey v{prefix + key.name + "[0].", target, value};
    describe(field[0], v);
  }
};

// "loads[0].t_start" as a JSON pointer, "/loads/0/t_start".
inline nlohmann::json::json_pointer PointerOf(const std::string& path) {
  std::string pointer = "/";
  for (const char c : path) {
    if (c == '.' || c == '[') {
      pointer += '/';
    } else if (c != ']') {
      pointer += c;
    }
  }
  return nlohmann::json::json_pointer(pointer);
}

// Whether the echo `j` has the README row `row` ("loads[].t_start": in some element).
inline bool EchoHas(const nlohmann::json& j, const std::string& row) {
  const size_t dot = row.find('.');
  const std::string head = row.substr(0, dot);
  if (head.size() > 2 && head.substr(head.size() - 2) == "[]") {
    const std::string list = head.substr(0, head.size() - 2);
    if (!j.contains(list)) return false;
    for (const nlohmann::json& e : j[list]) {
      if (EchoHas(e, row.substr(dot + 1))) return true;
    }
    return false;
  }
  if (!j.contains(head)) return false;
  return dot == std::string::npos || EchoHas(j[head], row.substr(dot + 1));
}

// What a ConfigError's message says is allowed: the part after "'key' = value: ".
inline std::string AllowedPart(const std::string& message) {
  const size_t value = message.find("' = ");
  return message.substr(message.find(": ", value) + 2);
}

// The ConfigError that `f` throws; fails the test when it throws none.
template <class F>
ConfigError ErrorOf(F f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e;
  }
  FAIL("accepted, no ConfigError");
  return ConfigError("");
}

// One section under test: `full` has every key given and one element in each list; `parse`
// reads the section's JSON inside a whole config, `validate` checks a section built in code
// inside a whole config.
template <class S>
struct DescribedSection {
  const SectionInfo& info;
  std::string text;  // ConfigSectionText or SweepSectionText
  S full;
  std::function<S(const nlohmann::json&)> parse;
  std::function<void(const S&)> validate;
};

// For every key: the README's table lists exactly the described keys; the echo has it and
// reads back to itself; a value out of range is refused by the parse and by Validate, naming
// the same key with the same allowed-part.
template <class S>
void CheckDescribedSection(const DescribedSection<S>& s, const std::string& readme) {
  INFO("section " << s.info.name);
  const std::string heading = SectionHeading(s.info);
  REQUIRE(s.text.substr(0, heading.size() + 1) == heading + "\n");
  const std::string part = ReadmePart(readme, s.info.name);
  CHECK(part.substr(0, heading.size()) == heading);
  CHECK(part.find(s.text.substr(heading.size() + 1)) != std::string::npos);

  std::vector<std::string> rows;
  std::vector<BadKey> keys;
  CollectKeys collect{"", "", &rows, &keys};
  DescribeFields(s.full, collect);
  CHECK(ReadmeKeys(part) == rows);

  const nlohmann::json echo = EchoFields(s.full);
  CHECK(EchoFields(s.parse(echo)) == echo);
  for (const std::string& row : rows) {
    INFO("row " << row);
    CHECK(EchoHas(echo, row));
  }
  for (const BadKey& k : keys) {
    const std::string name = std::string(s.info.name) + "." + k.path + k.at;
    INFO("key " << name << " = " << k.bad.dump());
    nlohmann::json bad = echo;
    bad[PointerOf(k.path)] = k.bad;
    const ConfigError parsed = ErrorOf([&] { s.parse(bad); });
    CHECK(parsed.key() == name);
    S config = s.full;
    SetKey set{"", k.path, k.bad};
    DescribeFields(config, set);
    const ConfigError validated = ErrorOf([&] { s.validate(config); });
    CHECK(validated.key() == name);
    CHECK(AllowedPart(validated.what()) == AllowedPart(parsed.what()));
  }
}

}  // namespace tbridge::test
