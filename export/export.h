// The FE formats a design is exported to, by name, and the writer of each.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "core/named_choice.h"
#include "design/design.h"
#include "export/calculix.h"

namespace tbridge {

enum class ExportFormat { kCalculix, kOpenSees };
inline constexpr std::array<Named<ExportFormat>, 2> kExportFormatNames{
    {{ExportFormat::kCalculix, "calculix"}, {ExportFormat::kOpenSees, "opensees"}}};

// The format `text` names (one of kExportFormatNames); nullopt for any other text.
inline std::optional<ExportFormat> ExportFormatOf(const std::string& text) {
  return ValueIn(kExportFormatNames, text);
}

// What an error says is allowed where a text names no format: "expected calculix or opensees".
inline std::string ExpectedExportFormats() {
  std::string out = "expected";
  for (size_t k = 0; k < kExportFormatNames.size(); ++k)
    out += std::string(k == 0 ? " " : " or ") + kExportFormatNames[k].name;
  return out;
}

// Writes `design` in `format` (`options.modes` is CalculiX's). Throws ModelError when the
// reference state does not stand.
void WriteExport(const Design& design, ExportFormat format, const CalculixOptions& options,
                 std::ostream& os);

}  // namespace tbridge
