// The minimum-mass sizing of a pin-jointed structure (truss/truss_model.h): one area per group,
// every member's stresses and buckling in every load case, the displacement limits and the
// lowest natural frequencies as rows of one nonlinear program, solved by the verified sizing's
// solvers (optim/solvers.h) and certified by the same KKT test (optim/kkt_certificate.h).
//
//   min  sum_g rho A_g L_g   over  min_area_g <= A_g <= max_area_g (and, where the prestress is
//        variable, the amplitudes of the self-stress states, free), subject to, in every case:
//     tension      1 - N / (sigma_t A) >= 0      strings and trusses
//     compression  1 + N / (sigma_c A) >= 0      bars and trusses
//     buckling     1 + N / (P_E / gamma) >= 0     P_E = pi E A^2 / (4 L^2), solid round section
//     taut         N / (sigma_t A) >= 0           strings: tension only
//     no tension   -N / (sigma_c A) >= 0          bars: compression only
//     displacement 1 -+ u / u_max >= 0            both signs
//   and once: frequency  omega_j^2 / (2 pi f_k)^2 - 1 >= 0 for j = k .. k + kTrussFollowingModes.
// Each row is a utilisation's complement (1 - utilisation), so every row reads the same way
// and the certificate's tolerance is one on utilisation.
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "optim/kkt_certificate.h"
#include "optim/nlp.h"
#include "truss/truss_analysis.h"
#include "truss/truss_model.h"

namespace tbridge {

enum class TrussRowKind {
  kTension,
  kCompression,
  kBuckling,
  kTaut,
  kNoTension,
  kDisplacement,
  kFrequency
};

// "tension", "compression", "buckling", "taut", "no_tension", "displacement", "frequency".
const char* TrussRowName(TrussRowKind kind);

// One row of the program: its kind, its case (-1 for a frequency), the member, the
// displacement limit or the frequency limit it is about, for a displacement its sign (+1 or -1)
// and for a frequency the mode it holds (0-based).
struct TrussRow {
  TrussRowKind kind = TrussRowKind::kTension;
  int load_case = -1;
  int index = 0;
  int sign = 1;
  int mode = 0;
};

// The modes each frequency limit holds beyond its own: the k-th lowest eigenvalue is the least
// of the branches that cross there, not smooth where two meet (the 10-bar problem's optimum has
// f3 = f4 = 20 Hz), while each branch is; with the next modes held to the same limit (redundant
// for the sorted values) both branches of a pair that meets are rows, and the optimum there is
// a KKT point.
inline constexpr int kTrussFollowingModes = 2;

// The rows a structure's model poses, in a fixed order.
std::vector<TrussRow> TrussRows(const TrussModel& model);

// Each row's value (1 - its utilisation) at the sizing's `variables` (TrussModel::num_variables:
// the group areas, then the self-stress amplitudes), and, with `jacobian` non-null, its
// derivatives in them (rows x variables). One analysis of every case and, where limits ask for
// them, of the modes.
Eigen::VectorXd TrussRowValues(const TrussModel& model, const std::vector<TrussRow>& rows,
                               const Eigen::VectorXd& variables, Eigen::MatrixXd* jacobian);

// What the members' mass pays for, by the sizing's Lagrange multipliers at its point (as the
// bridge's mass_attribution: sizing/sizing_attribution.h). The mass is linear in the areas,
// zero at zero and free of the prestress, so mass = grad(mass) . v = sum_r lambda_r grad g_r . v
// + mu . v: each active row's term (its kind's share) and each bound's, adding up to the mass
// up to the stationarity residual. Kinds: "strength" (tension, compression), "buckling",
// "taut_strings", "bars_in_compression", "displacement", "frequency", "minimum_sizes",
// "maximum_sizes" (signed: a largest area that binds holds mass elsewhere).
struct TrussMassAttribution {
  std::vector<std::pair<std::string, double>> by_constraint_kg;
  double structure_kg = 0;
  double stationarity_residual = 0;  // of the multipliers' equation, relative
  int active_rows = 0;
};

struct TrussSizing {
  Eigen::VectorXd group_areas;  // [m^2]
  Eigen::VectorXd prestress;    // per member [N]: a self-stress; zero without prestress
  SolverOutcome outcome;        // of the solve kept
  KktCertificate kkt;
  std::string start;               // which start the kept solve came from
  std::vector<std::string> tries;  // every solve: start, solver, status, mass, proved or not
  TrussMassAttribution attribution;
};

// The sizing of `model` with design.solver (`solver`: kAuto takes the SQP, then Ipopt where the
// SQP's point is not proved optimal), `tolerance` and `max_iterations`. Displacement and
// frequency limits make the program non-convex: it is then solved from several starts, by both
// solvers under kAuto, and of the feasible points the lightest proved one is kept (the
// lightest where none is proved). Where no start gives a feasible point, the least infeasible
// is kept: its check fails and names the row. Throws ModelError where the structure is a
// mechanism.
TrussSizing SizeTruss(const TrussModel& model, SolverKind solver, double tolerance,
                      int max_iterations);

}  // namespace tbridge
