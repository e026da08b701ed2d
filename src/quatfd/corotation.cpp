#include "cosserat/quatfd/corotation.hpp"

#include <cmath>

#include "cosserat/quatfd/quatfd_kernels.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"

namespace cosserat::quatfd {

CoRotation::CoRotation(int segments) { Resize(segments); }

void CoRotation::Resize(int segments) {
  segments_ = segments;
  segment_w_.resize(segments);
  segment_rot_.resize(segments);
  vertex_rot_.resize(segments + 1);
}

void CoRotation::Update(const Eigen::Ref<const Eigen::VectorXd>& q_ref,
                        const Eigen::Ref<const Eigen::VectorXd>& q) {
  // Written out (one reciprocal square root per rotation, the vertex matrix from its quaternion
  // directly): called three times per Newton iteration of the Radau integrator.
  const int N = segments_;
  for (int nu = 0; nu < N; ++nu) {
    const Eigen::Vector4d p = q.segment<4>(QuatFdLayout::P(nu));
    const Eigen::Vector4d pj = q_ref.segment<4>(QuatFdLayout::P(nu));
    // w = p ⊗ p̄_J / (|p| |p_J|): the world rotation that takes segment ν from where J was
    // evaluated to q.
    Eigen::Vector4d w = lie::QuatMultiply<double>(p, Eigen::Vector4d(pj[0], -pj[1], -pj[2], -pj[3]));
    w *= 1.0 / std::sqrt(w.squaredNorm());
    segment_w_[nu] = w;
    Eigen::Matrix4d& L = segment_rot_[nu];  // left multiplication by w
    L << w[0], -w[1], -w[2], -w[3],  //
        w[1], w[0], -w[3], w[2],     //
        w[2], w[3], w[0], -w[1],     //
        w[3], -w[2], w[1], w[0];
  }
  for (int k = 0; k <= N; ++k) {
    // A vertex turns with the mean of its segments' rotations (same hemisphere).
    Eigen::Vector4d w = k < N ? segment_w_[k] : segment_w_[N - 1];
    if (k > 0 && k < N) {
      const Eigen::Vector4d& o = segment_w_[k - 1];
      w += w.dot(o) >= 0 ? o : Eigen::Vector4d(-o);
      w *= 1.0 / std::sqrt(w.squaredNorm());
    }
    // R(w) for the unit quaternion w = [c, u]: I + 2c[u]× + 2[u]×².
    const double c = w[0], x = w[1], y = w[2], z = w[3];
    Eigen::Matrix3d& R = vertex_rot_[k];
    R << 1 - 2 * (y * y + z * z), 2 * (x * y - c * z), 2 * (x * z + c * y),  //
        2 * (x * y + c * z), 1 - 2 * (x * x + z * z), 2 * (y * z - c * x),   //
        2 * (x * z - c * y), 2 * (y * z + c * x), 1 - 2 * (x * x + y * y);
  }
}

void CoRotation::Apply(Eigen::Ref<Eigen::VectorXd> r, bool transpose) const {
  for (int k = 0; k <= segments_; ++k) {
    auto x = r.segment<3>(QuatFdLayout::X(k));
    const Eigen::Vector3d x0 = x;
    if (transpose)
      x.noalias() = vertex_rot_[k].transpose() * x0;
    else
      x.noalias() = vertex_rot_[k] * x0;
  }
  for (int nu = 0; nu < segments_; ++nu) {
    auto x = r.segment<4>(QuatFdLayout::P(nu));
    const Eigen::Vector4d x0 = x;
    if (transpose)
      x.noalias() = segment_rot_[nu].transpose() * x0;
    else
      x.noalias() = segment_rot_[nu] * x0;
  }
}

}  // namespace cosserat::quatfd
