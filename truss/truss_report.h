// The design file and the terminal summary of a designed structure (truss/truss_design.h). The
// file's fields are listed in README.md, "A structure's design file".
#pragma once

#include <ostream>
#include <string>

#include "truss/truss_design.h"

namespace tbridge {

void WriteTrussDesignJson(const TrussDesign& design, std::ostream& os);
std::string TrussDesignSummary(const TrussDesign& design);

}  // namespace tbridge
