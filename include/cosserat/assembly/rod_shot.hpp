#pragma once
/// \file
/// One rod's static shot for the assembly solver, in the normalised arc length σ = s/L, so that
/// the rod's length is a variable like its start: dy/dσ = L y'(s), RK4 over the rod's grid with
/// the sections at the nodes and the midpoints (the scheme of StaticShootingSolver). Templated on
/// the scalar: with T = ceres::Jet one shot gives the tip's exact derivatives in the start and
/// the length. The sections are sampled once at s = σ L₀ (L₀ the model's length): exact for a
/// uniform rod at any length. Loads: the distributed ones that do not depend on the pose
/// (gravity, buoyancy, a distributed force).

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
  template <typename T>
  Point<T> Rate(const Sample& smp, const Point<T>& y, const T& length) const;
  /// The RK4 step over segment i (nodes i to i + 1).
  template <typename T>
  Point<T> Step(int i, const Point<T>& y, const T& length) const;

  std::vector<double> sigma_;    ///< node fractions s/L₀, 0 … 1
  std::vector<Sample> samples_;  ///< node i at 2i, midpoint i + 1/2 at 2i + 1
  double model_length_ = 0.0, bending_stiffness_ = 0.0;
};

template <typename T>
RodShot::Point<T> RodShot::Rate(const Sample& smp, const Point<T>& y, const T& length) const {
  Vector6<T> xi;
  const Vector3<T> f = smp.force_W.template cast<T>();
  Point<T> d = rhs::StaticDerivative<T>(smp.rest_strain, smp.compliance, f, y, &xi);
  d.p *= length;
  d.R *= length;
  d.m *= length;
  d.n *= length;
  return d;
}

template <typename T>
RodShot::Point<T> RodShot::Step(int i, const Point<T>& y0, const T& length) const {
  auto axpy = [](const Point<T>& y, double a, const Point<T>& k) {
    return Point<T>{y.p + a * k.p, y.R + a * k.R, y.m + a * k.m, y.n + a * k.n};
  };
  const double h = sigma_[i + 1] - sigma_[i];
  const Sample &s0 = samples_[2 * i], &sm = samples_[2 * i + 1], &s1 = samples_[2 * i + 2];
  const Point<T> k1 = Rate(s0, y0, length);
  const Point<T> k2 = Rate(sm, axpy(y0, 0.5 * h, k1), length);
  const Point<T> k3 = Rate(sm, axpy(y0, 0.5 * h, k2), length);
  const Point<T> k4 = Rate(s1, axpy(y0, h, k3), length);
  const double a = h / 6, b = h / 3;
  Point<T> y = y0;
  y.p += a * (k1.p + k4.p) + b * (k2.p + k3.p);
  y.R += a * (k1.R + k4.R) + b * (k2.R + k3.R);
  y.m += a * (k1.m + k4.m) + b * (k2.m + k3.m);
  y.n += a * (k1.n + k4.n) + b * (k2.n + k3.n);
  return y;
}

template <typename T>
RodShot::Point<T> RodShot::Shoot(const Point<T>& start, const T& length) const {
  Point<T> y = start;
  for (int i = 0; i + 1 < nodes(); ++i) y = Step(i, y, length);
  return y;
}

}  // namespace cosserat
