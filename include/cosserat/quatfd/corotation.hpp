#pragma once
/// \file
/// The co-rotation that lets an implicit integrator keep a Jacobian J(y_J) while the rod turns
/// (sdirk.hpp, radau.hpp): the iteration matrix is applied as P (aI − J)⁻¹ Pᵀ with P block-
/// diagonal — per segment ν the left multiplication by the world rotation w_ν = p_ν p̄_ν,J / (|p_ν|
/// |p_ν,J|) (on p and ṗ; it keeps body directions and the radial one), per vertex the rotation by
/// the mean of its segments' w (on x and ẋ). The model is equivariant under rigid rotations (up to
/// gravity and the clamp), so this is the Jacobian at the iterate up to the change of the relative
/// rotations and strains: the turning of the stiff directions is followed.

#include <Eigen/Core>
#include <vector>

namespace cosserat::quatfd {

class CoRotation {
 public:
  /// Allocates for `segments` segments; Update and Apply do not allocate.
  explicit CoRotation(int segments = 0);
  void Resize(int segments);

  /// P for the turn from the quaternions of q_ref (where J was evaluated) to those of q (both in
  /// the QuatFdLayout of the positions).
  void Update(const Eigen::Ref<const Eigen::VectorXd>& q_ref,
              const Eigen::Ref<const Eigen::VectorXd>& q);
  /// r ← P r (or Pᵀ r) on one half of the state (positions or velocities, n entries).
  void Apply(Eigen::Ref<Eigen::VectorXd> r, bool transpose) const;

 private:
  int segments_ = 0;
  std::vector<Eigen::Vector4d> segment_w_;
  std::vector<Eigen::Matrix4d> segment_rot_;
  std::vector<Eigen::Matrix3d> vertex_rot_;
};

}  // namespace cosserat::quatfd
