// The writer thread behind `simulate`'s history.csv and VTK series: every row arrives, in
// order and unchanged, through a ring far smaller than the run; a sink's failure on the writer
// thread reaches the caller; and the CLI's streamed CSV agrees with the in-memory history.

#include "tools/background_history.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_support.h"
#include "core/config.h"
#include "csv_rows.h"
#include "dynamics/simulation.h"
#include "dynamics/structure_model.h"

namespace tbridge {
namespace {

// Keeps what it is given (on the writer thread); throws at row `fail_at` when asked.
class KeptRows : public HistorySink {
 public:
  explicit KeptRows(long fail_at = -1) : fail_at_(fail_at) {}
  void Begin(const DynamicModel& model, const std::vector<int>& nodes) override {
    width = model.dim * static_cast<int>(nodes.size());
  }
  void Row(double t, const double* c) override {
    if (static_cast<long>(rows.size()) == fail_at_) throw std::runtime_error("disk full");
    rows.emplace_back(1, t);
    rows.back().insert(rows.back().end(), c, c + width);
  }
  int width = 0;
  std::vector<std::vector<double>> rows;

 private:
  long fail_at_;
};

DynamicModel TwoNodes() {
  DynamicModel m;
  m.dim = 3;
  m.positions = Eigen::Matrix3Xd::Zero(3, 2);
  return m;
}

TEST_CASE("background history: 10000 rows through a ring of 8 arrive whole and in order") {
  KeptRows kept;
  cli::BackgroundHistory background({&kept}, /*always=*/true, /*capacity=*/8);
  background.Begin(TwoNodes(), {0, 1});
  const long n = 10000;
  for (long r = 0; r < n; ++r) {
    const double c[6] = {1.0 * r, 2.0 * r, 3.0 * r, -1.0 * r, -2.0 * r, -3.0 * r};
    background.Row(0.5 * r, c);
  }
  background.Finish();
  REQUIRE(kept.rows.size() == static_cast<size_t>(n));
  bool exact = true;  // copied doubles: bit for bit, no tolerance
  for (long r = 0; r < n; ++r) {
    const std::vector<double>& row = kept.rows[static_cast<size_t>(r)];
    exact = exact && row == std::vector<double>{0.5 * r,  1.0 * r,  2.0 * r, 3.0 * r,
                                                -1.0 * r, -2.0 * r, -3.0 * r};
  }
  CHECK(exact);
}

TEST_CASE("background history: narrow rows go straight through, on the caller's thread") {
  KeptRows kept;
  cli::BackgroundHistory background({&kept});
  background.Begin(TwoNodes(), {0, 1});  // 7 values a row, below kThreadedWidth
  const double c[6] = {1, 2, 3, 4, 5, 6};
  for (int r = 0; r < 3; ++r) background.Row(r, c);
  CHECK(kept.rows.size() == 3);  // before Finish: nothing was queued
  background.Finish();
  CHECK(kept.rows.size() == 3);
}

TEST_CASE("background history: a sink's failure on the writer thread is thrown by Finish") {
  KeptRows kept(/*fail_at=*/5);
  cli::BackgroundHistory background({&kept}, /*always=*/true, /*capacity=*/4);
  background.Begin(TwoNodes(), {0, 1});
  const double c[6] = {0, 0, 0, 0, 0, 0};
  for (int r = 0; r < 100; ++r) background.Row(r, c);  // never blocks on the dead writer
  CHECK_THROWS_WITH(background.Finish(), "disk full");
  CHECK(kept.rows.size() == 5);
}

TEST_CASE("simulate: the streamed history.csv of the MOTES prism is the in-memory history") {
  const std::string config = TBRIDGE_SOURCE_DIR "/configs/motes_prism.json";
  const test::fs::path dir = test::FreshDir("background_prism");
  const test::CliResult r = test::RunTbridge(
      dir, "simulate " + test::Quote(config) + " -o " + test::Quote((dir / "out").string()));
  INFO(r.err);
  REQUIRE(r.code == 0);
  const std::vector<std::vector<double>> csv =
      test::ReadCsvRows((dir / "out" / "history.csv").string());
  const Config c = LoadConfig(config);
  const DynamicModel model = BuildStructureModel(*c.structure, ModelOptionsOf(*c.dynamics));
  const SimulationResult memory = Simulate(model, *c.dynamics);
  REQUIRE(static_cast<long>(csv.size()) ==
          memory.history.rows());  // 501 records: t = 0 and every 10th step
  double worst = 0;
  for (Eigen::Index k = 0; k < memory.history.rows(); ++k) {
    REQUIRE(static_cast<long>(csv[static_cast<size_t>(k)].size()) == memory.history.cols());
    for (Eigen::Index j = 0; j < memory.history.cols(); ++j) {
      const double v = memory.history(k, j);
      worst = std::max(worst, std::abs(csv[static_cast<size_t>(k)][static_cast<size_t>(j)] - v) /
                                  std::max(std::abs(v), 1e-300));
    }
  }
  // 12 significant digits: a printed value is within half a unit in its 12th digit, 5e-12 relative.
  CHECK(worst <= 5e-12);
}

}  // namespace
}  // namespace tbridge
