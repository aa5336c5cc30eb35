#include "core/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <utility>

#include "core/error.h"

namespace tbridge {

namespace {
std::string Num(double v) { return NumberText(v); }
}  // namespace

bool Range::Contains(double v) const {
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string Range::Interval() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return std::string(lo_open ? "(" : "[") + Num(lo) + ", " + Num(hi) + (hi_open ? ")" : "]");
  if (has_lo) return std::string(lo_open ? "> " : ">= ") + Num(lo);
  if (has_hi) return std::string(hi_open ? "< " : "<= ") + Num(hi);
  return "";
}

std::string Range::Describe() const {
  const std::string interval = Interval();
  if (interval.empty()) return "a finite number";
  return std::string(interval[0] == '(' || interval[0] == '[' ? "a number in " : "a number ") +
         interval;
}

std::string Range::Refusal(double v) const {
  std::string out = "must be " + Describe();
  const bool beyond_lo = lo_open ? !(v > lo) : !(v >= lo);
  const RangeNote& note = beyond_lo ? below : above;
  if (note.text == nullptr || !std::isfinite(v) || v < 0) return out;
  std::string text = note.text;
  const bool numbers = text.find('{') != std::string::npos;
  // A reading outside the range too is no slip of that unit ("1e+300 mm is 1e+297 m").
  if (numbers && !Contains(v * note.factor)) return out;
  for (const auto& [mark, value] : {std::pair{"{v}", v}, std::pair{"{as}", v * note.factor}}) {
    for (std::size_t at = text.find(mark); at != std::string::npos; at = text.find(mark, at)) {
      const std::string shown = NumberText(value);
      text.replace(at, std::strlen(mark), shown);
      at += shown.size();
    }
  }
  return out + "; " + text;
}

std::string IntegerRangeText(long long lo, long long hi) {
  return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

std::string ChoiceText(const std::vector<std::string>& allowed) {
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
  return list;
}

std::string Show(const nlohmann::json& value) {
  std::string s = value.dump();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

JsonSection::JsonSection(const nlohmann::json& object, std::string path)
    : object_(object), path_(std::move(path)) {
  if (!object_.is_object()) {
    throw ConfigError(path_.empty() ? "(root)" : path_, Show(object_), "must be a JSON object");
  }
}

std::string JsonSection::PathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

const nlohmann::json& JsonSection::Get(const std::string& key) {
  read_.push_back(key);
  return object_.at(key);
}

double JsonSection::Number(const std::string& key, std::optional<double> fallback, Range range) {
  if (!Has(key)) {
    if (!fallback) throw ConfigError(PathOf(key), "(missing)", "required: " + range.Describe());
    return *fallback;
  }
  const nlohmann::json& v = Get(key);
  if (!v.is_number()) throw ConfigError(PathOf(key), Show(v), "must be " + range.Describe());
  const double d = v.get<double>();
  if (!std::isfinite(d) || !range.Contains(d))
    throw ConfigError(PathOf(key), Show(v), range.Refusal(d));
  return d;
}

int JsonSection::Integer(const std::string& key, std::optional<int> fallback, int lo, int hi) {
  return static_cast<int>(Integer64(key, fallback, lo, hi));
}

long long JsonSection::Integer64(const std::string& key, std::optional<long long> fallback,
                                 long long lo, long long hi) {
  const std::string allowed = IntegerRangeText(lo, hi);
  if (!Has(key)) {
    if (!fallback) throw ConfigError(PathOf(key), "(missing)", "required: " + allowed);
    return *fallback;
  }
  const nlohmann::json& v = Get(key);
  if (!v.is_number()) throw ConfigError(PathOf(key), Show(v), "must be " + allowed);
  const double d = v.get<double>();
  if (!std::isfinite(d) || d != std::floor(d) || d < lo || d > hi) {
    throw ConfigError(PathOf(key), Show(v), "must be " + allowed);
  }
  return static_cast<long long>(d);
}

bool JsonSection::Bool(const std::string& key, std::optional<bool> fallback) {
  if (!Has(key)) {
    if (!fallback) throw ConfigError(PathOf(key), "(missing)", "required: true or false");
    return *fallback;
  }
  const nlohmann::json& v = Get(key);
  if (!v.is_boolean()) throw ConfigError(PathOf(key), Show(v), "must be true or false");
  return v.get<bool>();
}

std::string JsonSection::Choice(const std::string& key, std::optional<std::string> fallback,
                                const std::vector<std::string>& allowed) {
  const std::string list = ChoiceText(allowed);
  if (!Has(key)) {
    if (!fallback) throw ConfigError(PathOf(key), "(missing)", "required: one of " + list);
    return *fallback;
  }
  const nlohmann::json& v = Get(key);
  if (!v.is_string() ||
      std::find(allowed.begin(), allowed.end(), v.get<std::string>()) == allowed.end()) {
    throw ConfigError(PathOf(key), Show(v), "must be one of " + list);
  }
  return v.get<std::string>();
}

std::string JsonSection::Text(const std::string& key, std::optional<std::string> fallback) {
  if (!Has(key)) {
    if (!fallback) throw ConfigError(PathOf(key), "(missing)", "required: a non-empty string");
    return *fallback;
  }
  const nlohmann::json& v = Get(key);
  if (!v.is_string() || v.get<std::string>().empty()) {
    throw ConfigError(PathOf(key), Show(v), "must be a non-empty string");
  }
  return v.get<std::string>();
}

std::vector<double> JsonSection::Numbers(const std::string& key,
                                         std::optional<std::vector<double>> fallback, Range range) {
  if (!Has(key)) {
    if (!fallback) {
      throw ConfigError(PathOf(key), "(missing)", "required: a list of " + range.Describe() + "s");
    }
    return *fallback;
  }
  const nlohmann::json& v = Get(key);
  if (!v.is_array()) throw ConfigError(PathOf(key), Show(v), "must be a list of numbers");
  std::vector<double> out;
  for (size_t k = 0; k < v.size(); ++k) {
    const std::string item = PathOf(key) + "[" + std::to_string(k) + "]";
    if (!v[k].is_number()) throw ConfigError(item, Show(v[k]), "must be " + range.Describe());
    const double d = v[k].get<double>();
    if (!std::isfinite(d) || !range.Contains(d))
      throw ConfigError(item, Show(v[k]), range.Refusal(d));
    out.push_back(d);
  }
  return out;
}

std::vector<int> JsonSection::Integers(const std::string& key,
                                       std::optional<std::vector<int>> fallback, int lo, int hi) {
  const std::string allowed = IntegerRangeText(lo, hi);
  if (!Has(key)) {
    if (!fallback) throw ConfigError(PathOf(key), "(missing)", "required: a list of integers");
    return *fallback;
  }
  const nlohmann::json& v = Get(key);
  if (!v.is_array()) throw ConfigError(PathOf(key), Show(v), "must be a list of integers");
  std::vector<int> out;
  for (size_t k = 0; k < v.size(); ++k) {
    const std::string item = PathOf(key) + "[" + std::to_string(k) + "]";
    const double d = v[k].is_number() ? v[k].get<double>() : std::nan("");
    if (!std::isfinite(d) || d != std::floor(d) || d < lo || d > hi) {
      throw ConfigError(item, Show(v[k]), "must be " + allowed);
    }
    out.push_back(static_cast<int>(d));
  }
  return out;
}

std::array<double, 3> JsonSection::Vector3(const std::string& key,
                                           std::optional<std::array<double, 3>> fallback) {
  if (!Has(key)) {
    if (!fallback)
      throw ConfigError(PathOf(key), "(missing)", "required: a list of 3 numbers [x, y, z]");
    return *fallback;
  }
  const std::vector<double> v = Numbers(key, std::nullopt, Range());
  if (v.size() != 3) {
    throw ConfigError(PathOf(key), std::to_string(v.size()) + " numbers",
                      "must be a list of 3 numbers [x, y, z]");
  }
  return {v[0], v[1], v[2]};
}

JsonSection JsonSection::Section(const std::string& key, bool optional_section) {
  if (!Has(key)) {
    if (!optional_section) throw ConfigError(PathOf(key), "(missing)", "required section");
    return JsonSection(nlohmann::json::object(), PathOf(key));
  }
  return JsonSection(Get(key), PathOf(key));
}

const nlohmann::json* JsonSection::Raw(const std::string& key) {
  if (!Has(key)) return nullptr;
  return &Get(key);
}

bool JsonSection::Has(const std::string& key) const {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.push_back(key);
  return object_.contains(key);
}

void JsonSection::Finish() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (std::find(read_.begin(), read_.end(), it.key()) == read_.end()) {
      const std::string nearest = NearestKey(it.key(), known_);
      throw ConfigError(
          PathOf(it.key()), Show(it.value()),
          "unknown key" + (nearest.empty() ? std::string() : ", did you mean '" + nearest + "'?") +
              " (see configs/README.md for the keys allowed here)");
    }
  }
}

std::string NearestKey(const std::string& key, const std::vector<std::string>& candidates) {
  auto lower = [](std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  const std::string a = lower(key);
  // Keys are short; a key of hostile length is not worth a suggestion (and a quadratic table).
  if (a.size() > 64) return "";
  std::string best;
  size_t best_distance = std::max<size_t>(1, a.size() / 3) + 1;
  for (const std::string& candidate : candidates) {
    const std::string b = lower(candidate);
    if (b.size() > 64 || candidate == key) continue;
    // Optimal string alignment distance (Damerau-Levenshtein without repeated edits).
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      for (size_t j = 1; j <= b.size(); ++j) {
        const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
        d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
        if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
          d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
      }
    }
    if (d[a.size()][b.size()] < best_distance) {
      best_distance = d[a.size()][b.size()];
      best = candidate;
    }
  }
  return best;
}

namespace {

// Configs are shallow; a bound on nesting keeps hostile input from exhausting the stack in
// the recursive copies and walks that follow parsing.
constexpr int kMaxJsonDepth = 64;

// Tracks the key path while parsing, so that a repeated key (which JSON parsers silently
// resolve to the last value) and a number too large for a double are reported by key.
class KeyTracker {
 public:
  bool operator()(int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using Event = nlohmann::json::parse_event_t;
    if (depth > kMaxJsonDepth) {
      throw ConfigError(Path(), "(nested " + std::to_string(depth) + " deep)",
                        "JSON nesting is limited to " + std::to_string(kMaxJsonDepth) + " levels");
    }
    switch (event) {
      case Event::object_start:
        frames_.push_back({true, {}, ""});
        break;
      case Event::array_start:
        frames_.push_back({false, {}, "[]"});
        break;
      case Event::object_end:
      case Event::array_end:
        if (!frames_.empty()) frames_.pop_back();
        break;
      case Event::key: {
        Frame& f = frames_.back();
        f.current = parsed.get<std::string>();
        if (!f.keys.insert(f.current).second) {
          throw ConfigError(Path(), "(given twice)", "each key may appear only once in an object");
        }
        break;
      }
      case Event::value:
        break;
    }
    return true;
  }

