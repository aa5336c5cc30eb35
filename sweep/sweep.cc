#include "sweep/sweep.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <tuple>

#include "core/error.h"
#include "core/json_reader.h"

namespace tbridge {

namespace {

std::string Fixed(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string Joined(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : ";") + i;
  return s;
}

std::string Describe(const CandidateRow& r) {
  std::ostringstream s;
  s << "n = " << r.candidate.n << ", p = " << r.candidate.p
    << ", beta = " << Fixed(r.candidate.beta_deg) << " deg, deck prestrain "
    << Fixed(r.candidate.deck_prestrain);
  return s.str();
}

std::string FirstViolation(const CandidateRow& r) { return !r.ok ? "failed" : r.violated.front(); }

template <typename T>
nlohmann::json Opt(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

template <typename T>
std::optional<T> GetOpt(const nlohmann::json& j, const char* key) {
  const nlohmann::json& v = j.at(key);
  if (v.is_null()) return std::nullopt;
  return v.get<T>();
}

std::string CsvText(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (const char c : s)
    out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
}

}  // namespace

SweepChoice Choose(const std::vector<CandidateRow>& rows) {
  SweepChoice c;
  const CandidateRow* best = nullptr;
  for (const CandidateRow& r : rows) {
    if (r.ok && r.feasible && (!best || r.objective < best->objective)) best = &r;
  }
  if (!best) {
    std::map<std::string, int> count;
    for (const CandidateRow& r : rows) ++count[FirstViolation(r)];
    std::string most;
    for (const auto& [name, k] : count) {
      if (most.empty() || k > count[most]) most = name;
    }
    c.binding = "none feasible";
    c.reason = "no candidate is feasible; the most frequent first violation is " + most;
    return c;
  }
  c.found = true;
  c.index = best->candidate.index;
  // The lighter candidates, all infeasible by construction; the one just below the choice.
  const CandidateRow* next_lighter = nullptr;
  int lighter = 0;
  for (const CandidateRow& r : rows) {
    if (!r.ok || r.objective >= best->objective) continue;
    ++lighter;
    if (!next_lighter || r.objective > next_lighter->objective) next_lighter = &r;
  }
  std::ostringstream why;
  if (next_lighter) {
    c.binding = FirstViolation(*next_lighter);
    why << "lightest feasible (" << Describe(*best) << ", " << Fixed(best->objective) << " kg); "
        << lighter << " lighter candidate(s) are infeasible, the next lighter ("
        << Describe(*next_lighter) << ", " << Fixed(next_lighter->objective) << " kg) violates "
        << Joined(next_lighter->violated.empty() ? std::vector<std::string>{"failed"}
                                                 : next_lighter->violated);
  } else {
    const CandidateRow* lighter_members = nullptr;
    int max_n = 0;
    for (const CandidateRow& r : rows) {
      max_n = std::max(max_n, r.candidate.n);
      if (r.ok && r.total < best->total && (!lighter_members || r.total < lighter_members->total))
        lighter_members = &r;
    }
    if (lighter_members && best->joint_mass > 0) {
      c.binding = "joint_mass";
      why << "objective minimum (" << Describe(*best) << ", " << Fixed(best->objective)
          << " kg): lighter members exist (" << Describe(*lighter_members) << ", "
          << Fixed(lighter_members->total) << " kg without joints) but their joint mass "
          << Fixed(lighter_members->joint_mass) << " kg outweighs it";
    } else if (best->candidate.n == max_n) {
      c.binding = "mass (monotone: largest n in grid)";
      why << "objective minimum at the largest n of the grid (" << Describe(*best) << ", "
          << Fixed(best->objective) << " kg): mass still falls with n, a larger n would be lighter";
    } else {
      c.binding = "mass";
      why << "objective minimum (" << Describe(*best) << ", " << Fixed(best->objective) << " kg)";
    }
  }
  // A candidate whose angle was searched (bridge.beta_deg "auto") says where it ended at a range
  // end.
  if (!best->angle_note.empty()) why << "; its angle: " << best->angle_note;
  c.reason = why.str();
  return c;
}

Shard ParseShard(const std::string& text, const std::string& option) {
  const std::string allowed = "must be i/N with whole numbers 1 <= i <= N, e.g. 1/4";
  const size_t slash = text.find('/');
  auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos) {
      throw OptionError(option, "'" + text + "'", allowed);
    }
    return std::stoi(s);
  };
  if (slash == std::string::npos) throw OptionError(option, "'" + text + "'", allowed);
  Shard s{number(text.substr(0, slash)), number(text.substr(slash + 1))};
  if (s.count < 1 || s.index < 1 || s.index > s.count)
    throw OptionError(option, "'" + text + "'", allowed);
  return s;
}

