// Why the banded Rosenbrock integrator of the quaternion-FD rod needs thousands of steps for
// the two benchmark rods of bench_quatfd.cpp (docs/performance.md, "What limits the Rosenbrock
// step"): a stability limit of the linearly implicit method, not of the ODE and not of the
// tolerance.
//
//   build/bench/diagnostics/quatfd_stability
//
// For each benchmark rod, after an adaptive run to t0 (rel_tol 1e-6) it prints
//  1. the spectrum of the frozen Jacobian [[0, I], [∂f/∂q, ∂f/∂v]] of the first-order system
//     (prescribed unknowns removed): its largest real part against max_ν |ṗ_ν| (the ±|ṗ| pairs
//     of the |p| gauge, an artefact of freezing a quadratic invariant), and the stiffest
//     eigenvalue; (the undamped steel string also has weakly growing fast rotary pairs, Re λ ≲ 0.2
//     Im λ);
//  2. the spectral radius ρ of the Jacobian of one Rosenbrock step map y ↦ Project(Step(y, h))
//     (central differences) for a range of fixed h, without and with Baumgarte stabilisation, and
//     where the dominant eigenvector lives. ρ > 1 means a perturbation grows by ρ per step,
//     whatever the tolerance: the controller must keep h below the onset;
//  3. for the rubber rod, the same for one step of the implicit SdirkIntegrator (Newton
//     iterations with the co-rotated iteration matrix, converged to 1e-10 · scale): ρ ≤ 1.

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/rosenbrock.hpp"
#include "cosserat/quatfd/sdirk.hpp"
#include "../quatfd_rods.hpp"

namespace {

using namespace cosserat;
using namespace cosserat::quatfd;
using L = QuatFdLayout;

using bench::Horizontal;  // the two rods of bench_quatfd.cpp: ../quatfd_rods.hpp
using bench::RubberRod;
using bench::SteelString;

std::vector<int> FreeUnknowns(const QuatFdModel& model) {
  std::vector<int> keep;
  const int n = model.size();
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < n; ++i)
      if (!model.IsFixed(i)) keep.push_back(k * n + i);
  return keep;
}

void FrozenSpectrum(const QuatFdModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
  const int n = model.size(), N = model.layout().segments;
  BandedMatrix A, B;
  model.Jacobian(q, v, &A, &B);
  const std::vector<int> keep = FreeUnknowns(model);
  const int m = static_cast<int>(keep.size());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(m, m);
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) {
      const int i = keep[a], j = keep[b];
      if (i < n) {
        J(a, b) = j == i + n ? 1.0 : 0.0;
      } else {
        const int r = i - n, c = j < n ? j : j - n;
        if (std::abs(r - c) <= L::kBandwidth) J(a, b) = j < n ? A(r, c) : B(r, c);
      }
    }
  const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(J, false).eigenvalues();
  double max_re = -1e300, min_re = 1e300, max_pd = 0;
  for (int k = 0; k < m; ++k) {
    max_re = std::max(max_re, ev[k].real());
    min_re = std::min(min_re, ev[k].real());
  }
  for (int nu = 0; nu < N; ++nu) max_pd = std::max(max_pd, v.segment<4>(L::P(nu)).norm());
  std::printf(
      "  frozen Jacobian: max Re(lambda) = %.4g 1/s (the |p| gauge pairs reach max |pdot| = "
      "%.4g), stiffest Re(lambda) = %.4g 1/s\n",
      max_re, max_pd, min_re);
}

