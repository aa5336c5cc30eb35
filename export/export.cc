#include "export/export.h"

#include "export/fe_model.h"
#include "export/opensees.h"

namespace tbridge {

void WriteExport(const Design& design, ExportFormat format, const CalculixOptions& options,
                 std::ostream& os) {
  const FeModel model = FeModelOf(design);
  if (format == ExportFormat::kCalculix) {
    WriteCalculix(model, options, os);
  } else {
    WriteOpenSees(model, options.rigid_bars, os);
  }
}

}  // namespace tbridge
