// The mirror symmetries of a bridge: each node's and member's image across one of its planes
// of symmetry (x = span / 2; between the planes of a 3D bridge), and what a mirror does to its
// loads, its cases, its deck stations and a static state. The sizing poses one row of each
// mirrored pair (sizing/sizing_problem.h) and the checks solve one station of each
// (checks/static_check.h, checks/modal_run.h): a symmetric bridge under a mirrored load is in
// the mirrored equilibrium.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/structure.h"
#include "design/load_cases.h"
#include "statics/static_solve.h"

namespace tbridge {

struct Mirror {
  std::vector<int> node, member;  // per node, per member [bars; strings]: its image, -1 for none
  // A point p's image is flip * p + offset (componentwise); a force f's is flip * f.
  Eigen::Vector3d flip = Eigen::Vector3d::Ones(), offset = Eigen::Vector3d::Zero();

  // Every node and member has an image, and a support's image is a support.
  bool Complete(const Structure& s) const;
  // The image of node loads (3 x nodes).
  Eigen::Matrix3Xd Of(const Eigen::Matrix3Xd& loads) const;
  // Whether `loads` is its own image.
  bool Keeps(const Eigen::Matrix3Xd& loads) const { return Same(Of(loads), loads); }
  // Whether `per_string` (one value per string) equals its images' (to 1e-12 relative: sizes
  // given one value per mirrored group, copied, not computed).
  bool KeepsStrings(const std::vector<double>& per_string, int bars) const;
  // Equal to 1e-9 of the larger entry: loads built from the same nodal shares on both sides
  // differ by rounding alone where they are alike, and by the loads themselves where not; a
  // state's forces and positions likewise, by one solve's rounding.
  static bool Same(const Eigen::Ref<const Eigen::MatrixXd>& a,
                   const Eigen::Ref<const Eigen::MatrixXd>& b);
  // The image of a static state (positions, forces member by member, reactions), and of a
  // solve's result; of a complete mirror only.
  StaticState Of(const StaticState& state) const;
  StaticResult Of(const StaticResult& result) const;
};

// The two mirrors of `s`: about x = span / 2, then between the planes of a 3D bridge (on a
// planar one, each node its own image). A node or member without an image has -1.
std::vector<Mirror> Mirrors(const Structure& s, double span);

// Per deck station, its image under `m`: the station at its mirrored x whose load is the
// image of its own. Empty where some station has none.
std::vector<int> StationImages(const Mirror& m, const Actions& actions, double span);

// Per case, its image under `m`: the case of its limit state and travelling load whose loads
// are the image of its own (itself for a symmetric case; the payload on the left for the
// right's). Empty where some case has none.
std::vector<int> CaseImages(const Mirror& m, const Actions& actions,
                            const std::vector<LoadCase>& cases);

// The mirror about mid-span of a static model whose structure, string sizes, reference state
// `start` and standing `loads` are their own images, with each deck station's image: a load at
// a station then has the mirror image of the response to the same load at the image station.
struct StationMirror {
  Mirror mirror;
  std::vector<int> station_image;
};
// None where the model, state or loads are not symmetric (a design edited on one side), or a
// station has no image.
std::optional<StationMirror> MidSpanMirror(const StaticModel& model, const StaticState& start,
                                           const Eigen::Matrix3Xd& loads, const Actions& actions,
                                           double span);

}  // namespace tbridge
