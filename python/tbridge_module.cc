// The Python module `tbridge`: the library the command-line tool runs, called from Python. It
// holds no logic of its own: each function is a path a command runs (design, check, export,
// modes), and each property a field of the design the JSON output writes. Arrays are owned
// copies: editing one changes nothing in the design. Long work runs with the GIL released.

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/modal_scene.h"
#include "app/scenario.h"
#include "app/simulation_report.h"
#include "bridge/design_model.h"
#include "checks/static_check.h"
#include "checks/verdict.h"
#include "core/config.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "core/progress.h"
#include "design/design.h"
#include "dynamics/modal.h"
#include "export/export.h"
#include "io/design_reader.h"
#include "io/design_report.h"
#include "sizing/verified_design.h"
#include "sweep/sweep.h"
#include "truss/truss_design.h"
#include "truss/truss_report.h"

namespace py = pybind11;

namespace tbridge {

namespace {

// Throws the ConfigError the tool gives for a bad key when a float under `value` (a dict, list
// or tuple, walked down to its numbers) is NaN or infinite: json.dumps would write it as the
// bare NaN or Infinity, which is no JSON, and the parse would name no key. `path` is the key
// path so far, as the tool writes it ("bridge.payload", "structure.nodes[2]").
void CheckFinite(const py::handle& value, const std::string& path) {
  if (py::isinstance<py::dict>(value)) {
    for (const auto& [key, item] : py::reinterpret_borrow<py::dict>(value)) {
      const std::string name = py::str(key).cast<std::string>();
      CheckFinite(item, path.empty() ? name : path + "." + name);
    }
  } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    size_t k = 0;
    for (const py::handle item : value) {
      std::string element = path;
      element += "[";
      element += std::to_string(k++);
      element += "]";
      CheckFinite(item, element);
    }
  } else if (py::isinstance<py::float_>(value)) {
    const double number = value.cast<double>();
    if (!std::isfinite(number)) {
      throw ConfigError(path.empty() ? "(root)" : path, NumberText(number),
                        "must be a finite number (JSON has no NaN or infinity)");
    }
  }
}

// The JSON of a config given as a dict, as Python writes it (every float exact), its numbers
// checked finite first.
nlohmann::json JsonOf(const py::object& config) {
  CheckFinite(config, "");
  return nlohmann::json::parse(
      py::module_::import("json").attr("dumps")(config).cast<std::string>());
}

// A config given as a dict or as a path to its file.
Config ConfigOf(const py::object& config) {
  if (py::isinstance<py::dict>(config)) return ParseConfig(JsonOf(config));
  return LoadConfig(py::str(py::module_::import("os").attr("fspath")(config)).cast<std::string>());
}

// Members in the order of the JSON output's "members": bars, then strings.
std::vector<const MemberSizing*> Members(const Design& d) {
  std::vector<const MemberSizing*> out;
  for (const MemberSizing& m : d.bars) out.push_back(&m);
  for (const MemberSizing& m : d.strings) out.push_back(&m);
  return out;
}

template <class Field>
py::array_t<double> MemberColumn(const Design& d, Field field) {
  const std::vector<const MemberSizing*> members = Members(d);
  py::array_t<double> out(static_cast<py::ssize_t>(members.size()));
  auto view = out.mutable_unchecked<1>();
  for (size_t k = 0; k < members.size(); ++k)
    view(static_cast<py::ssize_t>(k)) = field(*members[k]);
  return out;
}

// A 3 x n matrix as an n x 3 array.
py::array_t<double> Rows(const Eigen::Matrix3Xd& m) {
  py::array_t<double> out({static_cast<py::ssize_t>(m.cols()), py::ssize_t{3}});
  auto view = out.mutable_unchecked<2>();
  for (Eigen::Index v = 0; v < m.cols(); ++v) {
    for (int a = 0; a < 3; ++a) view(v, a) = m(a, v);
  }
  return out;
}

struct Modes {
  py::array_t<double> omega_rad_s, frequency_hz, period_s;
  py::array_t<double> shapes;  // modes x nodes x 3, mass-normalised [m / sqrt(kg)]
  bool all_modes = true;
};

Modes ModesOf(const DynamicModel& model, int count) {
  ModalOptions options;
  options.count = count;
  ModalResult result;
  {
    py::gil_scoped_release release;
    result = ComputeModes(model, options);
  }
  Modes out;
  const auto n = static_cast<py::ssize_t>(result.modes.size());
  out.omega_rad_s = py::array_t<double>(n);
  out.frequency_hz = py::array_t<double>(n);
  out.period_s = py::array_t<double>(n);
  out.shapes =
      py::array_t<double>({n, static_cast<py::ssize_t>(model.num_nodes()), py::ssize_t{3}});
  auto shapes = out.shapes.mutable_unchecked<3>();
  for (py::ssize_t k = 0; k < n; ++k) {
    const Mode& m = result.modes[k];
    out.omega_rad_s.mutable_at(k) = m.omega_rad_s;
    out.frequency_hz.mutable_at(k) = m.frequency_hz;
    out.period_s.mutable_at(k) = m.period_s;
    for (py::ssize_t v = 0; v < model.num_nodes(); ++v) {
      for (int a = 0; a < 3; ++a) shapes(k, v, a) = m.shape(a, v);
    }
  }
  out.all_modes = result.all_modes;
  return out;
}

// Raised inside a run when Python has a signal to handle (Ctrl-C): the run unwinds, and the
// Python error PyErr_CheckSignals set (KeyboardInterrupt) is raised once the GIL is back.
struct Interrupted {};

// Gives Python its signals during long work, at most every 50 ms: takes the GIL for
// PyErr_CheckSignals and throws Interrupted when a handler raised (Ctrl-C: KeyboardInterrupt).
// Python runs its handlers on its main thread only, so a poll from another thread finds none.
class SignalPoll {
 public:
  void operator()() {
    const auto now = std::chrono::steady_clock::now();
    if (now - polled_ < std::chrono::milliseconds(50)) return;
    polled_ = now;
    py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw Interrupted{};
  }

