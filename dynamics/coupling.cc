#include "dynamics/coupling.h"

#include <algorithm>

#include "core/structure.h"

namespace tbridge {

long AccelerationCoupling::entries() const {
  long n = 0;
  for (const auto& d : depends_on) n += static_cast<long>(d.size());
  return n;
}

AccelerationCoupling CouplingOf(const DynamicModel& model) {
  const int n_n = model.num_nodes();
  const std::vector<int> component = ComponentOf(n_n, model.bars);
  std::vector<std::vector<int>> members(n_n);
  for (int a = 0; a < n_n; ++a) members[component[a]].push_back(a);
  std::vector<std::vector<int>> neighbours(n_n);
  for (const DynamicString& s : model.strings) {
    neighbours[s.i].push_back(s.j);
    neighbours[s.j].push_back(s.i);
  }
  AccelerationCoupling c;
  c.dim = model.dim;
  c.depends_on.resize(n_n);
  for (int a = 0; a < n_n; ++a) {
    std::vector<int>& d = c.depends_on[a];
    for (const int m : members[component[a]]) {
      d.push_back(m);
      d.insert(d.end(), neighbours[m].begin(), neighbours[m].end());
    }
    std::sort(d.begin(), d.end());
    d.erase(std::unique(d.begin(), d.end()), d.end());
  }
  return c;
}

std::vector<int> ColourColumns(const AccelerationCoupling& coupling) {
  const int n_n = static_cast<int>(coupling.depends_on.size());
  std::vector<std::vector<int>> rows_of(n_n);  // transpose: the nodes that depend on q
  for (int a = 0; a < n_n; ++a) {
    for (const int q : coupling.depends_on[a]) rows_of[q].push_back(a);
  }
  std::vector<int> colour(n_n, -1);
  std::vector<int> seen;  // seen[k] == q: colour k is taken by a conflicting column of q
  for (int q = 0; q < n_n; ++q) {
    for (const int a : rows_of[q]) {
      for (const int r : coupling.depends_on[a]) {
        if (colour[r] < 0) continue;
        if (colour[r] >= static_cast<int>(seen.size())) seen.resize(colour[r] + 1, -1);
        seen[colour[r]] = q;
      }
    }
    int k = 0;
    while (k < static_cast<int>(seen.size()) && seen[k] == q) ++k;
    colour[q] = k;
  }
  return colour;
}

}  // namespace tbridge
