// The check of a sized structure (truss/truss_model.h): every member's utilisation in every load
// case, the displacement and frequency limits, the reactions and the verdict, from one linear
// analysis at the areas given. It returns a report and changes nothing.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/named_choice.h"
#include "truss/truss_analysis.h"
#include "truss/truss_model.h"

namespace tbridge {

// A utilisation within this of 1 passes: the sizing's certificate holds its rows to 1e-6.
inline constexpr double kTrussPassTolerance = 1e-6;

// How a member of a structure fails, with its text in the report.
enum class TrussFailure {
  kNone,  // no load case (frequency limits only): its text is empty, as the report always had it
  kTension,
  kCompression,
  kBuckling,
  kSlack,         // a string in compression
  kTensionInBar,  // a bar (compression only) pulled
};
inline constexpr std::array<Named<TrussFailure>, 6> kTrussFailureNames{
    {{TrussFailure::kNone, ""},
     {TrussFailure::kTension, "tension"},
     {TrussFailure::kCompression, "compression"},
     {TrussFailure::kBuckling, "buckling"},
     {TrussFailure::kSlack, "slack"},
     {TrussFailure::kTensionInBar, "tension in a bar"}}};
inline const char* NameOf(TrussFailure f) { return NameIn(kTrussFailureNames, f); }

struct TrussMemberCheck {
  double area = 0;         // [m^2]
  double force = 0;        // [N], tension > 0, in the governing case
  double utilisation = 0;  // the largest over the cases and modes of failure
  TrussFailure governed_by = TrussFailure::kNone;
  int governing_case = 0;
};

struct TrussLimitCheck {
  std::string what;         // "node 3 y" or "mode 1"
  double value = 0;         // the largest |u| [m] or the frequency [Hz]
  double limit = 0;         // max_m or min_hz
  double utilisation = 0;   // |u| / max, or (f_min / f)^2 (the row's own measure)
  int governing_case = -1;  // -1 for a frequency
};

struct TrussCheck {
  Eigen::VectorXd prestress;                // per member [N], as checked: a self-stress, or 0
  std::vector<TrussCaseResponse> cases;     // displacements and member forces, by case
  std::vector<Eigen::Matrix3Xd> reactions;  // by case: per node, zero where free [N]
  double equilibrium_residual = 0;          // |sum of reactions and loads| over cases [N]
  Eigen::VectorXd frequencies_hz;           // the lowest (at least the limits', up to 6)
  std::vector<TrussMemberCheck> members;
  std::vector<TrussLimitCheck> displacements;
  std::vector<TrussLimitCheck> frequencies;
  double utilisation_max = 0;
  std::string governing;  // what has utilisation_max: "member 3-4 (buckling, case heavy)"
  std::string lever;      // where it fails: the keys that move the governing row
  bool pass = false;      // utilisation_max <= 1 + kTrussPassTolerance

  // Each member's area as checked [m^2].
  Eigen::VectorXd Areas() const;
};

// `member_areas`: each member's area [m^2] (its group's, or its own in an edited design file);
// `prestress`: each member's prestress force [N], a self-stress (empty: none).
TrussCheck CheckTruss(const TrussModel& model, const Eigen::VectorXd& member_areas,
                      const Eigen::VectorXd& prestress = Eigen::VectorXd());

}  // namespace tbridge
