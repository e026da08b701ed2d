#pragma once
/// \file
/// One rod's static shot for the assembly solver, in the normalised arc length σ = s/L, so that
/// the rod's length is a variable like its start: dy/dσ = L y'(s), RK4 over the rod's grid with
/// the sections at the nodes and the midpoints. Templated on the scalar: with T = ceres::Jet one
/// shot gives the tip's exact derivatives in the start and the length. The sections are sampled
/// once at s = σ L₀ (L₀ the model's length): exact for a uniform rod at any length. Loads: the
/// distributed ones that do not depend on the pose (gravity, buoyancy, a distributed force).
///
/// Its ends speak the body-frame wrench [m; n] (Point), but the shot carries the internal force
/// in the world, n_W = R n, and the internal moment about the world origin, J = R m + p × n_W:
/// then n_W' = −f and J' = −p × f, so RK4 sums the loads with its own quadrature and a rod's end
/// wrenches balance them to round-off (LoadWrench_W gives that sum): an assembly's reactions
/// balance its loads exactly, not to the grid's truncation.

#include <vector>

#include "cosserat/loads/static_loads.hpp"
#include "cosserat/rod/rod_model.hpp"
#include "cosserat/state/rod_state.hpp"
#include "cosserat/strong/cosserat_rhs.hpp"
#include "cosserat/strong/shot_tangent.hpp"

namespace cosserat {

class RodShot {
 public:
  template <typename T>
  using Point = rhs::StaticPoint<T>;

  /// Throws std::invalid_argument for an invalid model, fewer than 2 nodes or a rod with
  /// tendons.
  RodShot(const RodModel& model, int nodes);

  /// The distributed loads per unit length at each sample (world, N/m).
  void SetLoads(const StaticLoads& loads);

  /// The state at s = L from the state at s = 0, for the rod's length L (m).
  template <typename T>
  Point<T> Shoot(const Point<T>& start, const T& length) const;

  /// The same shot in double with the exact derivative of its tip along 6 directions of the
  /// start (`start_tangent`, the length fixed): the hand-written linearisation of the right-hand
  /// side (shot_tangent.hpp) carried through the same RK4 steps. Writes the tip's tangent.
  Point<double> ShootTangent(const Point<double>& start, const rhs::StaticTangent& start_tangent,
                             double length, rhs::StaticTangent* tip_tangent) const;

  /// The same shot, recording every node into *state (resized to the grid; s scaled to L).
  void Record(const Point<double>& start, double length, RodState* state) const;

  /// The distributed loads on the rod shot from `start` at `length`, as the shot sums them:
  /// [moment about the world origin (N·m); force (N)], world. The rod's end wrenches balance it
  /// to round-off.
  Vec6 LoadWrench_W(const Point<double>& start, double length) const;

  int nodes() const { return static_cast<int>(sigma_.size()); }
  double model_length() const { return model_length_; }
  /// Bending stiffness at s = 0, the larger of the two (N·m²): the rod's scale.
  double bending_stiffness() const { return bending_stiffness_; }

 private:
  struct Sample {
    Vec6 rest_strain;  ///< ξ*, per unit length
    Vec6 compliance;   ///< diag K⁻¹
    Vec3 force_W = Vec3::Zero();  ///< distributed load, N/m
    double mass_per_length = 0.0, outer_diameter = 0.0, s = 0.0;
  };
  /// The state the shot carries: pose, J = R m + p × n_W (N·m, about the world origin) and
  /// n_W (N), world.
  template <typename T>
  struct Carried {
    Vector3<T> p;
    Matrix3<T> R;
    Vector3<T> J;
    Vector3<T> n;
  };
  template <typename T>
  static Carried<T> ToCarried(const Point<T>& y);
  /// The body-frame wrench at the ends: m_B = R⁻¹ (J − p × n_W), n_B = R⁻¹ n_W with the inverse,
  /// not the transpose: RK4 leaves R a rotation only to its truncation (~1e-9 near an
  /// equilibrium, up to ~0.1 on a hard-bent iterate), and R n_B must give back n_W to round-off
  /// for the balance.
  template <typename T>
  static Point<T> FromCarried(const Carried<T>& c);
  /// The same with Rᵀ, for the strain at a stage (where the difference is truncation).
  template <typename T>
  static Point<T> AtStage(const Carried<T>& c);
  /// dc/dσ: p' = R Γ, R' = R K̂ (the strain from the body-frame wrench), J' = −p × f,
  /// n_W' = −f, each times the length.
  template <typename T>
  Carried<T> Rate(const Sample& smp, const Carried<T>& c, const T& length) const;
  /// The RK4 step over segment i (nodes i to i + 1).
  template <typename T>
  Carried<T> Step(int i, const Carried<T>& c, const T& length) const;