std::vector<CandidateRow> RunSweep(const SweepSpec& spec, const SweepRunOptions& options,
                                   SweepStats* stats) {
  std::vector<Candidate> mine;
  for (const Candidate& c : EnumerateCandidates(spec.sweep)) {
    if (options.shard.Has(c.index)) mine.push_back(c);
  }
  std::vector<CandidateRow> rows(mine.size());
  std::vector<size_t> todo;
  SweepStats local;
  for (size_t k = 0; k < mine.size(); ++k) {
    std::optional<CandidateRow> old = options.reuse ? options.reuse(mine[k]) : std::nullopt;
    if (old) {
      rows[k] = *old;
      ++local.reused;
    } else {
      todo.push_back(k);
    }
  }
  // Largest bridges first: a candidate's cost grows about as 2^n (members) times the steps
  // its run needs, so taking them first leaves the short ones to fill the threads at the end
  // instead of one long run alone on one thread. Rows keep their grid order whatever the
  // evaluation order.
  std::stable_sort(todo.begin(), todo.end(), [&mine](size_t a, size_t b) {
    return std::tie(mine[a].n, mine[a].p) > std::tie(mine[b].n, mine[b].p);
  });
  std::mutex mutex;
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  int done = local.reused;
  if (options.on_progress) options.on_progress(done, static_cast<int>(mine.size()));
  auto worker = [&] {
    for (size_t t = next++; t < todo.size() && !stop; t = next++) {
      try {
        CandidateRow row = EvaluateCandidate(spec, mine[todo[t]]);
        std::lock_guard<std::mutex> lock(mutex);
        if (options.on_done) options.on_done(row);
        rows[todo[t]] = std::move(row);
        ++local.evaluated;
        ++done;
        if (options.on_progress) options.on_progress(done, static_cast<int>(mine.size()));
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        stop = true;
      }
    }
  };
  const int threads = std::max(
      1, std::min<int>(options.threads, static_cast<int>(std::max<size_t>(todo.size(), 1))));
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  if (stats) *stats = local;
  return rows;
}

namespace {

// Every field of a sweep.json row, listed once: the group it sits in ("" at the top, or
// "mass_kg"), its key and the member that holds it. RowToJson and RowFromJson both walk this
// list, so a field added here is written, read back and merged without a second line.
template <class Row, class Visit>
void RowFields(Row& r, Visit&& v) {  // Row: CandidateRow or const CandidateRow
  auto& c = r.candidate;
  v("", "index", c.index);
  v("", "n", c.n);
  v("", "p", c.p);
  v("", "beta_deg", c.beta_deg);
  v("", "deck_prestrain", c.deck_prestrain);
  v("", "ok", r.ok);
  v("", "note", r.note);
  v("mass_kg", "bars", r.bars);
  v("mass_kg", "strings", r.strings);
  v("mass_kg", "deck_strings", r.deck_strings);
  v("mass_kg", "deck_beams", r.deck_beams);
  v("mass_kg", "structure", r.structure);
  v("mass_kg", "total", r.total);
  v("mass_kg", "joints", r.joint_mass);
  v("mass_kg", "objective", r.objective);
  v("mass_kg", "first_design", r.first_design);
  v("", "designs", r.designs);
  v("", "verified", r.verified);
  v("", "utilisation_max", r.utilisation_max);
  v("", "free_nodes", r.free_nodes);
  v("", "deck_string_area_factor", r.deck_string_area_factor);
  v("", "prestress_pa", r.prestress);
  v("", "allowed_stress_pa", r.allowed_stress);
  v("", "first_frequency_rad_s", r.first_frequency_rad_s);
  v("", "dynamic_check_done", r.dynamic_check_done);
  v("", "peak_deck_displacement_m", r.peak_deck_displacement);
  v("", "dynamic_string_utilisation", r.dynamic_string_utilisation);
  v("", "dynamic_bar_utilisation", r.dynamic_bar_utilisation);
  v("", "slack_taut_strings", r.slack_taut_strings);
  v("", "dynamic_runs", r.dynamic_runs);
  v("", "feasible", r.feasible);
  v("", "violated", r.violated);
}

template <typename T>
nlohmann::json RowValue(const T& v) {
  return nlohmann::json(v);
}
template <typename T>
nlohmann::json RowValue(const std::optional<T>& v) {
  return Opt(v);
}
template <typename T>
void ReadRowValue(const nlohmann::json& j, const char* key, T& v) {
  v = j.at(key).get<T>();
}
template <typename T>
void ReadRowValue(const nlohmann::json& j, const char* key, std::optional<T>& v) {
  v = GetOpt<T>(j, key);
}

}  // namespace

