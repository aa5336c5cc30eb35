// ParaView export of a simulation: one VTK PolyData file (.vtp, ASCII XML) per recorded
// sample and a .pvd collection that ParaView opens as a time series.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace tbridge::cli {

// The export, written as the run records: "run_<k>.vtp", k = 0.. over the recorded samples,
// each handed to `emit` (name relative to the export folder, content) when taken, and the
// collection "run.pvd" streamed to `pvd` (its header at Begin, a line per sample, its footer at
// Finish). Points are all nodes (pinned nodes at their positions); lines are the bars then the
// strings. Point data: displacement [m]. Cell data: member type (0 bar, 1 string, 2 deck
// string), string tension [N] (k (s - L0) when taut, else 0) and slack flag. Begin throws
// ConfigError naming dynamics.record.nodes when a free node is not recorded.
class VtkHistory : public HistorySink {
 public:
  using Emit = std::function<void(const std::string& name, const std::string& content)>;
  VtkHistory(std::ostream& pvd, Emit emit) : pvd_(pvd), emit_(std::move(emit)) {}
  void Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) override;
  void Row(double t, const double* coordinates) override;
  // After the run. Throws ConfigError naming dynamics.record.nodes when nothing was recorded.
  void Finish();

 private:
  std::ostream& pvd_;
  Emit emit_;
  const DynamicModel* model_ = nullptr;
  std::vector<int> recorded_;
  Eigen::Matrix3Xd positions_;
  long samples_ = 0;
};

// Upper estimate of the bytes one sample of the export takes [B] (its .vtp file and its line
// in run.pvd), for the output limit checked before a run (dynamics.limits.max_output_bytes).
double VtkBytesPerSample(const DynamicModel& model);

}  // namespace tbridge::cli
