#include "export/fe_model.h"

#include "bridge/design_model.h"
#include "design/case_envelope.h"
#include "design/static_model.h"

namespace tbridge {

FeModel FeModelOf(const Design& d) {
  FeModel fe;
  fe.statics = StaticModelOf(d);
  fe.reference = ReferenceState(fe.statics, d);
  fe.youngs_modulus = BarMaterial(d.config).youngs_modulus;
  for (const MemberSizing& b : d.bars) fe.bar_area.push_back(b.area);
  for (const MemberSizing& s : d.strings) fe.string_area.push_back(s.area);
  fe.reference_loads = d.loads;
  const int stations = static_cast<int>(d.actions.station_nodes.size());
  for (size_t c = 0; c < d.cases.size(); ++c) {
    const LoadCase& lc = d.cases[c];
    const int last = lc.station_load != 0 ? stations - 1 : -1;
    for (int k = lc.station_load != 0 ? 0 : -1; k <= last; ++k) {
      fe.cases.push_back({CaseLabel(d.cases, d.actions, MemberExtreme{0, static_cast<int>(c), k}),
                          d.actions.Loads(lc, k)});
    }
  }
  fe.modal = BuildDynamicModel(d, ModalModelOptions(d.config));
  return fe;
}

}  // namespace tbridge
