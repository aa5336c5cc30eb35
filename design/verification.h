// What the checks of a sized design found (filled by verify/, written by the design report):
// plain data, so that the design's outputs can carry it without knowing how it was checked.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace tbridge {

// One load case solved as a nonlinear static problem (verify/static_check.h).
struct CaseResponse {
  std::string label;  // the case, with its station for a travelling family ("sls_travelling at node 5")
  int case_index = -1;
  int station = -1;
  bool converged = false;
  std::string message;         // why not, when not converged
  double deflection_m = 0;     // largest vertical deck-node displacement from the drawn geometry [m]
  int deflection_node = -1;    // 0-based
  Eigen::Matrix3Xd reactions;  // 3 x n_n [N], zero at free nodes
  double balance = 0;          // |sum reactions + sum loads| / sum |loads|
  int slack_strings = 0;
};

struct StaticCheck {
  bool done = false;
  std::vector<CaseResponse> cases;
  double deflection_limit_m = 0;  // span / loads.deflection_limit
  double deflection_max_m = 0;    // over the serviceability cases
  std::string deflection_case;
  int stations_per_family = 0;    // travelling stations solved per family
  bool all_converged = true;
};

// The dynamic check (verify/dynamic_check.h): each dynamic load run at service level.
struct GroupAmplification {
  std::string group;          // member group ("deck", "substructure", "vertical", ...)
  double static_peak = 0;     // largest force of the group's members over the static counterpart [N]
  double dynamic_peak = 0;    // largest in the run [N]
  double amplification = 0;   // the largest dynamic / static ratio of a member of the group
};

struct DynamicRun {
  std::string name;        // "paper_travelling", "moving_load" or "wind_gust"
  std::string load;        // what it applies, as an engineer writes it
  bool done = false;
  std::string note;        // why it was skipped, when not done
  std::string integrator;  // as resolved
  double dt = 0;           // [s]
  long steps = 0;
  double duration = 0;     // [s]
  double peak_deck_displacement = 0;  // [m], from the run's start (static equilibrium)
  std::vector<GroupAmplification> groups;
};

struct DynamicCheck {
  std::vector<DynamicRun> runs;
  bool ran() const { return !runs.empty(); }
  // The runs not done, with their notes ("moving_load skipped: ..."); empty when all were.
  std::string NotDone() const {
    std::string out;
    for (const DynamicRun& r : runs) {
      if (r.done) continue;
      if (!out.empty()) out.append("; ");
      out.append(r.name).append(" ").append(r.note);
    }
    return out;
  }
};

// The resizing loop's record (verify/verified_design.h).
struct Resizing {
  int iterations = 0;                     // designs run
  bool converged = false;                 // the last one passed every check
  std::vector<double> structure_mass_kg;  // per design
  std::string why;                        // when not converged: the last verdict
};

}  // namespace tbridge
