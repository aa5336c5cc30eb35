#include "dynamics/modal_sensitivity.h"

namespace tbridge {

ModeEnergies ModeEnergiesOf(const DynamicModel& model, const Mode& mode,
                            StringMassMode string_mass) {
  const int nb = static_cast<int>(model.bars.size()), ns = static_cast<int>(model.strings.size());
  ModeEnergies out;
  out.omega_squared = mode.omega_squared;
  out.by_stiffness.assign(static_cast<size_t>(nb + ns), 0.0);
  out.by_force.assign(static_cast<size_t>(nb + ns), 0.0);
  out.mass_energy.assign(static_cast<size_t>(nb + ns), 0.0);
  const Eigen::Matrix3Xd& phi = mode.shape;  // zero at pinned nodes
  // phi^T M_b phi of a bar of unit mass (eq. 21), which also weighs the string mass it carries.
  std::vector<double> bar_energy(static_cast<size_t>(nb));
  for (int k = 0; k < nb; ++k) {
    const DynamicBar b = model.bars[static_cast<size_t>(k)];
    const Eigen::Vector3d pi = phi.col(b.i), pj = phi.col(b.j);
    bar_energy[static_cast<size_t>(k)] = (pi.squaredNorm() + pi.dot(pj) + pj.squaredNorm()) / 3.0;
    out.by_force[static_cast<size_t>(k)] = -(pj - pi).squaredNorm() / b.length;
    out.mass_energy[static_cast<size_t>(k)] = bar_energy[static_cast<size_t>(k)];
  }
  for (int k = 0; k < ns; ++k) {
    const DynamicString st = model.strings[static_cast<size_t>(k)];
    const Eigen::Vector3d s = model.positions.col(st.j) - model.positions.col(st.i);
    const double length = s.norm();
    if (length < st.rest_length) continue;  // slack: no stiffness, as modal.h assembles it
    const Eigen::Vector3d dphi = phi.col(st.j) - phi.col(st.i);
    const double axial = s.dot(dphi) / length;
    out.by_stiffness[static_cast<size_t>(nb + k)] = axial * axial;
    out.by_force[static_cast<size_t>(nb + k)] = (dphi.squaredNorm() - axial * axial) / length;
  }
  ForEachStringMassShare(model, string_mass, [&](int k, int node, int bar, int count) {
    const double energy =
        bar < 0 ? phi.col(node).squaredNorm() : bar_energy[static_cast<size_t>(bar)];
    out.mass_energy[static_cast<size_t>(nb + k)] += 0.5 * energy / count;
  });
  return out;
}

}  // namespace tbridge
