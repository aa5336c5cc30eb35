// The visitors that turn one description of a config section into its strict parse, its
// echo, Validate() for configs built in code and its README key table. A section is described
// by a `DescribeFields(section_struct, visitor)` overload (core/config_fields.h,
// core/dynamics_fields.h, core/structure_fields.h, sweep/sweep_fields.h) that calls the
// visitor once per key, in the order the keys are parsed and listed. The protocol, with
// `field` a (const) reference into the config and `key` a KeyInfo:
//   v.Number(key, double, range)                  finite, in `range`
//   v.Integer(key, I, lo, hi)                     I = int or long, in [lo, hi]
//   v.Bool(key, bool)
//   v.Choice(key, std::string, allowed)           one of `allowed`
//   v.Text(key, std::string)                      a non-empty name (a group's, a case's)
//   v.Choices(key, std::vector<std::string>, allowed)  each one of `allowed`, none twice
//   v.OptionalNumber(key, std::optional<double>, range, absent)
//                                                 absent = off; Absent::kNull also reads and
//                                                 echoes null as off, kOmitted leaves it out
//   v.NumberOrAuto(key, double, bool is_auto, range)  finite, in `range`, or the string
//                                                 "auto" (is_auto set, the number kept)
//   v.Integers(key, std::vector<int>, lo, hi)     each in [lo, hi]
//   v.Numbers(key, std::vector<double>, range)    each in `range`
//   v.Vector3(key, std::array<double, 3>)         [x, y, z], finite
//   v.Points(key, std::vector<std::array<double, 3>>, max)   1 to `max` finite [x, y, z]
//   v.NodePair(key, std::array<int, 2>, n_nodes)  two node numbers [i, j] in [1, n_nodes]
//   v.Section(name, nested)                       the nested struct's own DescribeFields
//   v.List(key, std::vector<T>, describe)         a list of objects, each described by
//                                                 describe(element, visitor)
// A key's default is the struct member's initial value unless `key.required`. Rules across
// keys are not visited: each section states them in its SectionInfo and checks them in one
// function that both its parse and Validate() call.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

struct KeyInfo {
  const char* name;
  const char* unit;       // "–" for a pure number
  const char* what;       // what it controls, as the README's table shows it (Markdown)
  bool required = false;  // no default: the key must be given
  // The README's "allowed" and "default" cells where the range or the struct's initial value
  // alone would not say it (a bound that is the node count, a default taken from another key).
  const char* allowed = nullptr;
  const char* fallback = nullptr;
};

// One section: its key in the config, the README heading after the key, and the rules
// across its keys (checked by one function per section, stated here once for the README).
struct SectionInfo {
  const char* name;
  const char* title;
  const char* rules;  // "" when none
};

// What an absent optional number looks like in the file and in the echo.
enum class Absent { kNull, kOmitted };

// describe(element, visitor) for list elements that have a DescribeFields of their own.
struct Described {
  template <class T, class V>
  void operator()(T& element, V& v) const {
    DescribeFields(element, v);
  }
};