nlohmann::json RowToJson(const CandidateRow& r) {
  nlohmann::json j = nlohmann::json::object();
  RowFields(r, [&j](const char* group, const char* key, const auto& field) {
    (*group ? j[group] : j)[key] = RowValue(field);
  });
  return j;
}

CandidateRow RowFromJson(const nlohmann::json& j) {
  try {
    CandidateRow r;
    RowFields(r, [&j](const char* group, const char* key, auto& field) {
      ReadRowValue(*group ? j.at(group) : j, key, field);
    });
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError("sweep row", Show(j), std::string("malformed: ") + e.what());
  }
}

std::string SweepFingerprint(const SweepSpec& spec) {
  const std::string text = ToJson(spec).dump();
  unsigned long long h = 1469598103934665603ULL;
  for (const unsigned char ch : text) {
    h ^= ch;
    h *= 1099511628211ULL;
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", h);
  return buf;
}

std::string SweepCsv(const std::vector<CandidateRow>& rows) {
  std::ostringstream out;
  out << "index,n,p,beta_deg,deck_prestrain,ok,bars_kg,strings_kg,deck_strings_kg,deck_beams_kg,"
         "structure_kg,"
         "total_kg,joint_mass_kg,objective_kg,first_design_kg,designs,verified,utilisation_max,"
         "deck_string_area_factor,prestress_pa,first_frequency_rad_s,"
         "dynamic_check_done,peak_deck_displacement_m,dynamic_string_utilisation,dynamic_bar_"
         "utilisation,slack_taut_strings,"
         "dynamic_runs,feasible,violated,note\n";
  auto opt = [](const std::optional<double>& v) { return v ? Fixed(*v) : std::string(); };
  for (const CandidateRow& r : rows) {
    const Candidate& c = r.candidate;
    out << c.index << "," << c.n << "," << c.p << "," << Fixed(c.beta_deg) << ","
        << Fixed(c.deck_prestrain) << "," << (r.ok ? 1 : 0) << "," << Fixed(r.bars) << ","
        << Fixed(r.strings) << "," << Fixed(r.deck_strings) << "," << Fixed(r.deck_beams) << ","
        << Fixed(r.structure) << "," << Fixed(r.total) << "," << Fixed(r.joint_mass) << ","
        << Fixed(r.objective) << "," << Fixed(r.first_design) << "," << r.designs << ","
        << (r.verified ? (*r.verified ? "1" : "0") : "") << "," << opt(r.utilisation_max) << ","
        << Fixed(r.deck_string_area_factor) << "," << Fixed(r.prestress) << ","
        << opt(r.first_frequency_rad_s) << ","
        << (r.dynamic_check_done ? (*r.dynamic_check_done ? "1" : "0") : "") << ","
        << opt(r.peak_deck_displacement) << "," << opt(r.dynamic_string_utilisation) << ","
        << opt(r.dynamic_bar_utilisation) << ","
        << (r.slack_taut_strings ? std::to_string(*r.slack_taut_strings) : std::string()) << ","
        << CsvText(r.dynamic_runs.value_or("")) << "," << (r.feasible ? 1 : 0) << ","
        << Joined(r.violated) << "," << CsvText(r.note) << "\n";
  }
  return out.str();
}

std::string SweepJson(const SweepSpec& spec, const std::vector<CandidateRow>& rows,
                      const std::optional<Shard>& shard) {
  nlohmann::json j;
  j["config"] = ToJson(spec);
  j["fingerprint"] = SweepFingerprint(spec);
  j["candidates"] = spec.sweep.size();
  j["shard"] = shard ? nlohmann::json{{"index", shard->index}, {"count", shard->count}}
                     : nlohmann::json(nullptr);
  nlohmann::json list = nlohmann::json::array();
  for (const CandidateRow& r : rows) list.push_back(RowToJson(r));
  j["rows"] = list;
  if (shard) {
    j["choice"] = nullptr;
  } else {
    const SweepChoice c = Choose(rows);
    j["choice"] = {{"found", c.found},
                   {"index", c.found ? nlohmann::json(c.index) : nlohmann::json(nullptr)},
                   {"binding", c.binding},
                   {"reason", c.reason}};
    if (c.found) {
      for (const CandidateRow& r : rows) {
        if (r.candidate.index == c.index) j["choice"]["row"] = RowToJson(r);
      }
    }
  }
  return j.dump(2) + "\n";
}

}  // namespace tbridge
