#include "core/config_visitors.h"

namespace tbridge {

namespace {

std::string PointsAllowed(int max) {
  return "a list of 1 to " + std::to_string(max) + " positions [x, y, z]";
}

std::string PairAllowed(int n_nodes) {
  return "two node numbers [i, j] in [1, " + std::to_string(n_nodes) + "]";
}

// "`[1, 2]`": a default list as the README's table shows it.
template <class T>
std::string ListText(const std::vector<T>& values) {
  std::string text;
  for (const T& v : values) text += (text.empty() ? "" : ", ") + NumberText(v);
  return "`[" + text + "]`";
}

}  // namespace

void ParseVisitor::Points(const KeyInfo& key, std::vector<std::array<double, 3>>& field, int max) {
  const std::string path = s.PathOf(key.name);
  const nlohmann::json* raw = s.Raw(key.name);
  if (raw == nullptr)
    throw ConfigError(path, "(missing)", "required: a list of [x, y, z] node positions");
  if (!raw->is_array() || raw->empty() || raw->size() > static_cast<std::size_t>(max)) {
    throw ConfigError(path, Show(*raw), "must be " + PointsAllowed(max));
  }
  field.clear();
  for (std::size_t k = 0; k < raw->size(); ++k) {
    const nlohmann::json& e = (*raw)[k];
    bool ok = e.is_array() && e.size() == 3;
    for (std::size_t d = 0; ok && d < 3; ++d)
      ok = e[d].is_number() && std::isfinite(e[d].get<double>());
    if (!ok) {
      throw ConfigError(ValidateVisitor::Item(path, k), Show(e),
                        "must be a list of 3 finite numbers [x, y, z] (m)");
    }
    field.push_back({e[0].get<double>(), e[1].get<double>(), e[2].get<double>()});
  }
}

void ParseVisitor::NodePair(const KeyInfo& key, std::array<int, 2>& field, int n_nodes) {
  const std::vector<int> ends = s.Integers(key.name, std::nullopt, 1, n_nodes);
  if (ends.size() != 2) {
    throw ConfigError(s.PathOf(key.name), std::to_string(ends.size()) + " numbers",
                      "must be " + PairAllowed(n_nodes));
  }
  field = {ends[0], ends[1]};
}

void ValidateVisitor::Points(const KeyInfo& key, const std::vector<std::array<double, 3>>& field,
                             int max) const {
  if (field.empty() || field.size() > static_cast<std::size_t>(max)) {
    throw ConfigError(Path(key), std::to_string(field.size()) + " positions",
                      "must be " + PointsAllowed(max));
  }
  for (std::size_t k = 0; k < field.size(); ++k) {
    for (std::size_t d = 0; d < 3; ++d) {
      if (!std::isfinite(field[k][d])) {
        throw ConfigError(Item(Path(key), k), NumberText(field[k][d]),
                          "must be a list of 3 finite numbers [x, y, z] (m)");
      }
    }
  }
}

void TableVisitor::Row(const KeyInfo& key, const std::string& fallback,
                       const std::string& allowed) {
  const std::string shown_fallback = key.required   ? "required"
                                     : key.fallback ? key.fallback
                                                    : fallback;
  rows += "| `" + prefix + key.name + "` | " + key.unit + " | " + shown_fallback + " | " +
          (key.allowed ? key.allowed : allowed) + " | " + key.what + " |\n";
}

namespace {

// `"a"`, `"b"` or `"c"` (with `last` before the last one).
std::string QuotedList(const std::vector<std::string>& values, const char* last) {
  std::string list;
  for (std::size_t k = 0; k < values.size(); ++k) {
    list += (k == 0 ? "" : k + 1 == values.size() ? last : ", ") + ("`\"" + values[k] + "\"`");
  }
  return list;
}

}  // namespace

void TableVisitor::Choice(const KeyInfo& key, const std::string& field,
                          const std::vector<std::string>& allowed) {
  Row(key, "`\"" + field + "\"`", QuotedList(allowed, " or "));
}

void TableVisitor::Choices(const KeyInfo& key, const std::vector<std::string>& field,
                           const std::vector<std::string>& allowed) {
  std::string fallback = "[";
  fallback += QuotedList(field, ", ");
  fallback += ']';
  std::string text = "list of ";
  text += QuotedList(allowed, " and ");
  text += ", each at most once";
  Row(key, fallback, text);
}

void ValidateVisitor::CheckChoices(const std::string& path, const std::vector<std::string>& list,
                                   const std::vector<std::string>& allowed) {
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (std::find(allowed.begin(), allowed.end(), list[k]) == allowed.end()) {
      throw ConfigError(Item(path, k), "\"" + Printable(list[k]) + "\"",
                        "must be one of " + ChoiceText(allowed));
    }
    if (std::find(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(k), list[k]) !=
        list.begin() + static_cast<std::ptrdiff_t>(k)) {
      throw ConfigError(Item(path, k), "\"" + Printable(list[k]) + "\"", "each value at most once");
    }
  }
}

void ParseVisitor::Choices(const KeyInfo& key, std::vector<std::string>& field,
                           const std::vector<std::string>& allowed) {
  const std::string path = s.PathOf(key.name);
  const nlohmann::json* raw = s.Raw(key.name);
  if (raw == nullptr) {
    if (key.required)
      throw ConfigError(path, "(missing)", "required: a list of " + ChoiceText(allowed));
    return;
  }
  if (!raw->is_array())
    throw ConfigError(path, Show(*raw), "must be a list of " + ChoiceText(allowed));
  field.clear();
  for (std::size_t k = 0; k < raw->size(); ++k) {
    const nlohmann::json& e = (*raw)[k];
    if (!e.is_string())
      throw ConfigError(ValidateVisitor::Item(path, k), Show(e),
                        "must be one of " + ChoiceText(allowed));
    field.push_back(e.get<std::string>());
  }
  ValidateVisitor::CheckChoices(path, field, allowed);
}

void TableVisitor::Integers(const KeyInfo& key, const std::vector<int>& field, int lo, int hi) {
  Row(key, ListText(field),
      "list of integers in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

void TableVisitor::Numbers(const KeyInfo& key, const std::vector<double>& field, Range range) {
  const std::string interval = range.Interval();
  Row(key, ListText(field),
      std::string("list of numbers ") + (interval[0] == '(' || interval[0] == '[' ? "in " : "") +
          interval);
}

void TableVisitor::Vector3(const KeyInfo& key, const std::array<double, 3>& field) {
  Row(key, ListText(std::vector<double>(field.begin(), field.end())),
      "3 finite numbers `[x, y, z]`");
}

void TableVisitor::Points(const KeyInfo& key, const std::vector<std::array<double, 3>>&, int max) {
  Row(key, "`[]`", "list of 1 to " + std::to_string(max) + " entries `[x, y, z]`, finite");
}

void TableVisitor::NodePair(const KeyInfo& key, const std::array<int, 2>& field, int n_nodes) {
  Row(key, ListText(std::vector<int>(field.begin(), field.end())),
      "`[i, j]`, node numbers in [1, " + std::to_string(n_nodes) + "]");
}

std::string SectionHeading(const SectionInfo& section) {
  return std::string("## `") + section.name + "`: " + section.title + "\n";
}

std::string SectionBody(const SectionInfo& section, const std::string& table) {
  return (*section.rules ? std::string("Rules across keys: ") + section.rules + "\n\n"
                         : std::string()) +
         table;
}

}  // namespace tbridge
