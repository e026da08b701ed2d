#include "cosserat/quatfd/frozen_jacobian.hpp"

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

}  // namespace cosserat::quatfd
