#include "io/design_loads.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <type_traits>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {
namespace {

using json = nlohmann::json;

// Calls f(key, unit, field) for each load key of `config`, in the order the record lists them.
template <class C, class F>
void ForEachLoad(C& config, F f) {
  f("bridge.payload", "N", config.bridge.payload);
  f("loads.superimposed_dead_n_per_m", "N/m", config.loads.superimposed_dead_n_per_m);
  f("loads.travelling_load_n", "N", config.loads.travelling_load_n);
  f("loads.wind_n_per_m", "N/m", config.loads.wind_n_per_m);
  f("comfort.traffic_class", "", config.comfort.traffic_class);
  f("comfort.comfort_level", "", config.comfort.comfort_level);
  f("supports.horizontal_capacity_n", "N", config.supports.horizontal_capacity_n);
  f("supports.vertical_capacity_n", "N", config.supports.vertical_capacity_n);
}

json ValueJson(double v) { return v; }
template <class E>
json ValueJson(E v) requires std::is_enum_v<E> {
  return NameOf(v);
}
json ValueJson(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

std::string ValueText(double v, const char* unit) {
  return NumberText(v) + (*unit ? " " : "") + unit;
}
template <class E>
std::string ValueText(E v, const char*) requires std::is_enum_v<E> {
  return std::string("\"") + NameOf(v) + "\"";
}
std::string ValueText(const std::optional<double>& v, const char* unit) {
  return v ? ValueText(*v, unit) : "null (unlimited)";
}

void Read(const json& j, const std::string& key, double& field) {
  if (!j.is_number()) throw ConfigError(key, j.dump(), "a number, as tbridge design writes it");
  field = j.get<double>();
}
// A choice (comfort.traffic_class, comfort.comfort_level) by its text in the enum's table.
template <class E>
void Read(const json& j, const std::string& key, E& field) requires std::is_enum_v<E> {
  const std::optional<E> value =
      j.is_string() ? ValueIn(NamesOf(field), j.get<std::string>()) : std::nullopt;
  if (!value)
    throw ConfigError(
        key, j.dump(),
        "one of " + ChoiceText(AllNames(NamesOf(field))) + ", as tbridge design writes it");
  field = *value;
}
void Read(const json& j, const std::string& key, std::optional<double>& field) {
  if (j.is_null()) {
    field.reset();
    return;
  }
  double v = 0;
  Read(j, key, v);
  field = v;
}

}  // namespace

json DesignLoadsJson(const Config& config) {
  json out = json::object();
  ForEachLoad(config, [&out](const char* key, const char*, const auto& field) {
    out[key] = ValueJson(field);
  });
  return out;
}

Config WithDesignLoads(const Config& config, const json& record) {
  if (!record.is_object())
    throw ConfigError("designed_for", record.dump(),
                      "an object of load keys, as tbridge design writes it");
  Config out = config;
  std::vector<std::string> keys;
  ForEachLoad(out, [&](const char* key, const char*, auto& field) {
    keys.push_back(key);
    if (record.contains(key)) Read(record.at(key), std::string("designed_for.") + key, field);
  });
  for (const auto& [key, value] : record.items()) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    std::string allowed;
    for (const std::string& k : keys) allowed += (allowed.empty() ? "" : ", ") + k;
    throw ConfigError("designed_for." + key, value.dump(),
                      "not a load key of the design; allowed: " + allowed);
  }
  return out;
}

std::vector<std::string> ChangedLoads(const Config& designed, const Config& now) {
  std::vector<std::string> was, is, names;
  ForEachLoad(designed, [&](const char* key, const char* unit, const auto& field) {
    names.push_back(key);
    was.push_back(ValueText(field, unit));
  });
  ForEachLoad(now, [&](const char*, const char* unit, const auto& field) {
    is.push_back(ValueText(field, unit));
  });
  std::vector<std::string> out;
  for (size_t k = 0; k < names.size(); ++k) {
    if (was[k] != is[k]) out.push_back(names[k] + " " + was[k] + " -> " + is[k]);
  }
  return out;
}

}  // namespace tbridge
