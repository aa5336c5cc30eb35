// ParaView export of a simulation as one time series in two files: "run.xdmf" (XDMF 2, the
// XML that ParaView and VisIt open as a temporal collection) and "run.bin" (its heavy data,
// raw little-endian arrays addressed by byte offset). One file per sample (VTK's .vtp with a
// .pvd collection) cost about 0.3 ms a sample, 6.5 times a run of the paper's n = 3 bridge
// recording every 40 steps; a sample here is a few hundred bytes of text and one binary write.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace tbridge::cli {

// The export, written as the run records, to the streams of "run.xdmf" (`xml`: its header at
// Begin, a grid per sample, its footer at Finish) and "run.bin" (`bin`). Points are all nodes
// (pinned nodes at their positions); cells are polylines of two points, the bars then the
// strings. Point data: displacement [m]. Cell data: member type (0 bar, 1 string, 2 deck
// string), string tension [N] (k (s - L0) when taut, else 0) and slack flag. The
// connectivity and member types are written once, at the head of run.bin; each sample adds its
// points, displacements, tensions and slack flags. Begin throws ConfigError naming
// dynamics.record.nodes when a free node is not recorded.
class VtkHistory : public HistorySink {
 public:
  VtkHistory(std::ostream& xml, std::ostream& bin) : xml_(xml), bin_(bin) {}
  void Begin(const DynamicModel& model, const std::vector<int>& recorded_nodes) override;
  void Row(double t, const double* coordinates) override;
  // After the run. Throws ConfigError naming dynamics.record.nodes when nothing was recorded.
  void Finish();

 private:
  // One DataItem of run.bin: `count` values of `type` ("Float" 8 or "Int" 4) from `offset`.
  void Item(const char* dimensions, bool real, long long offset);
  std::ostream& xml_;
  std::ostream& bin_;
  const DynamicModel* model_ = nullptr;
  std::vector<int> recorded_;
  Eigen::Matrix3Xd positions_;
  // The workspace of a sample, sized at Begin: its arrays as written.
  std::vector<double> points_, displacement_, tension_;
  std::vector<int> slack_;
  long long offset_ = 0;  // bytes written to run.bin
  long long types_offset_ = 0;
  long samples_ = 0;
};

// Upper estimate of the bytes one sample of the export takes [B] (its grid in run.xdmf and its
// arrays in run.bin), for the output limit checked before a run
// (dynamics.limits.max_output_bytes).
double VtkBytesPerSample(const DynamicModel& model);

}  // namespace tbridge::cli
