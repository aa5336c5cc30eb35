#include "dynamics/model.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace tbridge {

void ShareStringMass(DynamicModel& m, StringMassMode mode) {
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
  for (const DynamicString& s : m.strings) {
    for (const int end : {s.i, s.j}) {
      const double half = 0.5 * s.mass;
      if (m.fixed[end]) continue;  // carried by the support
      const int count = bars_at[end + 1] - bars_at[end];
      if (mode == StringMassMode::kAtNodes || (mode == StringMassMode::kOnBars && count == 0)) {
        m.node_mass(end) += half;
      } else if (mode == StringMassMode::kOnBars) {
        for (int r = bars_at[end]; r < bars_at[end + 1]; ++r) m.bars[bar_of[r]].mass += half / count;
      }
    }
  }
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

double MovingMass(const DynamicModel& model) {
  double total = model.node_mass.size() != 0 ? model.node_mass.sum() : 0.0;
  for (const DynamicBar& b : model.bars) total += b.mass;
  return total;
}

}  // namespace tbridge