// Reads every described key of a section from JSON, strictly; a key's current value (the
// struct's default) is its fallback unless the key is required.
struct ParseVisitor {
  JsonSection& s;
  template <class T>
  static std::optional<T> Fallback(const KeyInfo& key, const T& field) {
    return key.required ? std::nullopt : std::optional<T>(field);
  }
  void Number(const KeyInfo& key, double& field, Range range) {
    field = s.Number(key.name, Fallback(key, field), range);
  }
  template <class I>
  void Integer(const KeyInfo& key, I& field, std::type_identity_t<I> lo,
               std::type_identity_t<I> hi) {
    field = static_cast<I>(s.Integer64(key.name, Fallback<long long>(key, field), lo, hi));
  }
  void Bool(const KeyInfo& key, bool& field) { field = s.Bool(key.name, Fallback(key, field)); }
  void Choice(const KeyInfo& key, std::string& field, const std::vector<std::string>& allowed) {
    field = s.Choice(key.name, Fallback(key, field), allowed);
  }
  void Text(const KeyInfo& key, std::string& field) {
    field = s.Text(key.name, Fallback(key, field));
  }
  void Choices(const KeyInfo& key, std::vector<std::string>& field,
               const std::vector<std::string>& allowed);
  void OptionalNumber(const KeyInfo& key, std::optional<double>& field, Range range,
                      Absent absent) {
    if (!s.Has(key.name)) return;
    if (absent == Absent::kNull && s.Raw(key.name)->is_null()) {
      field.reset();
      return;
    }
    field = s.Number(key.name, std::nullopt, range);
  }
  void NumberOrAuto(const KeyInfo& key, double& field, bool& is_auto, Range range) {
    const nlohmann::json* raw = s.Has(key.name) ? s.Raw(key.name) : nullptr;
    if (raw != nullptr && raw->is_string()) {
      if (*raw != "auto") {
        throw ConfigError(s.PathOf(key.name), Show(*raw),
                          "must be a number, " + range.Describe() + ", or \"auto\"");
      }
      is_auto = true;
      return;
    }
    is_auto = false;
    Number(key, field, range);
  }
  void Integers(const KeyInfo& key, std::vector<int>& field, int lo, int hi) {
    field = s.Integers(key.name, Fallback(key, field), lo, hi);
  }
  void Numbers(const KeyInfo& key, std::vector<double>& field, Range range) {
    field = s.Numbers(key.name, Fallback(key, field), range);
  }
  void Vector3(const KeyInfo& key, std::array<double, 3>& field) {
    field = s.Vector3(key.name, Fallback(key, field));
  }
  void Points(const KeyInfo& key, std::vector<std::array<double, 3>>& field, int max);
  void NodePair(const KeyInfo& key, std::array<int, 2>& field, int n_nodes);
  template <class T>
  void Section(const char* name, T& field) {
    JsonSection nested = s.Section(name);
    ParseVisitor v{nested};
    DescribeFields(field, v);
    nested.Finish();
  }
  template <class T, class D>
  void List(const KeyInfo& key, std::vector<T>& field, D describe) {
    field = ObjectList<T>(s, key.name, [&](JsonSection element) {
      T t;
      ParseVisitor v{element};
      describe(t, v);
      element.Finish();
      return t;
    });
  }
};

// Writes every described key of a section into a JSON object: the echo.
struct EchoVisitor {
  nlohmann::json& out;
  template <class T>
  void Put(const KeyInfo& key, const T& field) {
    out[key.name] = field;
  }
  void Number(const KeyInfo& key, double field, Range) { Put(key, field); }
  template <class I>
  void Integer(const KeyInfo& key, const I& field, std::type_identity_t<I>,
               std::type_identity_t<I>) {
    Put(key, field);
  }
  void Bool(const KeyInfo& key, bool field) { Put(key, field); }
  void Choice(const KeyInfo& key, const std::string& field, const std::vector<std::string>&) {
    Put(key, field);
  }
  void Text(const KeyInfo& key, const std::string& field) { Put(key, field); }
  void Choices(const KeyInfo& key, const std::vector<std::string>& field,
               const std::vector<std::string>&) {
    Put(key, field);
  }
  void OptionalNumber(const KeyInfo& key, const std::optional<double>& field, Range,
                      Absent absent) {
    if (field) {
      Put(key, *field);
    } else if (absent == Absent::kNull) {
      out[key.name] = nullptr;
    }
  }
  void NumberOrAuto(const KeyInfo& key, double field, bool is_auto, Range) {
    if (is_auto) {
      out[key.name] = "auto";
    } else {
      Put(key, field);
    }
  }
  void Integers(const KeyInfo& key, const std::vector<int>& field, int, int) { Put(key, field); }
  void Numbers(const KeyInfo& key, const std::vector<double>& field, Range) { Put(key, field); }
  void Vector3(const KeyInfo& key, const std::array<double, 3>& field) { Put(key, field); }
  void Points(const KeyInfo& key, const std::vector<std::array<double, 3>>& field, int) {
    Put(key, field);
  }
  void NodePair(const KeyInfo& key, const std::array<int, 2>& field, int) { Put(key, field); }
  template <class T>
  void Section(const char* name, const T& field) {
    nlohmann::json nested = nlohmann::json::object();
    EchoVisitor v{nested};
    DescribeFields(field, v);
    out[name] = nested;
  }
  template <class T, class D>
  void List(const KeyInfo& key, const std::vector<T>& field, D describe) {
    nlohmann::json list = nlohmann::json::array();
    for (const T& element : field) {
      nlohmann::json object = nlohmann::json::object();
      EchoVisitor v{object};
      describe(element, v);
      list.push_back(object);
    }
    out[key.name] = list;
  }
};

