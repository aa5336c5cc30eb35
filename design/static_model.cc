#include "design/static_model.h"

namespace tbridge {

StaticModel StaticModelOf(const Design& d) {
  StaticModel m;
  m.structure = d.topology.structure;
  for (const MemberSizing& s : d.strings) {
    m.string_stiffness.push_back(s.stiffness);
    m.string_rest_length.push_back(s.rest_length);
  }
  return m;
}

StaticState ReferenceState(const StaticModel& model, const Design& d) {
  const Structure& s = d.topology.structure;
  return StateAt(model, s.nodes, d.reference_forces.head(s.num_bars()), d.loads);
}

}  // namespace tbridge
