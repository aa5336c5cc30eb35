#include "core/structure.h"

#include <algorithm>
#include <set>
#include <utility>

#include "core/error.h"

namespace tbridge {

int Structure::num_free_nodes() const {
  return static_cast<int>(std::count(fixed.begin(), fixed.end(), false));
}

std::string Structure::Name(const Member& m) {
  return std::to_string(m.i + 1) + "-" + std::to_string(m.j + 1);
}

std::vector<int> Structure::BarsPerNode() const {
  std::vector<int> count(num_nodes(), 0);
  for (const Member& b : bars) {
    ++count[b.i];
    ++count[b.j];
  }
  return count;
}

int Structure::TensegrityClass() const {
  const std::vector<int> count = BarsPerNode();
  return count.empty() ? 0 : *std::max_element(count.begin(), count.end());
}

void Structure::Validate() const {
  if (static_cast<int>(fixed.size()) != num_nodes()) {
    throw ModelError("structure: fixed flags (" + std::to_string(fixed.size()) +
                     ") do not match the node count (" + std::to_string(num_nodes()) + ")");
  }
  std::set<std::pair<int, int>> seen;
  auto check = [&](const Member& m, const char* kind) {
    if (m.i < 0 || m.j < 0 || m.i >= num_nodes() || m.j >= num_nodes() || m.i == m.j) {
      throw ModelError(std::string("structure: ") + kind + " " + Name(m) +
                       " has an invalid node index (nodes are 1.." + std::to_string(num_nodes()) +
                       ")");
    }
    if (Length(m) <= 0.0) {
      throw ModelError(std::string("structure: ") + kind + " " + Name(m) + " has zero length");
    }
    if (!seen.insert(std::minmax(m.i, m.j)).second) {
      throw ModelError(std::string("structure: member ") + Name(m) + " is listed twice");
    }
  };
  for (const Member& b : bars) check(b, "bar");
  for (const Member& s : strings) check(s, "string");
}

}  // namespace tbridge
