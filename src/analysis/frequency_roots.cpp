#include "frequency_roots.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace cosserat::detail {
namespace {

/// Singular values of B(ω), ascending.
Vec6 Sigma(const FrequencyShooting& fs, double omega) {
  const Eigen::JacobiSVD<Mat6> svd(fs.BoundaryMatrix(omega));
  return svd.singularValues().reverse();
}

/// A candidate root of det B(ω): exact when bisected from a sign change (a simple root, to
/// 1e-13 ω), else a refined minimum of σ_min (a root of even multiplicity, or a simple one
/// found twice: the minimum sits up to ~1e-7 ω off the root when another root is near).
struct Candidate {
  double omega;
  bool exact;
};

/// Candidates for the roots of det B(ω) in [lo, hi], sampled at 17 points: a sign change of det B
/// between neighbours (a simple root) is bisected to 1e-13 ω; a local minimum of σ_min(B) (also
/// a root of even multiplicity, which does not change the sign) is bracketed by its neighbours
/// and refined again, down to a bracket of 1e-10 ω. Roots closer than the sampling are
/// separated at a deeper level. A root may be reported more than once.
void RefineMinima(const FrequencyShooting& fs, double lo, double hi, int* budget,
                  std::vector<Candidate>* found) {
  constexpr int k = 16;
  double w[k + 1], s[k + 1];
  bool d[k + 1];
  for (int j = 0; j <= k; ++j) {
    w[j] = lo + (hi - lo) * j / k;
    const Mat6 B = fs.BoundaryMatrix(w[j]);
    s[j] = Eigen::JacobiSVD<Mat6>(B).singularValues()(5);
    d[j] = B.determinant() > 0;
  }
  *budget -= k + 1;
  for (int j = 0; j < k; ++j) {
    if (d[j] == d[j + 1]) continue;
    double a = w[j], b = w[j + 1];
    const bool da = d[j];
    while (b - a > 1e-13 * b && *budget > 0) {
      const double mid = 0.5 * (a + b);
      ((fs.BoundaryMatrix(mid).determinant() > 0) == da ? a : b) = mid;
      --*budget;
    }
    found->push_back({0.5 * (a + b), true});
  }
  for (int j = 1; j < k; ++j) {
    if (!(s[j] <= s[j - 1] && s[j] < s[j + 1])) continue;
    if (w[j + 1] - w[j - 1] < 1e-10 * w[j] || *budget <= 0)
      found->push_back({w[j], false});
    else
      RefineMinima(fs, w[j - 1], w[j + 1], budget, found);
  }
}


/// Another simple root of det B within 1e-3 ω of the roots `near` (all within 1e-5 ω of each
/// other), as the root of the deflated det B(ω) / Π (ω − near_i): bisected to 1e-13 ω from the
/// sign change between 32 samples nearest near[0]; NaN when there is none (the roots are then
/// of even multiplicity: the two bending planes of a rod symmetric about its axis).
double NeighbouringRoot(const FrequencyShooting& fs, const std::vector<double>& near,
                        int* budget) {
  constexpr int k = 32;
  const double wc = near.front();
  auto deflated = [&](double w) {
    double d = fs.BoundaryMatrix(w).determinant();
    for (double r : near) d /= (w - r);
    return d;
  };
  // Samples at wc (1 + 1e-3 ((2j + 1)/k − 1)), j = 0 … k − 1, nudged off the known roots.
  auto sample = [&](int j) {
    double w = wc * (1 + 1e-3 * ((2.0 * j + 1) / k - 1));
    for (double r : near)
      if (std::abs(w - r) < 1e-9 * wc) w += 1e-8 * wc;
    return w;
  };
  double best = NAN;
  double w_prev = sample(0), f_prev = deflated(w_prev);
  for (int j = 1; j < k && *budget > 0; ++j) {
    const double w = sample(j);
    const double f = deflated(w);
    --*budget;
    if ((f > 0) != (f_prev > 0)) {
      double a = w_prev, b = w;
      const bool fa = f_prev > 0;
      while (b - a > 1e-13 * b && *budget > 0) {
        const double mid = 0.5 * (a + b);
        (deflated(mid) > 0) == fa ? a = mid : b = mid;
        --*budget;
      }
      const double root = 0.5 * (a + b);
      // Within 1e-5 ω of a known root (a cluster's width): that root itself, which the
      // deflation leaves as sign changes where det B's sign flickers around it.
      bool apart = true;
      for (double r : near) apart = apart && std::abs(root - r) > 1e-5 * wc;
      if (apart && !(std::abs(root - wc) >= std::abs(best - wc))) best = root;
    }
    w_prev = w, f_prev = f;
  }
  return best;
}

/// The roots in [lo, hi] not yet in *roots, appended with their multiplicity. RefineMinima's
/// candidates are clustered within 1e-5 ω. A cluster with more small singular values than
/// roots is near another simple root (5e-5 ω apart: the two bending planes of a loaded rod),
/// found by deflation, or is a multiple root, whose further null vectors are then its modes.
void AddRoots(const FrequencyShooting& fs, double lo, double hi, int* budget,
              std::vector<Root>* roots, std::vector<double>* dips) {
  std::vector<Candidate> found;
  RefineMinima(fs, lo, hi, budget, &found);
  std::sort(found.begin(), found.end(),
            [](const Candidate& x, const Candidate& y) { return x.omega < y.omega; });
  for (size_t a = 0; a < found.size();) {
    size_t b = a + 1;
    while (b < found.size() && found[b].omega - found[a].omega < 1e-5 * found[a].omega) ++b;
    // The cluster's root: its first exact candidate, else its first minimum. The sign of det B
    // flickers near a root (round-off; over ~1e-7 ω at 500 Hz, ~7e-6 ω at 1 kHz on a 0.5 m
    // steel wire), so the cluster's sign changes are all this one root.
    std::vector<double> here;
    for (size_t q = a; q < b && here.empty(); ++q)
      if (found[q].exact) here.push_back(found[q].omega);
    const bool exact = !here.empty();
    if (!exact) here.push_back(found[a].omega);
    const double wc = here.front();
    a = b;
    bool known = false, beside_known = false;
    for (const Root& r : *roots) {
      known = known || std::abs(r.omega - wc) < 1e-5 * wc;
      beside_known = beside_known || std::abs(r.omega - wc) <= 5e-5 * wc;
    }
    if (known) continue;
    const Vec6 sc = Sigma(fs, wc), sm = Sigma(fs, wc * (1 - 1e-3)), sp = Sigma(fs, wc * (1 + 1e-3));
    // Small singular values: below 5 % of their value 1e-3 ω away may be a root nearby; below
    // 1e-4 of it only a root here (a double root's second is zero to round-off, ~1e-10).
    int small = 0, null = 0;
    for (int k = 0; k < 6; ++k) {
      small += sc(k) < 0.05 * std::max(sm(k), sp(k));
      null += sc(k) < 1e-4 * std::max(sm(k), sp(k));
    }
    // More small singular values than roots here: another simple root nearby (5e-5 ω apart,
    // the two bending planes of a loaded rod), else a multiple root.
    while (static_cast<int>(here.size()) < small) {
      const double neighbour = NeighbouringRoot(fs, here, budget);
      if (!std::isfinite(neighbour)) break;
      here.push_back(neighbour);
    }
    // A minimum of σ_min with no sign change of det B is a root only where B is singular: a
    // root of even multiplicity is zero there to round-off (~1e-7 of σ 1e-3 ω away, refined to
    // 1e-10 ω). A dip that stays above 1e-4 of its flanks is no root: past flutter under a
    // follower load, where a pair of roots has left the real axis, it marks their real part.
    if (!exact && null == 0) {
      if (dips && !beside_known) dips->push_back(wc);  // else the blur of that root's minimum
      continue;
    }
    // Still more small singular values than roots: those no other root (a candidate from a sign
    // change, or one known) within 5e-5 ω explains (a neighbour there also makes a singular
    // value small here; a mere minimum there may be this root's own, blurred by round-off) lie
    // within 1e-5 ω, closer than the neighbour search separates from sign flicker: a
    // cantilever's two bending planes under a 0.01 N lateral tip force, 1e-6 ω apart, lost one
    // of each pair and the list skipped to the next pair. They are listed at ω with the further
    // null vectors.
    auto near = [&](double w) {
      return std::abs(w - wc) > 1e-5 * wc && std::abs(w - wc) <= 5e-5 * wc;
    };
    const bool explained =
        std::any_of(found.begin(), found.end(),
                    [&](const Candidate& c) { return c.exact && near(c.omega); }) ||
        std::any_of(roots->begin(), roots->end(), [&](const Root& r) { return near(r.omega); });
    const int simple = static_cast<int>(here.size());
    const int mult = std::max({simple, null, explained ? 0 : small});
    for (int r = 0; r < mult; ++r) {
      const double w = r < simple ? here[r] : wc;
      const int vec = r < simple ? 0 : r - simple + 1;
      const Eigen::JacobiSVD<Mat6> svd(fs.BoundaryMatrix(w), Eigen::ComputeFullV);
      roots->push_back({w, svd.matrixV().col(5 - vec)});
    }
  }
}

}  // namespace

