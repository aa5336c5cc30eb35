// Time and peak memory of the lowest six linearised frequencies against n, for the planar
// p = 1 bridge of configs/paper_n3.json with n changed. The design and the dynamic model are
// built first and not timed; each n's modal analysis runs in a forked child so that its peak
// memory is its own: `modal_peak_KB` is the child's ru_maxrss less its resident size at the
// fork (what the modal analysis added), `process_peak_KB` the child's whole ru_maxrss.
// Then the whole `tbridge modes CONFIG -o OUT --modes 6 -q` process is timed for the n listed
// (wall time and its ru_maxrss from wait4).
// Usage: bench_modal [max_n] [repeats] [process_n,...]   (defaults 12, 3, "10,12")
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "bridge/design_model.h"
#include "core/config.h"
#include "design/design.h"
#include "dynamics/modal.h"
#include "dynamics/model.h"

namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// Resident set size now [KB] (second field of /proc/self/statm, in pages).
long ResidentKb() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

struct ChildReport {
  double best_ms = 0;       // lowest six modes (ComputeModes), best of the repeats
  double linearise_ms = 0;  // of which the sparse assembly (Linearise), best of the repeats
  double omega1 = 0;        // lowest omega [rad/s]
  double omega_max = 0;     // highest omega [rad/s]
  int iterations = 0;
  int sparse = 0;  // 1: sparse solver, 0: dense (too few modes for Lanczos)
  long baseline_kb = 0;
  long peak_kb = 0;
};

// Runs the modal analysis of `model` in a forked child and returns what it measured.
ChildReport MeasureInChild(const tbridge::DynamicModel& model, int repeats) {
  int fds[2];
  if (pipe(fds) != 0) std::exit(4);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    ChildReport r;
    r.baseline_kb = ResidentKb();
    tbridge::ModalOptions options;
    options.count = 6;
    options.solver = tbridge::ModalSolver::kSparse;
    r.best_ms = r.linearise_ms = 1e300;
    for (int k = 0; k < repeats; ++k) {
      const auto t0 = Clock::now();
      const tbridge::LinearisedSystem sys = tbridge::Linearise(model);
      const auto t1 = Clock::now();
      const tbridge::ModalResult modes = tbridge::ComputeModes(model, options);
      const auto t2 = Clock::now();
      r.linearise_ms = std::min(r.linearise_ms, Ms(t0, t1));
      r.best_ms = std::min(r.best_ms, Ms(t1, t2));
      r.omega1 = modes.modes.front().omega_rad_s;
      r.omega_max = modes.highest_omega_rad_s;
      r.iterations = modes.iterations;
      r.sparse = modes.solver == "sparse" ? 1 : 0;
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    r.peak_kb = usage.ru_maxrss;
    if (write(fds[1], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) _exit(4);
    _exit(0);
  }
  close(fds[1]);
  ChildReport r;
  const ssize_t got = read(fds[0], &r, sizeof r);
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (got != static_cast<ssize_t>(sizeof r) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "bench_modal: the modal child failed\n");
    std::exit(4);
  }
  return r;
}

// Wall time [s] and peak RSS [KB] of one `tbridge modes` run.
void TimeProcess(const std::string& config_path, const std::string& out_path, int n) {
  const auto t0 = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    execl(TBRIDGE_BINARY, TBRIDGE_BINARY, "modes", config_path.c_str(), "-o", out_path.c_str(),
          "--modes", "6", "-q", static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  const auto t1 = Clock::now();
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  std::printf("tbridge modes --modes 6, n = %2d: %8.2f s wall, peak %8ld KB%s\n", n,
              Ms(t0, t1) / 1e3, usage.ru_maxrss, ok ? "" : " (FAILED)");
}

}  // namespace

int main(int argc, char** argv) {
  const int max_n = argc > 1 ? std::atoi(argv[1]) : 12;
  const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  std::vector<int> process_n;
  {
    std::stringstream list(argc > 3 ? argv[3] : "10,12");
    for (std::string item; std::getline(list, item, ',');) {
      if (!item.empty()) process_n.push_back(std::atoi(item.c_str()));
    }
  }
  const std::string base = std::string(TBRIDGE_SOURCE_DIR) + "/configs/paper_n3.json";
  std::printf("%3s %7s %9s %12s %9s %6s %10s %12s %12s %14s %15s\n", "n", "dofs", "design_s",
              "modes6_ms", "lin_ms", "iters", "omega1", "omega_max", "solver", "modal_peak_KB",
              "process_peak_KB");
  for (int n = 1; n <= max_n; ++n) {
    tbridge::Config c = tbridge::LoadConfig(base);
    c.bridge.n = n;
    const auto t0 = Clock::now();
    const tbridge::Design d = tbridge::RunDesign(c);
    const auto t1 = Clock::now();
    const tbridge::DynamicModel model = tbridge::BuildDynamicModel(d);
    int free_nodes = 0;
    for (const bool fixed : model.fixed) free_nodes += fixed ? 0 : 1;
    const ChildReport r = MeasureInChild(model, repeats);
    std::printf("%3d %7d %9.2f %12.2f %9.2f %6d %10.3f %12.1f %12s %14ld %15ld\n", n,
                free_nodes * model.dim, Ms(t0, t1) / 1e3, r.best_ms, r.linearise_ms, r.iterations,
                r.omega1, r.omega_max, r.sparse ? "sparse" : "dense", r.peak_kb - r.baseline_kb,
                r.peak_kb);
    std::fflush(stdout);
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "bench_modal";
  std::filesystem::create_directories(dir);
  for (const int n : process_n) {
    nlohmann::json j = nlohmann::json::parse(std::ifstream(base));
    j["bridge"]["n"] = n;
    const std::string tag = std::to_string(n);
    const std::string config_path = (dir / ("n" + tag)).replace_extension(".json").string();
    std::ofstream(config_path) << j.dump(2) << "\n";
    TimeProcess(config_path, (dir / ("modes_n" + tag)).replace_extension(".json").string(), n);
    std::fflush(stdout);
  }
  std::filesystem::remove_all(dir);
  return 0;
}