// Checks every described key of a section built in code against its range, with the messages
// the parse gives for the same value. `prefix` is the key path up to the section's keys
// ("dynamics.", "structure.strings[2].").
struct ValidateVisitor {
  std::string prefix;
  std::string Path(const KeyInfo& key) const { return prefix + key.name; }
  static std::string Item(const std::string& path, std::size_t k) {
    return path + "[" + std::to_string(k) + "]";
  }
  static void CheckNumber(const std::string& path, double field, Range range) {
    if (!std::isfinite(field) || !range.Contains(field)) {
      throw ConfigError(path, NumberText(field), range.Refusal(field));
    }
  }
  static void CheckInteger(const std::string& path, long long field, long long lo, long long hi) {
    if (field < lo || field > hi)
      throw ConfigError(path, std::to_string(field), "must be " + IntegerRangeText(lo, hi));
  }
  void Number(const KeyInfo& key, double field, Range range) const {
    CheckNumber(Path(key), field, range);
  }
  template <class I>
  void Integer(const KeyInfo& key, const I& field, std::type_identity_t<I> lo,
               std::type_identity_t<I> hi) const {
    CheckInteger(Path(key), field, lo, hi);
  }
  void Bool(const KeyInfo&, bool) const {}
  void Choice(const KeyInfo& key, const std::string& field,
              const std::vector<std::string>& allowed) const {
    if (std::find(allowed.begin(), allowed.end(), field) == allowed.end()) {
      throw ConfigError(Path(key), "\"" + Printable(field) + "\"",
                        "must be one of " + ChoiceText(allowed));
    }
  }
  void Choices(const KeyInfo& key, const std::vector<std::string>& field,
               const std::vector<std::string>& allowed) const {
    CheckChoices(Path(key), field, allowed);
  }
  void Text(const KeyInfo& key, const std::string& field) const {
    if (field.empty()) throw ConfigError(Path(key), "\"\"", "must be a non-empty string");
  }
  // Each of `list` one of `allowed`, and none twice (a repeated case would be checked twice).
  static void CheckChoices(const std::string& path, const std::vector<std::string>& list,
                           const std::vector<std::string>& allowed);
  void OptionalNumber(const KeyInfo& key, const std::optional<double>& field, Range range,
                      Absent) const {
    if (field) CheckNumber(Path(key), *field, range);
  }
  void NumberOrAuto(const KeyInfo& key, double field, bool is_auto, Range range) const {
    if (!is_auto) CheckNumber(Path(key), field, range);
  }
  void Integers(const KeyInfo& key, const std::vector<int>& field, int lo, int hi) const {
    for (std::size_t k = 0; k < field.size(); ++k)
      CheckInteger(Item(Path(key), k), field[k], lo, hi);
  }
  void Numbers(const KeyInfo& key, const std::vector<double>& field, Range range) const {
    for (std::size_t k = 0; k < field.size(); ++k) CheckNumber(Item(Path(key), k), field[k], range);
  }
  void Vector3(const KeyInfo& key, const std::array<double, 3>& field) const {
    for (std::size_t k = 0; k < 3; ++k) CheckNumber(Item(Path(key), k), field[k], Range());
  }
  void Points(const KeyInfo& key, const std::vector<std::array<double, 3>>& field, int max) const;
  void NodePair(const KeyInfo& key, const std::array<int, 2>& field, int n_nodes) const {
    for (std::size_t k = 0; k < 2; ++k) CheckInteger(Item(Path(key), k), field[k], 1, n_nodes);
  }
  template <class T>
  void Section(const char* name, const T& field) const {
    ValidateVisitor v{prefix + name + "."};
    DescribeFields(field, v);
  }
  template <class T, class D>
  void List(const KeyInfo& key, const std::vector<T>& field, D describe) const {
    for (std::size_t k = 0; k < field.size(); ++k) {
      ValidateVisitor v{Item(Path(key), k) + "."};
      describe(field[k], v);
    }
  }
};

