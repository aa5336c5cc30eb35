// The extremes of every member's force over the load cases.
//
// Member forces of case c are x_c = P f_c + s_c I_k + N alpha: P the particular forces of the
// base actions, f_c the case's factors, s_c its travelling load at station k (I_k the forces
// of a unit downward load there) and N alpha the self-stress, the same in every case. So a
// member's extremes over the cases, and which case gives them, do not depend on alpha, and a
// travelling family's extremes come from each member's largest and smallest influence: the
// sizing sees two columns (largest ultimate force, smallest force of any case) and is exact.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "design/equilibrium.h"
#include "design/equilibrium_basis.h"
#include "design/load_cases.h"

namespace tbridge {

// Per member, the largest and smallest force [N] of a unit downward load on any deck station,
// and the station that gives each.
struct StationInfluence {
  Eigen::VectorXd max, min;
  std::vector<int> argmax, argmin;
  double load_residual = 0;  // largest |A x + w| of any station's unit load [N]
};
// Solves the stations in blocks of `block` right-hand sides, so memory stays members x block.
StationInfluence InfluenceOfStations(const EquilibriumSolver& solver, const EquilibriumSystem& eq,
                                     const Actions& actions, int block = 256);

struct MemberExtreme {
  double force = 0;  // [N], compression for bars, tension for strings, without the self-stress
  int case_index = -1;
  int station = -1;  // the travelling load's station, -1 when the case has none
};

struct CaseEnvelope {
  std::vector<MemberExtreme> uls_max;  // largest force over the ultimate cases: sizes the member
  std::vector<MemberExtreme>
      min;  // smallest force over every case: strings stay taut, bars compressed
};

// `base` is members x kNumBaseActions (the particular forces of Actions::base); `influence`
// may be null when no case travels.
CaseEnvelope EnvelopeOf(const std::vector<LoadCase>& cases, const Eigen::MatrixXd& base,
                        const StationInfluence* influence);

// "uls_travelling at node 12" (1-based node of the station's first deck node) or the case name.
std::string CaseLabel(const std::vector<LoadCase>& cases, const Actions& actions,
                      const MemberExtreme& e);

}  // namespace tbridge