std::vector<Root> FindRoots(const FrequencyShooting& fs, double w_lo, double w_hi, double step,
                            int count, std::vector<double>* dips,
                            const std::function<void(double, double)>& progress) {
  std::vector<Root> roots;
  int budget = 200000;
  auto det_sign = [&](double w) { return fs.BoundaryMatrix(w).determinant() > 0; };
  double w0 = w_lo, w1 = w_lo * step;
  double s0 = Sigma(fs, w0)(0), s1 = Sigma(fs, w1)(0);
  bool d1 = det_sign(w1);
  while (static_cast<int>(roots.size()) < count && w1 < w_hi && budget > 0) {
    const double w2 = w1 * step, s2 = Sigma(fs, w2)(0);
    const bool d2 = det_sign(w2);
    budget -= 2;
    if (s1 <= s0 && s1 < s2) AddRoots(fs, w0, w2, &budget, &roots, dips);
    if (d1 != d2) AddRoots(fs, w0, w2 * step, &budget, &roots, dips);
    w0 = w1, s0 = s1, w1 = w2, s1 = s2, d1 = d2;
    if (progress) progress(static_cast<double>(roots.size()), count);
  }
  std::sort(roots.begin(), roots.end(),
            [](const Root& a, const Root& b) { return a.omega < b.omega; });
  return roots;
}

}  // namespace cosserat::detail