 private:
  std::chrono::steady_clock::time_point polled_ = std::chrono::steady_clock::now();
};

// A silent progress reporter whose cancel hook is a SignalPoll: the work it follows (a design,
// a check, a sweep) stops at its next progress report after Ctrl-C.
struct Interruptible {
  Interruptible() {
    progress.SetCancelHook([this] { poll(); });
  }
  SignalPoll poll;
  ProgressReporter progress;
};

// Runs `work` with the GIL released and Ctrl-C polled through `progress`; an interruption
// raises Python's KeyboardInterrupt once the GIL is back.
template <class Work>
auto Interruptibly(Work work) {
  Interruptible on;
  try {
    py::gil_scoped_release release;
    return work(&on.progress);
  } catch (const Interrupted&) {
    throw py::error_already_set();
  }
}

// The rows of a sweep and its choice, as tbridge sweep writes them in sweep.json and sweep.csv.
struct SweepResult {
  py::list rows;
  py::object choice;  // dict, or None for a shard
  std::string json_text, csv_text;
};

// Keeps the recorded rows of a run in memory, and gives Python its signals during the run:
// every 50 ms of recording it takes the GIL for PyErr_CheckSignals.
class PythonHistory : public HistorySink {
 public:
  void Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) override {
    width_ = static_cast<size_t>(model.dim) * recorded_nodes.size();
  }
  void Row(double t, const double* coordinates) override {
    times.push_back(t);
    rows.insert(rows.end(), coordinates, coordinates + width_);
    poll_();
  }
  std::vector<double> times, rows;

 private:
  size_t width_ = 0;
  SignalPoll poll_;
};

struct Run {
  py::dict summary;                 // summary.json of tbridge simulate
  py::array_t<double> time;         // [s], one per record
  py::array_t<double> positions;    // records x recorded nodes x dim [m]
  py::array_t<int> recorded_nodes;  // 0-based
};

}  // namespace

}  // namespace tbridge

