// Non-negative least squares, min |A z - b| subject to z >= 0, by Lawson and Hanson's active
// set method (Solving Least Squares Problems, 1974, ch. 23), the QR factors of the passive
// columns updated as columns join and leave. Eigen has no such solver, and the sizing's
// multipliers need dense problems of up to a few hundred unknowns (one per active-set round and
// per design), so a transcription of the method serves better than a general NLP. A column
// dependent on the passive ones (a wide A) stays out.
#pragma once

#include <Eigen/Core>

namespace tbridge {

// The solution z (size A.cols()); `residual` (optional) gets |A z - b|. At most 3 A.cols()
// outer steps.
Eigen::VectorXd NonNegativeLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                        double* residual = nullptr);

}  // namespace tbridge
