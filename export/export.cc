#include "export/export.h"

#include "core/error.h"
#include "export/fe_model.h"
#include "export/opensees.h"

namespace tbridge {

bool IsExportFormat(const std::string& format) {
  return format == "calculix" || format == "opensees";
}

void WriteExport(const Design& design, const std::string& format, const CalculixOptions& options,
                 std::ostream& os) {
  if (!IsExportFormat(format))
    throw ConfigError("format", "'" + format + "'", std::string("expected ") + kExportFormats);
  const FeModel model = FeModelOf(design);
  if (format == "calculix") {
    WriteCalculix(model, options, os);
  } else {
    WriteOpenSees(model, options.rigid_bars, os);
  }
}

}  // namespace tbridge
