// Material constants (SI). One material serves bars, strings and deck beams, as in the paper.
#pragma once

namespace tbridge {

struct Material {
  double density = 7862.0;          // rho [kg/m^3]
  double yield_stress = 6.9e8;      // sigma_yield [Pa]
  double youngs_modulus = 2.06e11;  // E [Pa]
};

}  // namespace tbridge
