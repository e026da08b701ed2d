// Diagnostic for issue 4 (BENCHMARKS.md, "What limits the Radau step: Newton"): why does the
// Radau IIA Newton iteration stop converging at h ≈ 8 ms on the rubber rod (a) and ≈ 1.7 ms on
// the steel string (b)? Fixed-size Radau IIA steps from states of the benchmark runs (the
// integrator's own run, rel_tol 1e-6, stopped at t = 0.5, 2, 5 s), h = 0.5 … 32 ms, the
// collocation system (velocity half; Z_q = h A (v_n + Z_v) exact, as in radau.cpp) solved by:
//   simp-corot   J(y_n) frozen, co-rotated per stage and iteration: the integrator's matrix
//   simp-plain   J(y_n) frozen, not co-rotated
//   full         full Newton: the exact Jacobian of the 3-stage system at the current iterates,
//                every iteration
//   full-tan     full, with the quaternion-rate unknowns restricted to the tangent of S³ at p_n
//                (the radial/gauge direction of ṗ kept at its starting value, its equations dropped)
//   simp-oracle  frozen per-stage exact Jacobians at the converged stages (only with full)
//   simp-start   frozen per-stage exact Jacobians at the starting iterates
//   simp-endrot  one J at the predicted end point y_n + Z_3⁰, co-rotated per stage
//   simp-rot-tan simp-corot restricted to the tangent directions like full-tan
//   simp-st-tan  simp-start restricted to the tangent directions like full-tan
// Dense LU of the 3n × 3n velocity system (slow; a diagnostic). Norm, κ = 0.05, the 7-iteration
// limit and the "slow"/"diverged" rules as in radau.cpp; each line gives that verdict and its
// iteration, the iterations to ‖ΔZ‖ < 1e-5 (in tolerance units; up to 40, -1: not reached), the
// increments ‖ΔZ‖, their ratios θ, and the component class carrying the increment at the verdict
// (xq/xv vertex positions/velocities, pq/pv quaternions/rates, _rad along p, _tan tangent to S³,
// @ the vertex or segment). Also printed per state: max |ω| and the eigenvalues of J(y_n) with
// Re > 1 1/s.
//
//   build/bench/quatfd_newton_diag a|b [variant mask, default 511] [start: 1 extrapolated, 0 zero]
//
// Starting values "extrapolated": the step before, of the same h, solved tightly (full Newton, or
// full-tan then full from it), its collocation polynomial extrapolated as in radau.cpp; "zero":
// Z = 0 (RadauIntegrator::Step after ForgetHistory; with this start the integrator's own Step is
// also run, as a check of the simp-corot emulation). Mask bits in the order listed above.

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <complex>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "quatfd_rods.hpp"
#include "cosserat/quatfd/corotation.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/radau.hpp"
#include "cosserat/quatfd/radau_tableau.hpp"

using namespace cosserat;
using namespace cosserat::quatfd;
using L = QuatFdLayout;

// The Radau IIA tableau of the integrator (radau_tableau.hpp).
static const RadauIIA3Tableau& K = RadauIIA3();
// COND=1 in the environment: the condition of the exact iteration matrix at the starting iterates
// of the test steps (full, full-tan; not of the preparatory steps before them).
static bool g_print_condition = false;

enum Variant { kSimpCorot, kSimpPlain, kFull, kFullTan, kSimpOracle, kSimpStart, kSimpEndCorot, kSimpCorotTan, kSimpStartTan };
static const char* kName[] = {"simp-corot", "simp-plain", "full", "full-tan", "simp-oracle", "simp-start", "simp-endrot", "simp-rot-tan", "simp-st-tan"};

struct Problem {
  const QuatFdModel& m;
  int n, N;
  double rel = 1e-6, atol = 1e-6, vatol = 1e-6;  // Newton norm: min(abs_tol, velocity_abs_tol)
};

static Eigen::MatrixXd Dense(const BandedMatrix& b) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(b.rows(), b.rows());
  for (int j = 0; j < b.rows(); ++j)
    for (int i = 0; i < b.rows(); ++i)
      if (b.InBand(i, j)) d(i, j) = b(i, j);
  return d;
}

