#pragma once
// The damped modes of a quaternion-FD linearisation. Internal to src/analysis.

#include <Eigen/Core>
#include <vector>

#include "cosserat/analysis/modes.hpp"

namespace cosserat::detail {

/// The damped pair of each of `modes` (ω, ascending) of λ² M + λ C + K = 0, in their order: the
/// frequency and ratio NaN for a mode without one (overdamped, divergent, or no pair holds more
/// than half its energy in the mode's cluster). `symmetric`: *companion already holds the modal
/// first-order form [[0, Ω], [−Ω, −D]] SymmetricSpectrum built, whose pairs are matched by
/// shape; else the plain companion matrix [[0, I], [Ar, Br]] of the reduced Jacobians is built
/// there, and pairs are matched by |λ|. True when one of the 2n + 6 lowest pairs grows
/// (Re λ > 0), of those with |λ| above `judged_above` (rad/s; the neutral modes' round-off below).
bool DampedOfModes(bool symmetric, const Eigen::MatrixXd& Ar, const Eigen::MatrixXd& Br,
                   const std::vector<Mode>& modes, double judged_above, Eigen::MatrixXd* companion,
                   std::vector<DampedMode>* out);

}  // namespace cosserat::detail