  std::vector<double> sigma_;    ///< node fractions s/L₀, 0 … 1
  std::vector<Sample> samples_;  ///< segment i: start 3i, middle 3i + 1, end 3i + 2 (inside)
  double model_length_ = 0.0, bending_stiffness_ = 0.0;
};

template <typename T>
RodShot::Carried<T> RodShot::ToCarried(const Point<T>& y) {
  Carried<T> c{y.p, y.R, Vector3<T>(), Vector3<T>()};
  c.n = y.R * y.n;
  c.J = y.R * y.m + y.p.cross(c.n);
  return c;
}

template <typename T>
RodShot::Point<T> RodShot::FromCarried(const Carried<T>& c) {
  const Matrix3<T> R_inv = c.R.inverse();
  return Point<T>{c.p, c.R, R_inv * (c.J - c.p.cross(c.n)), R_inv * c.n};
}

template <typename T>
RodShot::Point<T> RodShot::AtStage(const Carried<T>& c) {
  const Matrix3<T> Rt = c.R.transpose();
  return Point<T>{c.p, c.R, Rt * (c.J - c.p.cross(c.n)), Rt * c.n};
}

template <typename T>
COSSERAT_RHS_INLINE RodShot::Carried<T> RodShot::Rate(const Sample& smp, const Carried<T>& c,
                                                      const T& length) const {
  // m_B = Rᵀ (J − p × n_W), n_B = Rᵀ n_W, written out: through AtStage (a copy of R and two
  // products) the warm inverse kinematics of the Stewart–Gough robot ran ~20 % slower.
  const Vector3<T> q = c.J - c.p.cross(c.n);
  Vector3<T> m_B, n_B;
  for (int j = 0; j < 3; ++j) {
    m_B(j) = c.R(0, j) * q(0) + c.R(1, j) * q(1) + c.R(2, j) * q(2);
    n_B(j) = c.R(0, j) * c.n(0) + c.R(1, j) * c.n(1) + c.R(2, j) * c.n(2);
  }
  Vector6<T> xi;
  rhs::LinearStrain<T>(smp.rest_strain, smp.compliance, m_B, n_B, &xi);
  // dc/dσ = L c'(s): the strain's length scales the rates.
  xi *= length;
  Carried<T> d;
  rhs::KinematicRates<T>(c.R, xi.data(), &d.p, &d.R);
  const Vec3& f = smp.force_W;
  d.J = Vector3<T>(f(1) * c.p(2) - f(2) * c.p(1), f(2) * c.p(0) - f(0) * c.p(2),
                   f(0) * c.p(1) - f(1) * c.p(0)) * length;  // −p × f = f × p
  d.n = -length * f.template cast<T>();
  return d;
}

template <typename T>
COSSERAT_RHS_INLINE RodShot::Carried<T> RodShot::Step(int i, const Carried<T>& c0,
                                                      const T& length) const {
  auto axpy = [](const Carried<T>& y, double a, const Carried<T>& k) {
    return Carried<T>{y.p + a * k.p, y.R + a * k.R, y.J + a * k.J, y.n + a * k.n};
  };
  const double h = sigma_[i + 1] - sigma_[i];
  const Sample &s0 = samples_[3 * i], &sm = samples_[3 * i + 1], &s1 = samples_[3 * i + 2];
  const Carried<T> k1 = Rate(s0, c0, length);
  const Carried<T> k2 = Rate(sm, axpy(c0, 0.5 * h, k1), length);
  const Carried<T> k3 = Rate(sm, axpy(c0, 0.5 * h, k2), length);
  const Carried<T> k4 = Rate(s1, axpy(c0, h, k3), length);
  const double a = h / 6, b = h / 3;
  Carried<T> c = c0;
  c.p += a * (k1.p + k4.p) + b * (k2.p + k3.p);
  c.R += a * (k1.R + k4.R) + b * (k2.R + k3.R);
  c.J += a * (k1.J + k4.J) + b * (k2.J + k3.J);
  c.n += a * (k1.n + k4.n) + b * (k2.n + k3.n);
  return c;
}

template <typename T>
RodShot::Point<T> RodShot::Shoot(const Point<T>& start, const T& length) const {
  Carried<T> c = ToCarried(start);
  for (int i = 0; i + 1 < nodes(); ++i) c = Step(i, c, length);
  return FromCarried(c);
}

}  // namespace cosserat
