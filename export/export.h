// The FE formats a design is exported to, by name, and the writer of each.
#pragma once

#include <ostream>
#include <string>

#include "design/design.h"
#include "export/calculix.h"

namespace tbridge {

inline constexpr const char* kExportFormats = "calculix or opensees";

// Whether `format` names a format: "calculix" or "opensees".
bool IsExportFormat(const std::string& format);

// Writes `design` in `format` (`options.modes` is CalculiX's). Throws ConfigError naming the
// key "format" for an unknown format, before anything is written; ModelError when the
// reference state does not stand.
void WriteExport(const Design& design, const std::string& format, const CalculixOptions& options,
                 std::ostream& os);

}  // namespace tbridge
