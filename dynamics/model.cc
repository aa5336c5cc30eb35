#include "dynamics/model.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "core/error.h"

namespace tbridge {

namespace {

std::string Count(std::size_t n) { return std::to_string(n); }

}  // namespace

void CheckModel(const DynamicModel& m, const std::string& where) {
  const int n_n = m.num_nodes();
  const auto fail = [&](const std::string& what) { throw ModelError(where + ": " + what); };
  if (m.dim != 2 && m.dim != 3) fail("dim must be 2 or 3, got " + std::to_string(m.dim));
  const auto nodes = [&](std::size_t size, const char* what) {
    if (size != static_cast<std::size_t>(n_n)) {
      fail(std::string(what) + " has " + Count(size) + " entries for " + Count(n_n) + " nodes");
    }
  };
  nodes(m.fixed.size(), "fixed");
  if (m.node_mass.size() != 0) nodes(static_cast<std::size_t>(m.node_mass.size()), "node_mass");
  if (m.loads.size() != 0) nodes(static_cast<std::size_t>(m.loads.cols()), "loads");
  if (m.node_mass.size() != 0 && !(m.node_mass.minCoeff() >= 0)) fail("node_mass must be >= 0");
  if (!(m.mass_damping_per_s >= 0) || !std::isfinite(m.mass_damping_per_s)) {
    fail("mass_damping_per_s must be finite and >= 0");
  }
  const BarColumns& b = m.bars;
  for (const std::size_t size : {b.j.size(), b.mass.size(), b.length.size()}) {
    if (size != b.size()) fail("the bar columns differ in length");
  }
  const StringColumns& s = m.strings;
  for (const std::size_t size :
       {s.j.size(), s.rest_length.size(), s.stiffness.size(), s.damping.size(), s.mass.size(),
        s.area.size(), m.names.string_name.size(), m.names.string_group.size()}) {
    if (size != s.size()) fail("the string columns or names differ in length");
  }
  const auto member = [&](const char* kind, int i, int j) {
    return std::string(kind) + " " + std::to_string(i + 1) + "-" + std::to_string(j + 1);
  };
  const auto ends = [&](const char* kind, int i, int j) {
    if (i < 0 || j < 0 || i >= n_n || j >= n_n || i == j) {
      fail(member(kind, i, j) + " must join two distinct nodes of 1.." + Count(n_n));
    }
  };
  for (std::size_t k = 0; k < b.size(); ++k) {
    ends("bar", b.i[k], b.j[k]);
    if (!(b.mass[k] >= 0 && b.length[k] > 0))
      fail(member("bar", b.i[k], b.j[k]) + " needs mass >= 0 and length > 0");
  }
  for (std::size_t k = 0; k < s.size(); ++k) {
    ends("string", s.i[k], s.j[k]);
    if (!(s.rest_length[k] > 0 && s.stiffness[k] >= 0 && s.damping[k] >= 0 && s.mass[k] >= 0 &&
          s.area[k] >= 0)) {
      fail(member("string", s.i[k], s.j[k]) +
           " needs L0 > 0, k >= 0, c >= 0, mass >= 0 and area >= 0");
    }
  }
}

void ForEachStringMassShare(
    const DynamicModel& m, StringMassMode mode,
    const std::function<void(int string, int node, int bar, int count)>& share) {
  // Bars at each node in compressed rows (bars_at[a] .. bars_at[a + 1] in bar_of), built once so
  // that sharing is O(members). Each bar's shares arrive in the same order as a search over all
  // bars would add them (strings in order, end i then end j), so the sums are bit-identical.
  const int n_n = m.num_nodes();
  std::vector<int> bars_at(n_n + 1, 0);
  for (const DynamicBar& b : m.bars) {
    ++bars_at[b.i + 1];
    if (b.j != b.i) ++bars_at[b.j + 1];
  }
  for (int a = 0; a < n_n; ++a) bars_at[a + 1] += bars_at[a];
  std::vector<int> bar_of(bars_at[n_n]);
  std::vector<int> fill(bars_at.begin(), bars_at.end() - 1);
  for (size_t k = 0; k < m.bars.size(); ++k) {
    const DynamicBar& b = m.bars[k];
    bar_of[fill[b.i]++] = static_cast<int>(k);
    if (b.j != b.i) bar_of[fill[b.j]++] = static_cast<int>(k);
  }
  for (size_t k = 0; k < m.strings.size(); ++k) {
    const DynamicString s = m.strings[k];
    for (const int end : {s.i, s.j}) {
      if (m.fixed[end]) continue;  // carried by the support
      const int count = bars_at[end + 1] - bars_at[end];
      if (mode == StringMassMode::kAtNodes || (mode == StringMassMode::kOnBars && count == 0)) {
        share(static_cast<int>(k), end, -1, 1);
      } else if (mode == StringMassMode::kOnBars) {
        for (int r = bars_at[end]; r < bars_at[end + 1]; ++r)
          share(static_cast<int>(k), end, bar_of[r], count);
      }
    }
  }
}

void ShareStringMass(DynamicModel& m, StringMassMode mode) {
  ForEachStringMassShare(m, mode, [&m](int k, int node, int bar, int count) {
    const double half = 0.5 * m.strings.mass[static_cast<size_t>(k)];
    if (bar < 0) {
      m.node_mass(node) += half;
    } else {
      m.bars.mass[static_cast<size_t>(bar)] += half / count;
    }
  });
}

void AddStructureWeight(DynamicModel& m) {
  for (const DynamicBar& b : m.bars) {
    m.loads(1, b.i) -= 0.5 * b.mass * m.gravity;
    m.loads(1, b.j) -= 0.5 * b.mass * m.gravity;
  }
  for (int a = 0; a < m.num_nodes(); ++a) m.loads(1, a) -= m.node_mass(a) * m.gravity;
}

int MaxBarsAtANode(const DynamicModel& model) {
  std::vector<int> count(model.num_nodes(), 0);
  int most = 0;
  for (const DynamicBar& b : model.bars) {
    for (const int a : {b.i, b.j}) {
      if (a >= 0 && a < model.num_nodes()) most = std::max(most, ++count[a]);
    }
  }
  return most;
}

std::vector<std::vector<ReactionEnd>> ReactionEnds(const DynamicModel& model) {
  const int nb = static_cast<int>(model.bars.size());
  std::vector<std::vector<ReactionEnd>> out;
  for (const std::vector<int>& group : model.reaction_groups) {
    std::vector<ReactionEnd> ends;
    const auto at = [&group](int node) {
      return std::find(group.begin(), group.end(), node) != group.end();
    };
    const auto add = [&](int member, int i, int j) {
      if (at(i)) ends.push_back({member, +1.0});
      if (at(j)) ends.push_back({member, -1.0});
    };
    for (int k = 0; k < nb; ++k) add(k, model.bars.i[k], model.bars.j[k]);
    for (int k = 0; k < static_cast<int>(model.strings.size()); ++k)
      add(nb + k, model.strings.i[k], model.strings.j[k]);
    out.push_back(std::move(ends));
  }
  return out;
}

std::vector<Eigen::Vector3d> ReactionGroupLoads(const DynamicModel& model) {
  std::vector<Eigen::Vector3d> out;
  for (const std::vector<int>& group : model.reaction_groups) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const int v : group) {
      if (model.loads.size() != 0) sum += model.loads.col(v);
    }
    out.push_back(sum);
  }
  return out;
}

double MovingMass(const DynamicModel& model) {
  double total = model.node_mass.size() != 0 ? model.node_mass.sum() : 0.0;
  for (const DynamicBar& b : model.bars) total += b.mass;
  return total;
}

}  // namespace tbridge
