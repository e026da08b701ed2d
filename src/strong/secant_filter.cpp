#include "cosserat/strong/secant_filter.hpp"

namespace cosserat {

void SecantFilter::Restart(const Mat6& jacobian) {
  jacobian_ = jacobian;
  rate_.setZero();
  covariance_.setZero();
  covariance_.topLeftCorner<6, 6>().diagonal().setOnes();
  covariance_.bottomRightCorner<6, 6>().diagonal().setConstant(1e-2);
}

void SecantFilter::Advance() {
  jacobian_ += rate_;
  rate_ *= kRateMemory;
  const Mat6 A = covariance_.topLeftCorner<6, 6>(), B = covariance_.topRightCorner<6, 6>(),
             C = covariance_.bottomRightCorner<6, 6>();
  covariance_.topLeftCorner<6, 6>() = A + B + B.transpose() + C;
  covariance_.topLeftCorner<6, 6>().diagonal().array() += kDriftJ;
  covariance_.topRightCorner<6, 6>() = kRateMemory * (B + C);
  covariance_.bottomLeftCorner<6, 6>() = kRateMemory * (B + C).transpose();
  covariance_.bottomRightCorner<6, 6>() = kRateMemory * kRateMemory * C;
  covariance_.bottomRightCorner<6, 6>().diagonal().array() += kDriftRate;
}

void SecantFilter::Update(const Vec6& dx, const Vec6& dr) {
  using Vec12 = Eigen::Matrix<double, 12, 1>;
  const Vec6 miss = dr - jacobian_ * dx;
  const Vec12 Ph = covariance_.leftCols<6>() * dx;  // P hᵀ for the measurement h = [dxᵀ 0]
  const double S = dx.dot(Ph.head<6>());
  if (S > 1e-3 * kDriftJ * dx.squaredNorm()) {
    const Vec12 K = Ph / S;
    jacobian_ += miss * K.head<6>().transpose();
    rate_ += miss * K.tail<6>().transpose();
    covariance_ -= K * Ph.transpose();
  } else {
    // dx along a direction already measured this step (P has no variance left there): Broyden's
    // update.
    jacobian_ += miss * dx.transpose() / dx.squaredNorm();
  }
}

}  // namespace cosserat
