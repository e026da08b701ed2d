#pragma once
// The natural frequencies of a rod by frequency shooting: the roots of det B(ω), the boundary
// matrix of FrequencyShooting, found by a geometric scan and refined; each with its null vector.
// Internal to src/analysis.

#include <functional>
#include <vector>

#include "cosserat/analysis/frequency_shooting.hpp"
#include "cosserat/lie/types.hpp"

namespace cosserat::detail {

/// A root of det B(ω) (rad/s) and its null vector (dimensionless).
struct Root {
  double omega;
  Vec6 x;
};

/// The first `count` roots of det B(ω) above w_lo (rad/s), ascending: a coarse geometric scan
/// (ratio `step`) of σ_min(B) and of the sign of det B up to w_hi. A sampled local minimum of
/// σ_min, or a sign change of det B (a simple root hidden in the flank of a neighbour's dip),
/// brackets candidates; they are refined, clustered and tested. A root of multiplicity m is
/// listed m times, with independent null vectors. Fewer than `count` when the scan reaches w_hi
/// or its budget of 200 000 boundary matrices. `dips`, when given, receives the minima of σ_min
/// where B is not singular: no root, but the real part of a pair of roots off the real axis,
/// as past flutter under a follower load. `progress`, when set, is called at each scan step with
/// the roots found and `count` (it may throw to stop the scan).
std::vector<Root> FindRoots(const FrequencyShooting& fs, double w_lo, double w_hi, double step,
                            int count, std::vector<double>* dips = nullptr,
                            const std::function<void(double, double)>& progress = nullptr);

}  // namespace cosserat::detail