// Stage states Y_i = y + Z_i with Z_q = h A (v_n + Z_v).
static void Stages(const Problem& P, const Eigen::VectorXd& y, double h, const Eigen::VectorXd& Zv,
                   std::vector<Eigen::VectorXd>& Y) {
  const int n = P.n;
  Y.assign(3, Eigen::VectorXd(2 * n));
  for (int i = 0; i < 3; ++i) {
    Eigen::VectorXd zq = (h * (K.A[i][0] + K.A[i][1] + K.A[i][2])) * y.tail(n);
    for (int j = 0; j < 3; ++j) zq += (h * K.A[i][j]) * Zv.segment(j * n, n);
    Y[i].head(n) = y.head(n) + zq;
    Y[i].tail(n) = y.tail(n) + Zv.segment(i * n, n);
  }
}

// -dG/dZ_v with per-stage (dfdq, dfdv): Ainv/h ⊗ I − h A_ij Aq_i − δ_ij B_i.
static Eigen::MatrixXd SystemMatrix(const Problem& P, double h, const Eigen::MatrixXd* Aq,
                                    const Eigen::MatrixXd* B) {
  const int n = P.n;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      auto blk = M.block(i * n, j * n, n, n);
      blk = -(h * K.A[i][j]) * Aq[i];
      if (i == j) blk -= B[i];
      blk.diagonal().array() += K.Ainv[i][j] / h;
    }
  return M;
}

struct Result {
  int verdict_it = -1;  // production verdict iteration
  std::string verdict;  // conv / slow / div
  std::vector<double> d;
  bool converged_eventually = false;
  int its_to_1e8 = -1;
  std::string dominant;  // of the increment at the verdict (or last) iteration
  Eigen::VectorXd Zv;
};

// Component classes of a velocity increment (scaled like the Newton norm), per stage.
static std::string Dominant(const Problem& P, const Eigen::VectorXd& y, double h,
                            const Eigen::VectorXd& dZv, const std::vector<Eigen::VectorXd>& Y) {
  const int n = P.n, N = P.N;
  // classes: 0 x_q, 1 x_v, 2 p_q radial, 3 p_q tangent, 4 p_v radial, 5 p_v tangent
  double cls[6] = {0, 0, 0, 0, 0, 0};
  int where[6] = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    Eigen::VectorXd dq = Eigen::VectorXd::Zero(n);
    for (int j = 0; j < 3; ++j) dq += (h * K.A[i][j]) * dZv.segment(j * n, n);
    const auto dv = dZv.segment(i * n, n);
    for (int k = 0; k <= N; ++k)
      for (int c = 0; c < 3; ++c) {
        const int e = L::X(k) + c;
        const double sq = P.atol + P.rel * std::abs(y[e]), sv = P.vatol + P.rel * std::abs(y[n + e]);
        if (std::abs(dq[e]) / sq > cls[0]) cls[0] = std::abs(dq[e]) / sq, where[0] = k;
        if (std::abs(dv[e]) / sv > cls[1]) cls[1] = std::abs(dv[e]) / sv, where[1] = k;
      }
    for (int s = 0; s < N; ++s) {
      const int e = L::P(s);
      const Eigen::Vector4d p = Y[i].segment<4>(e).normalized();
      double sq = 0, sv = 0;
      for (int c = 0; c < 4; ++c) {
        sq = std::max(sq, P.atol + P.rel * std::abs(y[e + c]));
        sv = std::max(sv, P.vatol + P.rel * std::abs(y[n + e + c]));
      }
      const Eigen::Vector4d a = dq.segment<4>(e), b = dv.segment<4>(e);
      const double ar = std::abs(p.dot(a)) / sq, at = (a - p.dot(a) * p).norm() / sq;
      const double br = std::abs(p.dot(b)) / sv, bt = (b - p.dot(b) * p).norm() / sv;
      const double v4[4] = {ar, at, br, bt};
      for (int c = 0; c < 4; ++c)
        if (v4[c] > cls[2 + c]) cls[2 + c] = v4[c], where[2 + c] = s;
    }
  }
  static const char* nm[6] = {"xq", "xv", "pq_rad", "pq_tan", "pv_rad", "pv_tan"};
  char buf[256];
  int best = 0;
  for (int c = 1; c < 6; ++c)
    if (cls[c] > cls[best]) best = c;
  std::snprintf(buf, sizeof buf, "%s@%d [xq %.1e xv %.1e pqr %.1e pqt %.1e pvr %.1e pvt %.1e]",
                nm[best], where[best], cls[0], cls[1], cls[2], cls[3], cls[4], cls[5]);
  return buf;
}

