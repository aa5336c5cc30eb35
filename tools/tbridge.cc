#include <iostream>

#include "design/design.h"

int main(int argc, char** argv) {
  if (argc < 3) return 2;
  tbridge::Design d = tbridge::RunDesign(tbridge::LoadConfig(argv[2]));
  std::cout << d.mass.bars + d.mass.strings << " " << d.solver.status << " " << d.solver.iterations << "\n";
  for (auto& m : d.bars) std::cout << m.name << " r=" << m.radius * 1e3 << " m=" << m.mass << " " << m.governed_by << "\n";
  for (auto& m : d.strings) std::cout << m.name << " r=" << m.radius * 1e3 << " L0=" << m.rest_length << " k=" << m.stiffness << "\n";
  return 0;
}
