#pragma once
/// \file
/// How near a tendon robot's tensions are to the limit of the tendon strain law: a straight
/// tendon at offset d bends the rod to κ = τ d/EI, and at τ d²/EI = 1 the inside of the bend,
/// where it runs, shrinks to zero length (a helical one on the three-tendon robot fails between
/// 0.76 and 0.91). Past it the law has no solution along the rod.

#include <string>

#include "cosserat/io/problem.hpp"

namespace cosserat::run::detail {

struct TendonLawLoad {
  double ratio = 0.0;  ///< the largest tension × offset² / EI over the tendons
  std::string name;    ///< the tendon's that reaches it
};

/// The tendon of `problem`'s rod nearest the law's limit under `actuation`'s tensions (offsets:
/// each route's largest; EI at s = 0, its smaller principal value); ratio 0 with no tendons.
TendonLawLoad LargestTendonLawLoad(const io::Problem& problem, const Actuation& actuation);

}  // namespace cosserat::run::detail