static double Norm(const Problem& P, const Eigen::VectorXd& y, double h, const Eigen::VectorXd& dZv) {
  const int n = P.n;
  double d = 0;
  for (int e = 0; e < n; ++e) {
    const double sv = P.vatol + P.rel * std::abs(y[n + e]);
    const double sq = P.atol + P.rel * std::abs(y[e]);
    for (int r = 0; r < 3; ++r) {
      const double dq = h * (K.A[r][0] * dZv[e] + K.A[r][1] * dZv[n + e] + K.A[r][2] * dZv[2 * n + e]);
      d = std::max(d, std::max(std::abs(dZv[r * n + e]) / sv, std::abs(dq) / sq));
    }
  }
  return d;
}

static Result Solve(const Problem& P, const Eigen::VectorXd& y, double h, Variant var,
                    const Eigen::VectorXd* oracle_Zv, const Eigen::VectorXd& Z0v, int max_it = 40) {
  const int n = P.n, N = P.N;
  Result res;
  Eigen::VectorXd Zv = Z0v;
  std::vector<Eigen::VectorXd> Y;
  BandedMatrix Ab, Bb;
  Eigen::MatrixXd Aq[3], B[3];
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  Eigen::VectorXd qref = y.head(n);
  if (var == kSimpCorot || var == kSimpCorotTan || var == kSimpPlain || var == kSimpOracle || var == kSimpStart || var == kSimpStartTan ||
      var == kSimpEndCorot) {
    if (var == kSimpEndCorot) {
      Stages(P, y, h, Z0v, Y);
      P.m.Jacobian(Y[2].head(n), Y[2].tail(n), &Ab, &Bb);
      qref = Y[2].head(n);
      for (int i = 0; i < 3; ++i) Aq[i] = Dense(Ab), B[i] = Dense(Bb);
    } else if (var == kSimpOracle || var == kSimpStart || var == kSimpStartTan) {
      Stages(P, y, h, var == kSimpOracle ? *oracle_Zv : Z0v, Y);
      for (int i = 0; i < 3; ++i) {
        P.m.Jacobian(Y[i].head(n), Y[i].tail(n), &Ab, &Bb);
        Aq[i] = Dense(Ab), B[i] = Dense(Bb);
      }
    } else {
      P.m.Jacobian(y.head(n), y.tail(n), &Ab, &Bb);
      for (int i = 0; i < 3; ++i) Aq[i] = Dense(Ab), B[i] = Dense(Bb);
    }
  }
  CoRotation rot[3] = {CoRotation(N), CoRotation(N), CoRotation(N)};
  // Tangent basis for full-tan: per segment, the 3 directions ⊥ p_n (velocity half only).
  Eigen::MatrixXd U;
  if (var == kFullTan || var == kSimpCorotTan || var == kSimpStartTan) {
    std::vector<int> keep;
    Eigen::MatrixXd Ub = Eigen::MatrixXd::Identity(n, n);
    for (int s = 0; s < N; ++s) {
      const Eigen::Vector4d p = y.segment<4>(L::P(s)).normalized();
      Eigen::Matrix4d proj = Eigen::Matrix4d::Identity() - p * p.transpose();
      Eigen::JacobiSVD<Eigen::Matrix4d> svd(proj, Eigen::ComputeFullU);
      Ub.block<4, 4>(L::P(s), L::P(s)) = svd.matrixU();  // first 3 columns span the tangent
    }
    for (int e = 0; e < n; ++e) {
      bool radial = false;
      for (int s = 0; s < N; ++s)
        if (e == L::P(s) + 3) radial = true;
      if (!radial) keep.push_back(e);
    }
    Eigen::MatrixXd U1(n, keep.size());
    for (size_t c = 0; c < keep.size(); ++c) U1.col(c) = Ub.col(keep[c]);
    U = Eigen::MatrixXd::Zero(3 * n, 3 * keep.size());
    for (int i = 0; i < 3; ++i) U.block(i * n, i * keep.size(), n, keep.size()) = U1;
  }
  if (var == kSimpCorotTan || var == kSimpStartTan)
    lu.compute(U.transpose() * SystemMatrix(P, h, Aq, B) * U);
  else if (var != kFull && var != kFullTan)
    lu.compute(SystemMatrix(P, h, Aq, B));
  double prev = 0, eta = 1.0;
  Eigen::VectorXd G(3 * n), a(n);
  for (int it = 0; it < max_it; ++it) {
    Stages(P, y, h, Zv, Y);
    for (int i = 0; i < 3; ++i) {
      P.m.Acceleration(Y[i].head(n), Y[i].tail(n), a);
      G.segment(i * n, n) = a;
      for (int j = 0; j < 3; ++j) G.segment(i * n, n) -= (K.Ainv[i][j] / h) * Zv.segment(j * n, n);
    }
    Eigen::VectorXd dZ;
    if (var == kFull || var == kFullTan) {
      for (int i = 0; i < 3; ++i) {
        P.m.Jacobian(Y[i].head(n), Y[i].tail(n), &Ab, &Bb);
        Aq[i] = Dense(Ab), B[i] = Dense(Bb);
      }
      const Eigen::MatrixXd M = SystemMatrix(P, h, Aq, B);
      if (it == 0 && g_print_condition) {
        Eigen::MatrixXd Ms = var == kFull ? M : Eigen::MatrixXd(U.transpose() * M * U);
        Eigen::BDCSVD<Eigen::MatrixXd> svd(Ms);
        const auto& sv = svd.singularValues();
        std::printf("      %s at the start: sigma_max %.3g sigma_min %.3g cond %.3g\n", kName[var],
                    sv[0], sv[sv.size() - 1], sv[0] / sv[sv.size() - 1]);
      }
      if (var == kFull)
        dZ = M.partialPivLu().solve(G);
      else
        dZ = U * (U.transpose() * M * U).partialPivLu().solve(U.transpose() * G);
    } else if (var == kSimpCorot || var == kSimpEndCorot || var == kSimpCorotTan) {
      Eigen::VectorXd r = G;
      for (int i = 0; i < 3; ++i) {
        rot[i].Update(qref, Y[i].head(n));
        auto ri = r.segment(i * n, n);
        rot[i].Apply(ri, true);
      }
      dZ = var == kSimpCorotTan ? Eigen::VectorXd(U * lu.solve(U.transpose() * r)) : Eigen::VectorXd(lu.solve(r));
      for (int i = 0; i < 3; ++i) {
        auto di = dZ.segment(i * n, n);
        rot[i].Apply(di, false);
      }
    } else if (var == kSimpStartTan) {
      dZ = U * lu.solve(U.transpose() * G);
    } else {
      dZ = lu.solve(G);
    }
    const double d = Norm(P, y, h, dZ);
    Zv += dZ;
    res.d.push_back(d);
    if (res.verdict.empty()) {
      std::string v;
      if (!std::isfinite(d)) v = "div";
      if (v.empty() && it > 0) {
        const double th = d / prev;
        if (th >= 0.99) v = "div";
        eta = th / (1 - th);
        if (v.empty() && std::pow(th, 7 - 1 - it) / (1 - th) * d > 0.05) v = "slow";
      }
      if (v.empty() && (eta * d <= 0.05 || d == 0)) v = "conv";
      if (v.empty() && it == 6) v = "slow";
      if (!v.empty()) {
        res.verdict = v, res.verdict_it = it + 1;
        res.dominant = Dominant(P, y, h, dZ, Y);
      }
    }
    if (!std::isfinite(d) || d > 1e30) break;
    if (d < 1e-5 && res.its_to_1e8 < 0) {
      res.its_to_1e8 = it + 1, res.converged_eventually = true;
      break;
    }
    prev = d;
  }
  res.Zv = Zv;
  return res;
}