// One Markdown row per key: | `key` | unit | default | allowed | what it controls |, nested
// keys as `section.key`, keys of list elements as `list[].key`.
struct TableVisitor {
  std::string prefix;
  std::string rows;
  void Row(const KeyInfo& key, const std::string& fallback, const std::string& allowed);
  void Number(const KeyInfo& key, double field, Range range) {
    Row(key, NumberText(field), range.Interval());
  }
  template <class I>
  void Integer(const KeyInfo& key, const I& field, std::type_identity_t<I> lo,
               std::type_identity_t<I> hi) {
    Row(key, std::to_string(field),
        "integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  void Bool(const KeyInfo& key, bool field) { Row(key, field ? "true" : "false", "true or false"); }
  void Choice(const KeyInfo& key, const std::string& field,
              const std::vector<std::string>& allowed);
  void Choices(const KeyInfo& key, const std::vector<std::string>& field,
               const std::vector<std::string>& allowed);
  void Text(const KeyInfo& key, const std::string& field) {
    Row(key, field.empty() ? "none" : "`\"" + field + "\"`", "a non-empty string");
  }
  void OptionalNumber(const KeyInfo& key, const std::optional<double>& field, Range range,
                      Absent absent) {
    Row(key,
        field                     ? NumberText(*field)
        : absent == Absent::kNull ? "off (null)"
                                  : "none",
        range.Interval());
  }
  void NumberOrAuto(const KeyInfo& key, double field, bool is_auto, Range range) {
    Row(key, is_auto ? "`\"auto\"`" : NumberText(field), range.Interval() + " or `\"auto\"`");
  }
  void Integers(const KeyInfo& key, const std::vector<int>& field, int lo, int hi);
  void Numbers(const KeyInfo& key, const std::vector<double>& field, Range range);
  void Vector3(const KeyInfo& key, const std::array<double, 3>& field);
  void Points(const KeyInfo& key, const std::vector<std::array<double, 3>>& field, int max);
  void NodePair(const KeyInfo& key, const std::array<int, 2>& field, int n_nodes);
  template <class T>
  void Section(const char* name, const T& field) {
    TableVisitor v{prefix + name + ".", ""};
    DescribeFields(field, v);
    rows += v.rows;
  }
  template <class T, class D>
  void List(const KeyInfo& key, const std::vector<T>&, D describe) {
    Row(key, "`[]`", "list of objects `{...}` (keys below)");
    const T element{};
    TableVisitor v{prefix + key.name + "[].", ""};
    describe(element, v);
    rows += v.rows;
  }
};

// Parses the section `s` into `config` (its defaults already set) and rejects unknown keys.
template <class T>
void ParseFields(JsonSection s, T& config) {
  ParseVisitor v{s};
  DescribeFields(config, v);
  s.Finish();
}

// A section parsed over its defaults, then its rules across keys checked (when it has any).
template <class T>
T ParseSection(JsonSection s, void (*check_rules)(const T&) = nullptr) {
  T config;
  ParseFields(s, config);
  if (check_rules != nullptr) check_rules(config);
  return config;
}

template <class T>
nlohmann::json EchoFields(const T& config) {
  nlohmann::json out = nlohmann::json::object();
  EchoVisitor v{out};
  DescribeFields(config, v);
  return out;
}

// Validate's part per key: each value in its range; `path` is the section's key path.
template <class T>
void ValidateFields(const T& config, const std::string& path) {
  ValidateVisitor v{path + "."};
  DescribeFields(config, v);
}

// The Markdown key table of a section, defaults taken from `defaults`.
template <class T>
std::string KeyTableOf(const T& defaults) {
  TableVisitor v;
  DescribeFields(defaults, v);
  return "| key | unit | default | allowed | what it controls |\n|---|---|---|---|---|\n" + v.rows;
}

// "## `name`: title": the README's heading of a section.
std::string SectionHeading(const SectionInfo& section);
// What follows the heading in the README (after the README's own paragraphs, if any): the
// rules across keys when there are any, then the key table.
std::string SectionBody(const SectionInfo& section, const std::string& table);

}  // namespace tbridge
