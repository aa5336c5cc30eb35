// ParaView export of a simulation: one VTK PolyData file (.vtp, ASCII XML) per recorded
// sample and a .pvd collection that ParaView opens as a time series.
#pragma once

#include <map>
#include <string>

#include "dynamics/model.h"
#include "dynamics/simulation.h"

namespace tbridge::cli {

// The files of the export, keyed by name relative to the export folder: "run.pvd" and
// "run_<k>.vtp", k = 0.. over the history rows. Points are all nodes (pinned nodes at their
// positions); lines are the bars then the strings. Point data: displacement [m]. Cell data:
// member type (0 bar, 1 string, 2 deck string), string tension [N] (k (s - L0) when taut,
// else 0) and slack flag. Throws ConfigError naming dynamics.record.nodes when a free node was
// not recorded or nothing was recorded.
std::map<std::string, std::string> VtkSeries(const DynamicModel& model,
                                             const SimulationResult& result);

// Upper estimate of the bytes one sample of the export takes [B] (its .vtp file and its line
// in run.pvd), for the output limit checked before a run (dynamics.limits.max_output_bytes).
double VtkBytesPerSample(const DynamicModel& model);

}  // namespace tbridge::cli