int main(int argc, char** argv) {
  const bool steel = argc > 1 && std::strcmp(argv[1], "b") == 0;
  QuatFdOptions opt;
  opt.segments = steel ? 20 : 10;
  opt.base_end = steel ? EndCondition::kPinned : EndCondition::kClamped;
  QuatFdModel model(steel ? bench::SteelString() : bench::RubberRod(), bench::Horizontal(), opt);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  model.set_loads(loads);
  const int n = model.size();
  Eigen::VectorXd q(n), v(n);
  model.RestState(q, v);
  IntegratorOptions io;
  RadauIntegrator radau(model, io);
  Problem P{model, n, opt.segments};
  std::vector<double> times = {0.5, 2.0, 5.0};
  std::vector<double> hs = {0.5e-3, 1e-3, 2e-3, 4e-3, 8e-3, 16e-3, 32e-3};
  double t = 0;
  const int variants = argc > 2 ? std::atoi(argv[2]) : 511;
  const bool warm = argc <= 3 || std::atoi(argv[3]) != 0;
  for (double te : times) {
    Eigen::VectorXd y(2 * n);
    RadauIntegrator base = radau;
    Eigen::VectorXd qb = q, vb = v;
    double tb = t;
    radau.Advance(te, &t, q, v);
    y << q, v;
    std::printf("== %s t = %.1f s (radau last dt %.2f ms) start %s\n", steel ? "(b)" : "(a)", t,
                radau.stats().last_dt * 1e3, warm ? "extrapolated" : "zero");
    {
      double wmax = 0;
      int wseg = 0;
      for (int sg = 0; sg < opt.segments; ++sg) {
        const Eigen::Vector4d p = q.segment<4>(L::P(sg)), pd = v.segment<4>(L::P(sg));
        // ω (body) = 2 Im(p̄ ṗ)/|p|²
        const Eigen::Vector3d w = 2 * (p[0] * pd.tail<3>() - pd[0] * p.tail<3>() -
                                       p.tail<3>().cross(pd.tail<3>())) / p.squaredNorm();
        if (w.norm() > wmax) wmax = w.norm(), wseg = sg;
      }
      std::printf("   max |omega| %.3g rad/s at segment %d\n", wmax, wseg);
      // Eigenvalues of J = [[0, I], [df/dq, df/dv]] at y_n with Re > 1 1/s: the iteration matrix
      // a I − J (a = γ/h, (α ± iβ)/h) is singular where a meets one of them.
      BandedMatrix Ab, Bb;
      model.Jacobian(q, v, &Ab, &Bb);
      Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2 * n, 2 * n);
      J.topRightCorner(n, n).setIdentity();
      J.bottomLeftCorner(n, n) = Dense(Ab);
      J.bottomRightCorner(n, n) = Dense(Bb);
      Eigen::EigenSolver<Eigen::MatrixXd> es(J);
      for (int k = 0; k < 2 * n; ++k) {
        const std::complex<double> lam = es.eigenvalues()[k];
        if (lam.real() <= 1.0 || lam.imag() < 0) continue;
        const Eigen::VectorXcd x = es.eigenvectors().col(k);
        double xs = 0, pr = 0, pt = 0;
        int seg = 0;
        double best = 0;
        for (int kk = 0; kk <= opt.segments; ++kk) xs = std::max(xs, x.segment(L::X(kk), 3).norm());
        for (int sg = 0; sg < opt.segments; ++sg) {
          const Eigen::Vector4d p = q.segment<4>(L::P(sg)).normalized();
          const Eigen::Vector4cd a = x.segment<4>(L::P(sg));
          const std::complex<double> r = p.cast<std::complex<double>>().dot(a);
          pr = std::max(pr, std::abs(r));
          const double tn = (a - r * p.cast<std::complex<double>>()).norm();
          pt = std::max(pt, tn);
          if (std::max(std::abs(r), tn) > best) best = std::max(std::abs(r), tn), seg = sg;
        }
        std::printf("   J eigenvalue %.4g %+.4gi  (h where gamma/h meets Re: %.3g ms)  eigvec q-part: x %.2g  p radial %.2g  p tangent %.2g  (largest at segment %d)\n",
                    lam.real(), lam.imag(), 3.6378 / lam.real() * 1e3, xs, pr, pt, seg);
      }
    }
    for (double h : hs) {
      Eigen::VectorXd Z0v = Eigen::VectorXd::Zero(3 * n);
      if (warm) {
        // The step before, of the same h, solved tightly; its collocation polynomial
        // extrapolated as in radau.cpp (StartingValues).
        RadauIntegrator r2 = base;
        Eigen::VectorXd q2 = qb, v2 = vb;
        double t2 = tb;
        r2.Advance(te - h, &t2, q2, v2);
        Eigen::VectorXd yp(2 * n);
        yp << q2, v2;
        const char* how = "full";
        Result pr = Solve(P, yp, h, kFull, nullptr, Eigen::VectorXd::Zero(3 * n), 60);
        if (!pr.converged_eventually) {
          how = "full-tan, then full from it";
          pr = Solve(P, yp, h, kFullTan, nullptr, Eigen::VectorXd::Zero(3 * n), 60);
          pr = Solve(P, yp, h, kFull, nullptr, pr.Zv, 60);
        }
        std::vector<Eigen::VectorXd> Yp;
        Stages(P, yp, h, pr.Zv, Yp);
        Eigen::VectorXd Z[3];
        for (int i = 0; i < 3; ++i) Z[i] = Yp[i] - yp;
        y = yp + Z[2];
        auto yq = y.head(n);
        auto yv = y.tail(n);
        model.Project(yq, yv);
        const double c1 = K.c[0], c2 = K.c[1];
        Eigen::VectorXd cont0 = (Z[1] - Z[2]) / (c2 - 1);
        Eigen::VectorXd dZ = (Z[0] - Z[1]) / (c1 - c2);
        Eigen::VectorXd cont1 = (dZ - cont0) / (c1 - 1);
        dZ = (dZ - Z[0] / c1) / c2;
        Eigen::VectorXd cont2 = cont1 - dZ;
        for (int i = 0; i < 3; ++i) {
          const double s = K.c[i];
          Eigen::VectorXd zi = s * (cont0 + (s - (c2 - 1)) * (cont1 + (s - (c1 - 1)) * cont2));
          Z0v.segment(i * n, n) = zi.tail(n);
        }
        std::printf("h %5.1f ms  previous step by %s (%s)\n", h * 1e3, how,
                    pr.converged_eventually ? "converged" : "NOT converged");
      }
      if (!warm) {
        // Cross-check of the emulation: the integrator's own Step (fresh J, Z = 0 start).
        RadauIntegrator fresh(model, io);
        fresh.ForgetHistory();
        Eigen::VectorXd y_new(2 * n), error(2 * n);
        const bool ok = fresh.Step(y, h, y_new, error);
        std::printf("h %5.1f ms RadauIntegrator::Step %s after %ld iterations\n", h * 1e3,
                    ok ? "converged" : "failed", fresh.newton_stats().newton_iterations);
      }
      Result full;
      const Variant order[] = {kSimpCorot, kSimpPlain, kFull, kFullTan, kSimpOracle, kSimpStart, kSimpEndCorot, kSimpCorotTan, kSimpStartTan};
      for (int vi = 0; vi < 9; ++vi) {
        Variant var = order[vi];
        if (!((variants >> vi) & 1)) continue;
        if (var == kSimpOracle && !full.converged_eventually) continue;
        g_print_condition = std::getenv("COND") != nullptr;
        Result r = Solve(P, y, h, var, &full.Zv, Z0v);
        g_print_condition = false;
        if (var == kFull) full = r;
        std::printf("h %5.1f ms %-11s verdict %-4s @%d  to1e-5 %3d  d:", h * 1e3, kName[var],
                    r.verdict.c_str(), r.verdict_it, r.its_to_1e8);
        for (size_t k = 0; k < r.d.size() && k < 10; ++k) std::printf(" %.1e", r.d[k]);
        std::printf("\n      theta:");
        for (size_t k = 1; k < r.d.size() && k < 10; ++k) std::printf(" %.2f", r.d[k] / r.d[k - 1]);
        std::printf("\n      dominant at verdict: %s\n", r.dominant.c_str());
      }
    }
    std::fflush(stdout);
  }
}