  std::string Path() const {
    std::string path;
    for (const Frame& f : frames_) {
      if (f.current.empty()) continue;
      path += (f.is_object && !path.empty() ? "." : "") + f.current;
    }
    return path.empty() ? "(root)" : path;
  }

 private:
  struct Frame {
    bool is_object;
    std::set<std::string> keys;
    std::string current;
  };
  std::vector<Frame> frames_;
};

}  // namespace

nlohmann::json ParseJsonText(const std::string& text, const std::string& source) {
  KeyTracker tracker;
  try {
    return nlohmann::json::parse(text, std::ref(tracker));
  } catch (const nlohmann::json::parse_error& e) {
    throw ConfigError(source + ": malformed JSON: " + e.what());
  } catch (const nlohmann::json::out_of_range& e) {
    // e.g. 1e999: the number does not fit a double.
    throw ConfigError(tracker.Path(), "(out of range, in " + source + ")",
                      std::string("must be a finite number (") + e.what() + ")");
  }
}

nlohmann::json ReadJsonFile(const std::string& path) {
  // An ifstream opens a directory without complaint and then reads nothing, which would be
  // reported as malformed JSON.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw ConfigError(path + ": is a directory, not a JSON file (give the path of a config file)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot open file for reading: " + std::strerror(errno));
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw ConfigError(path + ": read error");
  return ParseJsonText(buffer.str(), path);
}

}  // namespace tbridge