template <typename Integrator>
void StepMap(const QuatFdModel& model, const Eigen::VectorXd& q, const Eigen::VectorXd& v, double h,
             bool project, double newton_tol = 1e-10) {
  const int n = model.size(), N = model.layout().segments;
  // SDIRK: Newton converged to newton_tol · scale, below the ε = 1e-7 differences.
  IntegratorOptions io;
  io.rel_tol = io.abs_tol = io.velocity_abs_tol = newton_tol;
  Integrator integ(model, io);
  Eigen::VectorXd y(2 * n), out(2 * n), err(2 * n);
  y << q, v;
  bool all_ok = true;
  const auto phi = [&](const Eigen::VectorXd& y0) {
    all_ok = integ.Step(y0, h, out, err) && all_ok;
    if (project) model.Project(out.head(n), out.tail(n));
    return out;
  };
  const std::vector<int> keep = FreeUnknowns(model);
  const int m = static_cast<int>(keep.size());
  Eigen::MatrixXd D(m, m);
  for (int b = 0; b < m; ++b) {
    const double eps = 1e-7;
    Eigen::VectorXd yp = y, ym = y;
    yp[keep[b]] += eps;
    ym[keep[b]] -= eps;
    const Eigen::VectorXd d = (phi(yp) - phi(ym)) / (2 * eps);
    for (int a = 0; a < m; ++a) D(a, b) = d[keep[a]];
  }
  Eigen::EigenSolver<Eigen::MatrixXd> es(D);
  int k = 0;
  for (int i = 1; i < m; ++i)
    if (std::abs(es.eigenvalues()[i]) > std::abs(es.eigenvalues()[k])) k = i;
  const Eigen::VectorXcd vec = es.eigenvectors().col(k);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(2 * n);
  for (int a = 0; a < m; ++a) e[keep[a]] = std::abs(vec[a]);
  // Share of the eigenvector in the quaternion velocities, and the segment that carries most.
  double quat_rate = 0;
  int seg = 0;
  for (int nu = 0; nu < N; ++nu) {
    const double s = e.segment<4>(n + L::P(nu)).squaredNorm();
    quat_rate += s;
    if (s > e.segment<4>(n + L::P(seg)).squaredNorm()) seg = nu;
  }
  const Eigen::Vector4d p = q.segment<4>(L::P(seg));
  const Eigen::Vector3d w =
      kernels::AngularVelocity<double>(p, Eigen::Vector4d(v.segment<4>(L::P(seg))));
  std::printf(
      "    h = %7.3g ms: rho = %9.4g  (quaternion-rate share %.2f, largest on segment %d, "
      "|omega| there %.3g rad/s)%s\n",
      h * 1e3, std::abs(es.eigenvalues()[k]), quat_rate / e.squaredNorm(), seg, w.norm(),
      all_ok ? "" : "  [a step failed]");
}

void Report(const char* name, const RodModel& rod, EndCondition end, int segments, double t0,
            const std::vector<double>& steps, double baumgarte, double newton_tol) {
  for (int variant = 0; variant < 2; ++variant) {
    QuatFdOptions opt;
    opt.segments = segments;
    opt.base_end = end;
    if (variant == 1) opt.baumgarte_alpha = opt.baumgarte_beta = baumgarte;
    QuatFdModel model(rod, Horizontal(), opt);
    StaticLoads loads;
    loads.gravity_W = Vec3(0, 0, -9.81);
    model.set_loads(loads);
    Eigen::VectorXd q(model.size()), v(model.size());
    model.RestState(q, v);
    IntegratorOptions io;
    io.project = variant == 0;
    RosenbrockIntegrator integ(model, io);
    double t = 0;
    integ.Advance(t0, &t, q, v);
    std::printf(
        "%s, N = %d, t = %g s, %s:\n", name, segments, t0,
        variant == 0 ? "projection after each step" : "Baumgarte alpha = beta (no projection)");
    if (variant == 1) std::printf("  alpha = beta = %g 1/s\n", baumgarte);
    if (variant == 0) FrozenSpectrum(model, q, v);
    std::printf("  Jacobian of one Rosenbrock step map:\n");
    for (double h : steps) StepMap<RosenbrockIntegrator>(model, q, v, h, variant == 0);
    // Not for the steel string: from perturbed states its Newton iteration does not reach the
    // 1e-10 · scale the differences need (stiffness 1.6e9 1/s; round-off floor), at h ≥ 0.2 ms.
    if (variant == 0 && newton_tol > 0) {
      std::printf("  Jacobian of one SDIRK step map (Newton, co-rotated iteration matrix):\n");
      for (double h : steps) StepMap<SdirkIntegrator>(model, q, v, h, true, newton_tol);
    }
  }
}

}  // namespace

int main() {
  Report("(a) rubber rod", RubberRod(), EndCondition::kClamped, 10, 1.0,
         {1e-3, 2e-3, 5e-3, 1e-2, 2e-2}, 1e3, 1e-10);
  Report("(a) rubber rod", RubberRod(), EndCondition::kClamped, 10, 0.2, {2e-3, 5e-3, 1e-2}, 1e3, 1e-10);
  Report("(b) steel string", SteelString(), EndCondition::kPinned, 20, 1.0,
         {1e-4, 2e-4, 5e-4, 1e-3}, 1e4, 0.0);
  return 0;
}
