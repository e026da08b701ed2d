#include "cosserat/lie/se3.hpp"

namespace cosserat::lie {

Mat4 hat6(const Vec6& xi) { return hat6<double>(xi); }
Vec6 vee6(const Mat4& X) { return vee6<double>(X); }
SE3 SE3Exp(const Vec6& xi) { return SE3Exp<double>(xi); }
Mat6 ad(const Vec6& xi) { return ad<double>(xi); }
Mat6 coad(const Vec6& xi) { return coad<double>(xi); }
Mat6 SE3LeftJacobian(const Vec6& xi) { return SE3LeftJacobian<double>(xi); }
Mat6 SE3RightJacobian(const Vec6& xi) { return SE3LeftJacobian<double>(-xi); }
Mat6 SE3LeftJacobianInverse(const Vec6& xi) { return SE3LeftJacobianInverse<double>(xi); }
Mat6 SE3RightJacobianInverse(const Vec6& xi) { return SE3LeftJacobianInverse<double>(-xi); }

}  // namespace cosserat::lie
