#include "cosserat/quatfd/frozen_jacobian.hpp"

#include <algorithm>

namespace cosserat::quatfd {

void FrozenJacobian::Resize(const QuatFdModel& model) {
  const int n = model.size(), bw = QuatFdLayout::kBandwidth;
  dfdq.Resize(n, bw, bw);
  dfdv.Resize(n, bw, bw);
  q.resize(n);
  f.resize(n);
}

void FrozenJacobian::Evaluate(const QuatFdModel& model, const Eigen::Ref<const Eigen::VectorXd>& y,
                              IntegratorStats* stats) {
  const int n = model.size();
  model.Jacobian(y.head(n), y.tail(n), &dfdq, &dfdv, &f);
  q = y.head(n);
  ++stats->jacobian_evaluations;
  valid = true;
  fresh = true;
}

void FrozenJacobian::AssembleShifted(double a, BandedMatrix* m) const {
  const int n = static_cast<int>(q.size()), bw = QuatFdLayout::kBandwidth;
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - bw); i <= std::min(n - 1, j + bw); ++i)
      (*m)(i, j) = -a * dfdv(i, j) - dfdq(i, j) + (i == j ? a * a : 0.0);
}

void FrozenJacobian::SolveShifted(double a, const BandedMatrix& m, Eigen::Ref<Eigen::VectorXd> r,
                                  Eigen::Ref<Eigen::VectorXd> acc) const {
  const Eigen::Index n = q.size();
  auto rq = r.head(n);
  auto rv = r.tail(n);
  dfdq.Multiply(rq, acc);
  rv = a * rv + acc;
  m.Solve(rv);
  rq = (rq + rv) / a;
}

}  // namespace cosserat::quatfd
