// Strict reading of JSON config objects: every key is typed, range-checked and consumed;
// any key left unread is an error. Errors name the full key path, the value and what is allowed.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"

namespace tbridge {

// What a value beyond one end of a range most likely is, said in its refusal: a unit slip
// ("was it given in mm? 30000 mm is 30 m"). In `text`, {v} stands for the value and {as} for
// the value times `factor` (its reading in the key's own unit); a note that uses them is said
// only when that reading lies in the range, any other for any value >= 0.
struct RangeNote {
  const char* text = nullptr;
  double factor = 1;
};

// Closed or open numeric bounds for a config value.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  RangeNote below, above;  // said for a value below lo, above hi

  Range() = default;
  Range(double lo_end, double hi_end, bool lo_excluded = false, bool hi_excluded = false)
      : lo(lo_end), hi(hi_end), lo_open(lo_excluded), hi_open(hi_excluded) {}
  static Range Positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range NonNegative() {
    return {0.0, std::numeric_limits<double>::infinity(), false, false};
  }
  static Range AtLeast(double a) {
    return {a, std::numeric_limits<double>::infinity(), false, false};
  }
  static Range Closed(double a, double b) { return {a, b, false, false}; }
  static Range Open(double a, double b) { return {a, b, true, true}; }
  Range Below(RangeNote note) const {
    Range r = *this;
    r.below = note;
    return r;
  }
  Range Above(RangeNote note) const {
    Range r = *this;
    r.above = note;
    return r;
  }
  bool Contains(double v) const;
  // "(0, 90)", "[1, 1000]", "> 0", ">= 0", "< 1"; "" when unbounded.
  std::string Interval() const;
  // "a number in (0, 90)", "a number > 0", "a finite number": what messages say is allowed.
  std::string Describe() const;
  // Why `v` is refused: "must be " + Describe(), then the note of the end `v` lies beyond.
  std::string Refusal(double v) const;
};

// "an integer in [lo, hi]", as messages and the README say it.
std::string IntegerRangeText(long long lo, long long hi);
// "\"a\", \"b\", \"c\"": the allowed values of a choice, quoted.
std::string ChoiceText(const std::vector<std::string>& allowed);

class JsonSection {
 public:
  // `path` is the dotted key path of `object` ("" for the root). Throws ConfigError if
  // `object` is not a JSON object.
  JsonSection(const nlohmann::json& object, std::string path);

  // Whether `key` is present. Every key asked about is remembered as a key this section
  // knows, so that Finish() can suggest the nearest one for a misspelt key.
  bool Has(const std::string& key) const;
  // Finite number in `range`; `fallback` when absent (nullopt = required).
  double Number(const std::string& key, std::optional<double> fallback, Range range);
  // Integer in [lo, hi]; `fallback` when absent (nullopt = required).
  int Integer(const std::string& key, std::optional<int> fallback, int lo, int hi);
  // The same for counts beyond int (dynamics.limits.max_steps).
  long long Integer64(const std::string& key, std::optional<long long> fallback, long long lo,
                      long long hi);
  bool Bool(const std::string& key, std::optional<bool> fallback);
  // One of `allowed`; `fallback` when absent (nullopt = required).
  std::string Choice(const std::string& key, std::optional<std::string> fallback,
                     const std::vector<std::string>& allowed);
  // Free string (non-empty).
  std::string Text(const std::string& key, std::optional<std::string> fallback);
  // List of finite numbers, each in `range`.
  std::vector<double> Numbers(const std::string& key, std::optional<std::vector<double>> fallback,
                              Range range);
  std::vector<int> Integers(const std::string& key, std::optional<std::vector<int>> fallback,
                            int lo, int hi);
  // A list of exactly 3 finite numbers [x, y, z]; `fallback` when absent (nullopt = required).
  std::array<double, 3> Vector3(const std::string& key,
                                std::optional<std::array<double, 3>> fallback);
  // Nested object; absent -> empty object when `optional_section`, else ConfigError.
  JsonSection Section(const std::string& key, bool optional_section = true);
  // Raw access for arrays of objects; marks the key read. Returns nullptr when absent.
  const nlohmann::json* Raw(const std::string& key);
  // Path of a child key, for messages: "dynamics.loads[2].node".
  std::string PathOf(const std::string& key) const;
  // Throws ConfigError naming the first key that was never read, with "did you mean 'k'?"
  // when a known key is within NearestKey's distance.
  void Finish() const;

 private:
  const nlohmann::json& Get(const std::string& key);
  nlohmann::json object_;
  std::string path_;
  std::vector<std::string> read_;
  mutable std::vector<std::string> known_;  // every key asked about, present or not
};

// The candidate closest to `key` in edit distance (insertions, deletions, substitutions and
// swaps of neighbours, case ignored) when it is at most max(1, |key| / 3) away, else "".
std::string NearestKey(const std::string& key, const std::vector<std::string>& candidates);

// Parses JSON text; malformed input is a ConfigError naming `source` and the parser's reason.
nlohmann::json ParseJsonText(const std::string& text, const std::string& source);
// Reads and parses a file; unreadable files (missing, a directory, no permission) are a
// ConfigError naming the path and the reason.
nlohmann::json ReadJsonFile(const std::string& path);
// Short rendering of a JSON value for messages (truncated).
std::string Show(const nlohmann::json& value);

// Each element of the array `key` must be an object; `parse` reads one of them as a
// JsonSection with the path "key[k]". Absent = empty list.
template <typename T, typename F>
std::vector<T> ObjectList(JsonSection& section, const std::string& key, F parse) {
  std::vector<T> out;
  const nlohmann::json* raw = section.Raw(key);
  if (raw == nullptr) return out;
  if (!raw->is_array())
    throw ConfigError(section.PathOf(key), Show(*raw), "must be a list of objects");
  for (std::size_t k = 0; k < raw->size(); ++k) {
    out.push_back(
        parse(JsonSection((*raw)[k], section.PathOf(key) + "[" + std::to_string(k) + "]")));
  }
  return out;
}

}  // namespace tbridge
