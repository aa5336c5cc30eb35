#include "design/mirror.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace tbridge {

bool Mirror::Complete(const Structure& s) const {
  for (size_t a = 0; a < node.size(); ++a) {
    if (node[a] < 0 || s.fixed[a] != s.fixed[static_cast<size_t>(node[a])]) return false;
  }
  return std::all_of(member.begin(), member.end(), [](int j) { return j >= 0; });
}

Eigen::Matrix3Xd Mirror::Of(const Eigen::Matrix3Xd& loads) const {
  Eigen::Matrix3Xd out = Eigen::Matrix3Xd::Zero(3, loads.cols());
  for (Eigen::Index a = 0; a < loads.cols(); ++a) {
    if (node[static_cast<size_t>(a)] >= 0)
      out.col(node[static_cast<size_t>(a)]) = flip.cwiseProduct(loads.col(a));
  }
  return out;
}

bool Mirror::KeepsStrings(const std::vector<double>& per_string, int bars) const {
  for (size_t k = 0; k < per_string.size(); ++k) {
    const int image = member[static_cast<size_t>(bars) + k] - bars;
    if (image < 0) return false;
    const double a = per_string[k], b = per_string[static_cast<size_t>(image)];
    if (!(std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)))) return false;
  }
  return true;
}

bool Mirror::Same(const Eigen::Ref<const Eigen::MatrixXd>& a,
                  const Eigen::Ref<const Eigen::MatrixXd>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  if (a.size() == 0) return true;
  return (a - b).cwiseAbs().maxCoeff() <=
         1e-9 * std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
}

StaticState Mirror::Of(const StaticState& state) const {
  StaticState out = state;
  const int nb = static_cast<int>(state.bar_compression.size());
  for (Eigen::Index a = 0; a < state.nodes.cols(); ++a) {
    const int image = node[static_cast<size_t>(a)];
    out.nodes.col(image) = flip.cwiseProduct(state.nodes.col(a)) + offset;
    if (state.reactions.cols() > 0)
      out.reactions.col(image) = flip.cwiseProduct(state.reactions.col(a));
  }
  for (int b = 0; b < nb; ++b)
    out.bar_compression[member[static_cast<size_t>(b)]] = state.bar_compression[b];
  for (Eigen::Index k = 0; k < state.string_tension.size(); ++k) {
    out.string_tension[member[static_cast<size_t>(nb + k)] - nb] = state.string_tension[k];
  }
  return out;
}

StaticResult Mirror::Of(const StaticResult& result) const {
  StaticResult out = result;
  out.state = Of(result.state);
  return out;
}

std::vector<Mirror> Mirrors(const Structure& s, double span) {
  const int nn = s.num_nodes(), nb = s.num_bars(), nm = nb + s.num_strings();
  const double tol = 1e-9 * span;
  const double z_mid = 0.5 * (s.nodes.row(2).minCoeff() + s.nodes.row(2).maxCoeff());
  std::map<std::pair<int, int>, int> member_at;
  for (int j = 0; j < nm; ++j) {
    const Member& m = s.MemberAt(j);
    member_at[{std::min(m.i, m.j), std::max(m.i, m.j)}] = j;
  }
  std::vector<Mirror> out;
  for (const bool in_x : {true, false}) {
    Mirror mirror;
    mirror.flip[in_x ? 0 : 2] = -1;
    mirror.offset[in_x ? 0 : 2] = in_x ? span : 2 * z_mid;
    mirror.node.assign(static_cast<size_t>(nn), -1);
    for (int v = 0; v < nn; ++v) {
      const Eigen::Vector3d p = mirror.flip.cwiseProduct(s.nodes.col(v)) + mirror.offset;
      for (int w = 0; w < nn; ++w) {
        if ((s.nodes.col(w) - p).cwiseAbs().maxCoeff() <= tol) {
          mirror.node[static_cast<size_t>(v)] = w;
          break;
        }
      }
    }
    mirror.member.assign(static_cast<size_t>(nm), -1);
    for (int j = 0; j < nm; ++j) {
      const Member& m = s.MemberAt(j);
      const int a = mirror.node[static_cast<size_t>(m.i)],
                b = mirror.node[static_cast<size_t>(m.j)];
      if (a < 0 || b < 0) continue;
      const auto it = member_at.find({std::min(a, b), std::max(a, b)});
      if (it == member_at.end() || (it->second < nb) != (j < nb)) continue;
      mirror.member[static_cast<size_t>(j)] = it->second;
    }
    out.push_back(std::move(mirror));
  }
  return out;
}

std::vector<int> StationImages(const Mirror& m, const Actions& actions, double span) {
  const int stations = static_cast<int>(actions.station_nodes.size());
  std::vector<int> out(static_cast<size_t>(stations), -1);
  for (int k = 0; k < stations; ++k) {
    const double x = m.flip[0] < 0 ? span - actions.station_x[k] : actions.station_x[k];
    const Eigen::Matrix3Xd image = m.Of(actions.StationLoad(k, 1.0));
    for (int k2 = 0; k2 < stations; ++k2) {
      if (std::abs(actions.station_x[k2] - x) <= 1e-9 * span &&
          Mirror::Same(image, actions.StationLoad(k2, 1.0))) {
        out[static_cast<size_t>(k)] = k2;
        break;
      }
    }
    if (out[static_cast<size_t>(k)] < 0) return {};
  }
  return out;
}

std::vector<int> CaseImages(const Mirror& m, const Actions& actions,
                            const std::vector<LoadCase>& cases) {
  std::vector<int> out(cases.size(), -1);
  for (size_t c = 0; c < cases.size(); ++c) {
    const Eigen::Matrix3Xd image = m.Of(actions.Loads(cases[c]));
    for (size_t c2 = 0; c2 < cases.size(); ++c2) {
      const LoadCase &a = cases[c], &b = cases[c2];
      if (a.state == b.state && a.station_load == b.station_load &&
          Mirror::Same(image, actions.Loads(b))) {
        out[c] = static_cast<int>(c2);
        break;
      }
    }
    if (out[c] < 0) return {};
  }
  return out;
}

std::optional<StationMirror> MidSpanMirror(const StaticModel& model, const StaticState& start,
                                           const Eigen::Matrix3Xd& loads, const Actions& actions,
                                           double span) {
  const Structure& s = model.structure;
  std::vector<Mirror> mirrors = Mirrors(s, span);
  Mirror& m = mirrors.front();  // about x = span / 2
  if (!m.Complete(s) || !m.Keeps(loads) || !m.KeepsStrings(model.string_stiffness, s.num_bars()) ||
      !m.KeepsStrings(model.string_rest_length, s.num_bars())) {
    return std::nullopt;
  }
  // The reference state is its own image (to 1e-9 of its coordinates and forces: one solve's
  // rounding).
  const StaticState image = m.Of(start);
  if (!Mirror::Same(image.nodes, start.nodes) ||
      !Mirror::Same(image.bar_compression, start.bar_compression) ||
      !Mirror::Same(image.string_tension, start.string_tension)) {
    return std::nullopt;
  }
  std::vector<int> stations = StationImages(m, actions, span);
  if (stations.empty()) return std::nullopt;
  return StationMirror{std::move(m), std::move(stations)};
}

}  // namespace tbridge
