// The post-buckled branch of a found critical point (BucklingAnalysis::SolvePostBuckled): branch
// switching along the buckling mode and continuation in the mode amplitude, λ free
// (docs/buckling.md, step 5).
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <vector>

#include "cosserat/analysis/buckling.hpp"

namespace cosserat {

bool BucklingAnalysis::BorderedNewton(double eta, Vec6* u, double* lambda) {
  // Newton on z = (u, λ/λ_cr): r(u, λ) = 0, v · (u − u_cr) = η. Minimum-norm steps.
  const double lc = lambda_cr_;
  const double tol = options_.solver.tolerance;
  const Vec6& v = v_cr_;
  for (int it = 0; it <= options_.solver.max_iterations; ++it) {
    Mat6 J;
    const Vec6 r = ResidualAt(*lambda, *u, &J);
    Eigen::Matrix<double, 7, 1> F;
    F << r, v.dot(*u - u_cr_) - eta;
    if (!F.allFinite()) return false;
    if (F.norm() < tol) return true;
    if (it == options_.solver.max_iterations) return false;
    const double h = 1e-6 * lc;
    const Vec6 r_lambda =
        (ResidualAt(*lambda + h, *u, nullptr) - ResidualAt(*lambda - h, *u, nullptr)) / (2 * h) *
        lc;
    Eigen::Matrix<double, 7, 7> A = Eigen::Matrix<double, 7, 7>::Zero();
    A.topLeftCorner<6, 6>() = J;
    A.topRightCorner<6, 1>() = r_lambda;
    A.bottomLeftCorner<1, 6>() = v.transpose();
    Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, 7, 7>> cod;
    cod.setThreshold(1e-10);
    cod.compute(A);
    const Eigen::Matrix<double, 7, 1> dz = -cod.solve(F);
    double t = 1.0;
    bool accepted = false;
    for (int k = 0; k < 12 && !accepted; ++k, t *= 0.5) {
      const Vec6 u_try = *u + t * dz.head<6>();
      const double l_try = *lambda + t * dz(6) * lc;
      Eigen::Matrix<double, 7, 1> F_try;
      F_try << ResidualAt(l_try, u_try, nullptr), v.dot(u_try - u_cr_) - eta;
      if (F_try.allFinite() && F_try.norm() < (1 - 1e-4 * t) * F.norm()) {
        *u = u_try;
        *lambda = l_try;
        accepted = true;
      }
    }
    if (!accepted) return false;
  }
  return false;
}

ColumnSummary BucklingAnalysis::SolvePostBuckled(double lambda_target) {
  ColumnSummary fail;
  fail.status = SolveStatus::kMaxIterations;
  if (!found_ || !(lambda_target > lambda_cr_)) return fail;
  const double lc = lambda_cr_;
  const Vec6& v = v_cr_;

  struct BranchPoint {
    double eta, lambda;
    Vec6 u;
  };
  std::vector<BranchPoint> branch{{0.0, lc, u_cr_}};
  double d_eta = 0.02;
  while (branch.back().lambda < lambda_target) {
    if (branch.size() > 2000 || d_eta < 1e-6) return fail;
    const BranchPoint& b = branch.back();
    const double eta = b.eta + d_eta;
    Vec6 u;
    double lambda;
    if (branch.size() >= 2) {  // secant predictor in η
      const BranchPoint& a = branch[branch.size() - 2];
      const double w = (eta - b.eta) / (b.eta - a.eta);
      u = b.u + w * (b.u - a.u);
      lambda = b.lambda + w * (b.lambda - a.lambda);
    } else {
      u = b.u + d_eta * v;
      lambda = b.lambda;
    }
    if (!BorderedNewton(eta, &u, &lambda)) {
      d_eta *= 0.5;
      continue;
    }
    // Next step: about a quarter of the remaining way in λ, within [d_eta / 2, 2 d_eta] ∩ (0, 0.1].
    const double slope = std::abs(lambda - b.lambda) / d_eta;
    const double want = slope > 0 ? 0.25 * (lambda_target - lc) / slope : 2 * d_eta;
    branch.push_back({eta, lambda, u});
    d_eta = std::clamp(want, 0.5 * d_eta, std::min(2 * d_eta, 0.1));
  }
  // Regula falsi (Illinois) on η for λ(η) = λ_target between the last two branch points.
  BranchPoint a = branch[branch.size() - 2], b = branch.back();
  double fa = a.lambda - lambda_target, fb = b.lambda - lambda_target;
  BranchPoint c = b;
  for (int it = 0; it < 60 && std::abs(c.lambda - lambda_target) > 1e-13 * lc; ++it) {
    const double eta = b.eta - fb * (b.eta - a.eta) / (fb - fa);
    const double w = (eta - a.eta) / (b.eta - a.eta);
    Vec6 u = a.u + w * (b.u - a.u);
    double lambda = a.lambda + w * (b.lambda - a.lambda);
    if (!BorderedNewton(eta, &u, &lambda)) return fail;
    c = {eta, lambda, u};
    const double fc = lambda - lambda_target;
    if (fc * fb < 0) {
      a = b;
      fa = fb;
    } else {
      fa *= 0.5;
    }
    b = c;
    fb = fc;
  }
  column_.set_unknowns(c.u);
  return SolveAt(lambda_target);
}

}  // namespace cosserat