PYBIND11_MODULE(tbridge, m) {
  using namespace tbridge;
  m.doc() =
      "Minimum-mass tensegrity bridges: the library of the tbridge command-line tool (README.md, "
      "\"Python\").";
  py::register_exception<ConfigError>(m, "ConfigError", PyExc_ValueError);
  py::register_exception<ModelError>(m, "ModelError", PyExc_RuntimeError);

  py::class_<Design>(m, "Design",
                     "A sized bridge, as tbridge design writes it. Arrays are owned copies.")
      .def_property_readonly(
          "nodes", [](const Design& d) { return Rows(d.topology.structure.nodes); },
          "node positions, n x 3 [m]")
      .def_property_readonly(
          "member_ends",
          [](const Design& d) {
            const std::vector<const MemberSizing*> members = Members(d);
            py::array_t<int> out({static_cast<py::ssize_t>(members.size()), py::ssize_t{2}});
            auto view = out.mutable_unchecked<2>();
            for (size_t k = 0; k < members.size(); ++k) {
              view(static_cast<py::ssize_t>(k), 0) = members[k]->i;
              view(static_cast<py::ssize_t>(k), 1) = members[k]->j;
            }
            return out;
          },
          "each member's end nodes, 0-based rows of `nodes`; bars first, then strings, as in the "
          "JSON's members")
      .def_property_readonly("member_names",
                             [](const Design& d) {
                               std::vector<std::string> out;
                               for (const MemberSizing* s : Members(d)) out.push_back(s->name);
                               return out;
                             })
      .def_property_readonly("num_bars", [](const Design& d) { return d.bars.size(); })
      .def_property(
          "areas",
          [](const Design& d) {
            return MemberColumn(d, [](const MemberSizing& s) { return s.area; });
          },
          [](Design& d, const std::vector<double>& areas) { d = WithAreas(d, areas); },
          "[m^2]. Assigning areas edits the design as an engineer edits its file (with_areas); "
          "tbridge.check(design) then checks it")
      .def(
          "with_areas",
          [](const Design& d, const std::vector<double>& areas) { return WithAreas(d, areas); },
          py::arg("areas"),
          "a new design with these member areas [m^2] (bars first, then strings): each member's "
          "radius, mass and "
          "stiffness from its area, the rest lengths kept, and the reference state re-derived as "
          "built, as tbridge "
          "check reads an edited design file (the design's as_built says what moved)")
      .def_property_readonly(
          "forces",
          [](const Design& d) {
            return MemberColumn(d, [](const MemberSizing& s) { return s.force; });
          },
          "design force: compression of a bar, tension of a string [N]")
      .def_property_readonly(
          "rest_lengths",
          [](const Design& d) {
            return MemberColumn(d, [](const MemberSizing& s) { return s.rest_length; });
          },
          "[m]; a bar's is its length")
      .def_property_readonly("utilisation",
                             [](const Design& d) {
                               return MemberColumn(
                                   d, [](const MemberSizing& s) { return s.utilisation; });
                             })
      .def_property_readonly(
          "verdict",
          [](const Design& d) { return std::string(VerdictName(DesignVerdict(d).outcome)); },
          "PASS, FAIL or INCOMPLETE")
      .def_property_readonly("verdict_summary",
                             [](const Design& d) { return DesignVerdict(d).summary; })
      .def_property_readonly("cases",
                             [](const Design& d) {
                               std::vector<std::string> out;
                               for (const LoadCase& c : d.cases) out.push_back(c.name);
                               return out;
                             })
      .def_property_readonly(
          "structure_mass", [](const Design& d) { return d.mass.structure; }, "[kg]")
      .def(
          "to_json",
          [](const Design& d) {
            std::ostringstream os;
            WriteDesignJson(d, os);
            return os.str();
          },
          "the design file tbridge design writes, as text")
      .def(
          "summary", [](const Design& d) { return DesignSummary(d); },
          "the summary tbridge design prints");

  py::class_<Modes>(
      m, "Modes",
      "Natural frequencies and mass-normalised shapes (modes x nodes x 3), lowest first.")
      .def_readonly("omega_rad_s", &Modes::omega_rad_s)
      .def_readonly("frequency_hz", &Modes::frequency_hz)
      .def_readonly("period_s", &Modes::period_s)
      .def_readonly("shapes", &Modes::shapes)
      .def_readonly("all_modes", &Modes::all_modes);

  py::class_<TrussDesign>(
      m, "StructureDesign",
      "A sized pin-jointed structure (a structure section's members in groups), as tbridge "
      "design writes it. Arrays are owned copies; members in the config's order.")
      .def_property_readonly("group_names",
                             [](const TrussDesign& d) {
                               std::vector<std::string> out;
                               for (const TrussGroup& g : d.model.groups) out.push_back(g.name);
                               return out;
                             })
      .def_property_readonly(
          "group_areas", [](const TrussDesign& d) { return Eigen::VectorXd(d.sizing.group_areas); },
          "one area per group [m^2]")
      .def_property_readonly(
          "areas",
          [](const TrussDesign& d) {
            return Eigen::VectorXd(d.model.MemberAreas(d.sizing.group_areas));
          },
          "each member's area [m^2]")
      .def_property_readonly(
          "forces",
          [](const TrussDesign& d) {
            std::vector<double> out;
            for (const TrussMemberCheck& c : d.check.members) out.push_back(c.force);
            return out;
          },
          "each member's force in its governing case, tension > 0 [N]")
      .def_property_readonly(
          "prestress", [](const TrussDesign& d) { return Eigen::VectorXd(d.check.prestress); },
          "each member's prestress, a self-stress, tension > 0 [N] (zero without)")
      .def_property_readonly("utilisation",
                             [](const TrussDesign& d) {
                               std::vector<double> out;
                               for (const TrussMemberCheck& c : d.check.members)
                                 out.push_back(c.utilisation);
                               return out;
                             })
      .def_property_readonly(
          "frequencies_hz",
          [](const TrussDesign& d) { return Eigen::VectorXd(d.check.frequencies_hz); })
      .def_property_readonly(
          "structure_mass", [](const TrussDesign& d) { return d.model.Mass(d.sizing.group_areas); },
          "[kg]")
      .def_property_readonly("proved_local_optimum",
                             [](const TrussDesign& d) { return d.sizing.kkt.proved_local_optimum; })
      .def_property_readonly(
          "verdict",
          [](const TrussDesign& d) { return std::string(d.check.pass ? "PASS" : "FAIL"); },
          "PASS or FAIL")
      .def(
          "to_json",
          [](const TrussDesign& d) {
            std::ostringstream os;
            WriteTrussDesignJson(d, os);
            return os.str();
          },
          "the design file tbridge design writes, as text")
      .def(
          "summary", [](const TrussDesign& d) { return TrussDesignSummary(d); },
          "the summary tbridge design prints");

  m.def(
      "design",
      [](const py::object& config) -> py::object {
        const Config c = ConfigOf(config);
        if (c.structure)
          return py::cast(Interruptibly([&c](ProgressReporter*) { return DesignTruss(c); }));
        return py::cast(Interruptibly(
            [&c](ProgressReporter* progress) { return DesignAndVerify(c, progress); }));
      },
      py::arg("config"),
      "the verified design of a config (a dict, or the path of its JSON file), as tbridge design: "
      "a Design of a "
      "bridge, a StructureDesign of a structure's members in groups; Ctrl-C stops a bridge's "
      "(KeyboardInterrupt)");
  m.def(
      "load_design", [](const std::string& path) { return ReadDesign(ReadJsonFile(path)); },
      py::arg("path"),
      "a design file written by tbridge design or check, read as tbridge check reads it");
  m.def(
      "check",
      [](const Design& design) {
        return Interruptibly([&design](ProgressReporter* progress) {
          Design out = design;
          CheckAgain(out, progress);
          return out;
        });
      },
      py::arg("design"),
      "the design with its checks run again, as tbridge check; Ctrl-C stops it "
      "(KeyboardInterrupt)");
  m.def(
      "export",
      [](const Design& design, const std::string& format, bool rigid_bars, int modes) {
        CalculixOptions options;
        options.rigid_bars = rigid_bars;
        options.modes = modes;
        const std::optional<ExportFormat> chosen = ExportFormatOf(format);
        if (!chosen) {
          throw ConfigError("format", "'" + format + "'", ExpectedExportFormats());
        }
        std::ostringstream os;
        WriteExport(design, *chosen, options, os);
        return os.str();
      },
      py::arg("design"), py::arg("format"), py::arg("rigid_bars") = false, py::arg("modes") = 10,
      "the text tbridge export writes: format \"calculix\" or \"opensees\"");
  py::class_<Run>(m, "Run", "A dynamic run: its summary and its recorded history.")
      .def_readonly("summary", &Run::summary)
      .def_readonly("time", &Run::time)
      .def_readonly("positions", &Run::positions)
      .def_readonly("recorded_nodes", &Run::recorded_nodes);

  m.def(
      "simulate",
      [](const py::object& input) {
        // A Design, a design file (its dict or path: config, nodes and members), or a config.
        std::optional<Design> written;
        if (py::isinstance<Design>(input)) {
          written = input.cast<Design>();
        } else {
          const nlohmann::json j =
              py::isinstance<py::dict>(input)
                  ? JsonOf(input)
                  : ReadJsonFile(py::str(py::module_::import("os").attr("fspath")(input))
                                     .cast<std::string>());
          if (j.is_object() && j.contains("members") && j.contains("config"))
            written = ReadDesign(j);
        }
        const Config c = written ? written->config : ConfigOf(input);
        PythonHistory history;
        RunHooks hooks;
        hooks.history = {&history};
        ScenarioResult scenario;
        try {
          py::gil_scoped_release release;
          scenario = written ? RunDesignScenario(*written, hooks) : RunSimulateScenario(c, hooks);
        } catch (const Interrupted&) {
          throw py::error_already_set();
        }
        const SimulationResult& result = scenario.simulation;
        Run out;
        out.summary = py::module_::import("json").attr("loads")(
            SummaryJson(c, scenario.model, result).dump());
        const auto records = static_cast<py::ssize_t>(history.times.size());
        const auto nodes = static_cast<py::ssize_t>(result.recorded_nodes.size());
        out.time = py::array_t<double>(records, history.times.data());
        out.positions = py::array_t<double>({records, nodes, static_cast<py::ssize_t>(result.dim)},
                                            history.rows.data());
        out.recorded_nodes = py::array_t<int>(nodes, result.recorded_nodes.data());
        return out;
      },
      py::arg("config"),
      "the dynamic run of a \"dynamics\" section, as tbridge simulate: of a config (dict or path), "
      "or of a design "
      "(a Design, or a design file's dict or path, edited or not) with its config's section, run "
      "on the bridge as "
      "written or as built; Ctrl-C stops it (KeyboardInterrupt)");
  m.def(
      "case_nodes",
      [](const Design& design, const std::string& label) {
        const CaseAt at = CaseOfLabel(design, label, "case");
        Eigen::Matrix3Xd nodes;
        {
          py::gil_scoped_release release;
          nodes = SolveCaseNodes(design, at);
        }
        return Rows(nodes);
      },
      py::arg("design"), py::arg("case"),
      "the node positions (n x 3, m) under one load case of the design, solved as the static check "
      "solves it "
      "(the nonlinear static problem from the reference state); `case` as the design file names "
      "it: \"NAME\", or "
      "\"NAME at node N\" for a travelling case at the station of deck node N");
  py::class_<SweepResult>(m, "Sweep",
                          "The rows of a sweep and its choice, as tbridge sweep writes them.")
      .def_readonly("rows", &SweepResult::rows,
                    "one dict per candidate of the run, as sweep.json's \"rows\"")
      .def_readonly("choice", &SweepResult::choice,
                    "sweep.json's \"choice\" (the lightest feasible candidate and what decided "
                    "it); None for a shard")
      .def(
          "to_json", [](const SweepResult& s) { return s.json_text; },
          "the sweep.json tbridge sweep writes")
      .def(
          "to_csv", [](const SweepResult& s) { return s.csv_text; },
          "the sweep.csv tbridge sweep writes");

  m.def(
      "sweep",
      [](const py::object& config, std::optional<int> threads,
         std::optional<std::string> shard_text) {
        const SweepSpec spec =
            py::isinstance<py::dict>(config)
                ? ParseSweepSpec(JsonOf(config))
                : LoadSweepSpec(py::str(py::module_::import("os").attr("fspath")(config)));
        SweepRunOptions options;
        options.threads = threads
                              ? *threads
                              : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        if (options.threads < 1)
          throw ConfigError("threads", std::to_string(options.threads), "a whole number >= 1");
        std::optional<Shard> shard;
        if (shard_text) shard = ParseShard(*shard_text, "shard");
        if (shard) options.shard = *shard;
        const std::vector<CandidateRow> rows = Interruptibly([&](ProgressReporter* progress) {
          options.on_progress = [progress](int done, int total) { progress->Update(done, total); };
          return RunSweep(spec, options);
        });
        SweepResult out;
        out.json_text = SweepJson(spec, rows, shard);
        out.csv_text = SweepCsv(rows);
        const py::dict parsed = py::module_::import("json").attr("loads")(out.json_text);
        out.rows = parsed["rows"];
        out.choice = parsed["choice"];
        return out;
      },
      py::arg("config"), py::arg("threads") = py::none(), py::arg("shard") = py::none(),
      "the sweep of a config's \"sweep\" grid (a dict, or the path of its JSON file), as tbridge "
      "sweep: `threads` "
      "workers (None: the number of cores), `shard` \"i/N\" for the candidates with index % N == i "
      "- 1 (no "
      "choice then). Ctrl-C stops it once the candidate in the calling thread is done "
      "(KeyboardInterrupt)");
  m.def(
      "modes",
      [](const py::object& config_or_design, int count) {
        if (py::isinstance<Design>(config_or_design)) {
          const Design& d = config_or_design.cast<const Design&>();
          return ModesOf(BuildDynamicModel(d, ModalModelOptions(d.config)), count);
        }
        const Config c = ConfigOf(config_or_design);
        ModalScene scene;
        {
          py::gil_scoped_release release;
          scene = ModalSceneOf(c);
        }
        return ModesOf(scene.model, count);
      },
      py::arg("config_or_design"), py::arg("count") = 0,
      "the linearised modes tbridge modes computes: the lowest `count` (0: every mode)");
}
