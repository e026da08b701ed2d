// The Jacobian path of the quaternion-FD model: f = q̈ with ∂f/∂q and ∂f/∂v, banded, from the
// hand-derived element Jacobians (quatfd_kernel_jacobians.hpp) or, as their oracle, from Jets.
#include <ceres/jet.h>

#include <Eigen/Dense>
#include <algorithm>

#include "cosserat/quatfd/quatfd_kernel_jacobians.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"

namespace cosserat::quatfd {
namespace {

using kernels::V3;
using kernels::V4;
using L = QuatFdLayout;

template <int N>
using Jet = ceres::Jet<double, N>;

/// Seeds a Jet vector from doubles, derivative slots offset .. offset + size − 1.
template <int N, int M>
Eigen::Matrix<Jet<N>, M, 1> Seed(const Eigen::Ref<const Eigen::VectorXd>& x, int at, int offset) {
  Eigen::Matrix<Jet<N>, M, 1> out;
  for (int i = 0; i < M; ++i) out[i] = Jet<N>(x[at + i], offset + i);
  return out;
}

template <int M>
Eigen::Matrix<double, M, 1> Value(const Eigen::Ref<const Eigen::VectorXd>& x, int at) {
  return x.segment<M>(at);
}

/// Adds d out / d(slots [slot, slot + width)) of a 3-vector Jet output into rows row..row+2 of
/// the band matrix, columns col..col+width−1.
template <int N>
void AddBlock(const V3<Jet<N>>& out, int slot, int width, int row, int col, BandedMatrix* A) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < width; ++j) (*A)(row + i, col + j) += out[i].v[slot + j];
}

/// Adds a (3 × w) block into rows row..row+2, columns col..col+w−1 of D.
template <typename Block>
void AddRows(BandedMatrix* D, int row, int col, const Block& block) {
  for (int j = 0; j < block.cols(); ++j)
    for (int i = 0; i < 3; ++i) (*D)(row + i, col + j) += block(i, j);
}

/// SegmentForces and its Jacobian by Jet (the oracle of SegmentForcesJacobian) for the segment
/// between x_a (at xa) and x_b (at xb) with quaternion p (at pp). Slots: dx 0..2, p 3..6, dv
/// 7..9, ṗ 10..13.
void SegmentForcesAutoDiff(const kernels::SegmentConstants& c,
                           const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v, int xa, int xb, int pp,
                           Vec3* fa, Vec3* tau, kernels::SegmentJacobian* J) {
  using Jt = Jet<14>;
  V3<Jt> dx, dv, fj, tj;
  for (int k = 0; k < 3; ++k) {
    dx[k] = Jt(q[xb + k] - q[xa + k], k);
    dv[k] = Jt(v[xb + k] - v[xa + k], 7 + k);
  }
  kernels::SegmentForces<Jt>(c, dx, Seed<14, 4>(q, pp, 3), dv, Seed<14, 4>(v, pp, 10), &fj, &tj);
  for (int r = 0; r < 3; ++r) {
    (*fa)[r] = fj[r].a;
    (*tau)[r] = tj[r].a;
    for (int k = 0; k < 3; ++k) {
      J->fa_dx(r, k) = fj[r].v[k];
      J->fa_dv(r, k) = fj[r].v[7 + k];
      J->tau_dx(r, k) = tj[r].v[k];
      J->tau_dv(r, k) = tj[r].v[7 + k];
    }
    for (int k = 0; k < 4; ++k) {
      J->fa_p(r, k) = fj[r].v[3 + k];
      J->fa_pd(r, k) = fj[r].v[10 + k];
      J->tau_p(r, k) = tj[r].v[3 + k];
      J->tau_pd(r, k) = tj[r].v[10 + k];
    }
  }
}

/// BendTorques and its Jacobian by Jet (the oracle of BendTorquesJacobian). Slots: p_a 0..3,
/// p_b 4..7, ṗ_a 8..11, ṗ_b 12..15.
void BendTorquesAutoDiff(const kernels::BendConstants& c, const Vec4& pa, const Vec4& pb,
                         const Vec4& pda, const Vec4& pdb, Vec3* ta, Vec3* tb,
                         kernels::BendJacobian* J) {
  using Jt = Jet<16>;
  V3<Jt> tja, tjb;
  kernels::BendTorques<Jt>(c, Seed<16, 4>(pa, 0, 0), Seed<16, 4>(pb, 0, 4), Seed<16, 4>(pda, 0, 8),
                           Seed<16, 4>(pdb, 0, 12), &tja, &tjb);
  for (int r = 0; r < 3; ++r) {
    (*ta)[r] = tja[r].a;
    (*tb)[r] = tjb[r].a;
    for (int k = 0; k < 4; ++k) {
      J->ta_pa(r, k) = tja[r].v[k];
      J->ta_pb(r, k) = tja[r].v[4 + k];
      J->ta_pda(r, k) = tja[r].v[8 + k];
      J->ta_pdb(r, k) = tja[r].v[12 + k];
      J->tb_pa(r, k) = tjb[r].v[k];
      J->tb_pb(r, k) = tjb[r].v[4 + k];
      J->tb_pda(r, k) = tjb[r].v[8 + k];
      J->tb_pdb(r, k) = tjb[r].v[12 + k];
    }
  }
}

/// QuaternionAcceleration and its Jacobian by Jet (the oracle of
/// QuaternionAccelerationJacobian). Slots: p 0..3, ṗ 4..7, τ 8..10.
void QuaternionAccelerationAutoDiff(const kernels::RotationConstants& rc, const Vec4& p,
                                    const Vec4& pd, const Vec3& tau, Vec4* acc, kernels::M44* acc_p,
                                    kernels::M44* acc_pd, kernels::M43* acc_tau) {
  using Jt = Jet<11>;
  Eigen::Matrix<Jt, 3, 1> tj;
  for (int k = 0; k < 3; ++k) tj[k] = Jt(tau[k], 8 + k);
  const V4<Jt> accj =
      kernels::QuaternionAcceleration<Jt>(rc, Seed<11, 4>(p, 0, 0), Seed<11, 4>(pd, 0, 4), tj);
  for (int r = 0; r < 4; ++r) {
    (*acc)[r] = accj[r].a;
    for (int k = 0; k < 4; ++k) {
      (*acc_p)(r, k) = accj[r].v[k];
      (*acc_pd)(r, k) = accj[r].v[4 + k];
    }
    for (int k = 0; k < 3; ++k) (*acc_tau)(r, k) = accj[r].v[8 + k];
  }
}

/// Rows pp+1..pp+3 of D hold dτ/d(q or v) of segment ν's body torque over the window of columns
/// c0..c1 (at most 18: p_{ν−1}, x_ν, p_ν, x_{ν+1}, p_{ν+1}); replaces rows pp..pp+3 by
/// ∂p̈/∂τ · dτ plus the quaternion's own terms `own` (∂p̈/∂p or ∂p̈/∂ṗ).
void ChainTorqueRows(const kernels::M43& acc_tau, const kernels::M44& own, int pp, int c0, int c1,
                     BandedMatrix* D) {
  double window[3][18];
  for (int k = 0; k < 3; ++k)
    for (int c = c0; c <= c1; ++c) window[k][c - c0] = (*D)(pp + 1 + k, c);
  for (int r = 0; r < 4; ++r) {
    for (int c = c0; c <= c1; ++c) {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k) sum += acc_tau(r, k) * window[k][c - c0];
      (*D)(pp + r, c) = sum;
    }
    for (int k = 0; k < 4; ++k) (*D)(pp + r, pp + k) += own(r, k);
  }
}

}  // namespace

template <int kMode>
void QuatFdModel::AddSegmentForces(const Eigen::Ref<const Eigen::VectorXd>& q,
                                   const Eigen::Ref<const Eigen::VectorXd>& v,
                                   Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                                   BandedMatrix* dfdv) const {
  for (int i = 0; i < layout_.segments; ++i) {
    const int xa = L::X(i), xb = L::X(i + 1), pp = L::P(i);
    kernels::SegmentJacobian J;
    Vec3 fa, tau;
    if (kMode == kAnalytic) {
      kernels::SegmentForcesJacobian(segment_[i], Value<3>(q, xb) - Value<3>(q, xa),
                                     Value<4>(q, pp), Value<3>(v, xb) - Value<3>(v, xa),
                                     Value<4>(v, pp), &fa, &tau, &J);
    } else {
      SegmentForcesAutoDiff(segment_[i], q, v, xa, xb, pp, &fa, &tau, &J);
    }
    a.segment<3>(xa) += fa;
    a.segment<3>(xb) -= fa;
    a.segment<3>(pp + 1) += tau;
    // ∂/∂x_b = ∂/∂dx = −∂/∂x_a; the force on x_b is −force_a.
    AddRows(dfdq, xa, xb, J.fa_dx);
    AddRows(dfdq, xa, xa, -J.fa_dx);
    AddRows(dfdq, xa, pp, J.fa_p);
    AddRows(dfdv, xa, xb, J.fa_dv);
    AddRows(dfdv, xa, xa, -J.fa_dv);
    AddRows(dfdv, xa, pp, J.fa_pd);
    AddRows(dfdq, xb, xb, -J.fa_dx);
    AddRows(dfdq, xb, xa, J.fa_dx);
    AddRows(dfdq, xb, pp, -J.fa_p);
    AddRows(dfdv, xb, xb, -J.fa_dv);
    AddRows(dfdv, xb, xa, J.fa_dv);
    AddRows(dfdv, xb, pp, -J.fa_pd);
    AddRows(dfdq, pp + 1, xb, J.tau_dx);
    AddRows(dfdq, pp + 1, xa, -J.tau_dx);
    AddRows(dfdq, pp + 1, pp, J.tau_p);
    AddRows(dfdv, pp + 1, xb, J.tau_dv);
    AddRows(dfdv, pp + 1, xa, -J.tau_dv);
    AddRows(dfdv, pp + 1, pp, J.tau_pd);
  }
}

template <int kMode>
void QuatFdModel::AddBendTorques(const Eigen::Ref<const Eigen::VectorXd>& q,
                                 const Eigen::Ref<const Eigen::VectorXd>& v,
                                 Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                                 BandedMatrix* dfdv) const {
  // n = 0 is the base clamp's element (its p_a is the constant clamp quaternion), n = N the tip
  // clamp's (its p_b).
  const int N = layout_.segments;
  for (int n = 0; n <= N; ++n) {
    if (!bend_active_[n]) continue;
    const bool clamp = n == 0, tip_clamp = n == N;
    const int pa = clamp ? -1 : L::P(n - 1), pb = tip_clamp ? -1 : L::P(n);
    const Vec4 qa = clamp ? base_quat_ : Value<4>(q, pa);
    const Vec4 va = clamp ? Vec4::Zero() : Value<4>(v, pa);
    const Vec4 qb = tip_clamp ? tip_quat_ : Value<4>(q, pb);
    const Vec4 vb = tip_clamp ? Vec4::Zero() : Value<4>(v, pb);
    kernels::BendJacobian J;
    Vec3 ta, tb;
    if (kMode == kAnalytic)
      kernels::BendTorquesJacobian(bend_[n], qa, qb, va, vb, &ta, &tb, &J);
    else
      BendTorquesAutoDiff(bend_[n], qa, qb, va, vb, &ta, &tb, &J);
    if (tip_clamp) {
      a.segment<3>(pa + 1) += ta;
      AddRows(dfdq, pa + 1, pa, J.ta_pa);
      AddRows(dfdv, pa + 1, pa, J.ta_pda);
      continue;
    }
    a.segment<3>(pb + 1) += tb;
    AddRows(dfdq, pb + 1, pb, J.tb_pb);
    AddRows(dfdv, pb + 1, pb, J.tb_pdb);
    if (clamp) continue;
    a.segment<3>(pa + 1) += ta;
    AddRows(dfdq, pa + 1, pa, J.ta_pa);
    AddRows(dfdq, pa + 1, pb, J.ta_pb);
    AddRows(dfdv, pa + 1, pa, J.ta_pda);
    AddRows(dfdv, pa + 1, pb, J.ta_pdb);
    AddRows(dfdq, pb + 1, pa, J.tb_pa);
    AddRows(dfdv, pb + 1, pa, J.tb_pda);
  }
}

template <int kMode>
void QuatFdModel::AddLoads(const Eigen::Ref<const Eigen::VectorXd>& q,
                           Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq) const {
  // The distributed loads are constant; the tip loads depend on p_{N−1/2} (TipLoads).
  const int xt = L::X(layout_.segments), pl = L::P(layout_.segments - 1);
  Vec3 f, m;
  if (kMode == kAnalytic) {
    Eigen::Matrix<double, 3, 4> f_p, m_p;
    TipLoadsJacobian(Value<4>(q, pl), &f, &m, &f_p, &m_p);
    AddRows(dfdq, xt, pl, f_p);
    AddRows(dfdq, pl + 1, pl, m_p);
  } else {
    using Jt = Jet<4>;
    V3<Jt> fj, mj;
    TipLoads<Jt>(Seed<4, 4>(q, pl, 0), &fj, &mj);
    f = V3<double>(fj[0].a, fj[1].a, fj[2].a);
    m = V3<double>(mj[0].a, mj[1].a, mj[2].a);
    AddBlock<4>(fj, 0, 4, xt, pl, dfdq);
    AddBlock<4>(mj, 0, 4, pl + 1, pl, dfdq);
  }
  AddExternalLoads(f, m, a);
}

template <int kMode>
void QuatFdModel::AccelerateSegments(const Eigen::Ref<const Eigen::VectorXd>& q,
                                     const Eigen::Ref<const Eigen::VectorXd>& v, double alpha,
                                     double beta, Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq,
                                     BandedMatrix* dfdv) const {
  kernels::RotationConstants rc;
  rc.alpha = alpha;
  rc.beta = beta;
  for (int i = 0; i < layout_.segments; ++i) {
    const int pp = L::P(i);
    rc.inertia = rotation_[i].inertia;
    const Vec3 tau = a.segment<3>(pp + 1);
    Vec4 acc;
    kernels::M44 acc_p, acc_pd;
    kernels::M43 acc_tau;
    if (kMode == kAnalytic)
      kernels::QuaternionAccelerationJacobian(rc, Value<4>(q, pp), Value<4>(v, pp), tau, &acc,
                                              &acc_p, &acc_pd, &acc_tau);
    else
      QuaternionAccelerationAutoDiff(rc, Value<4>(q, pp), Value<4>(v, pp), tau, &acc, &acc_p,
                                     &acc_pd, &acc_tau);
    const int c0 = std::max(0, pp - 7), c1 = std::min(size() - 1, pp + 10);
    ChainTorqueRows(acc_tau, acc_p, pp, c0, c1, dfdq);
    ChainTorqueRows(acc_tau, acc_pd, pp, c0, c1, dfdv);
    a.segment<4>(pp) = acc;
  }
}

template <int kMode>
void QuatFdModel::Evaluate(const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                           Eigen::Ref<Eigen::VectorXd> a, BandedMatrix* dfdq, BandedMatrix* dfdv,
                           bool forces_only) const {
  // Part 1: generalised forces. x rows of `a` collect the vertex forces (N, world); rows
  // P(ν)+1..+3 collect the body torques of segment ν (N·m); the same rows of dfdq/dfdv collect
  // their derivatives.
  a.setZero();
  dfdq->SetZero();
  dfdv->SetZero();
  AddSegmentForces<kMode>(q, v, a, dfdq, dfdv);
  AddBendTorques<kMode>(q, v, a, dfdq, dfdv);
  AddLoads<kMode>(q, a, dfdq);
  if (motion_loads_) AddMotionLoads(q, v, a, dfdq, dfdv);
  if (forces_only) {
    ZeroFixedRows(a);
    return;
  }
  // Part 2: accelerations. Vertices: ẍ = M⁻¹ Q (prescribed: 0). Segments: p̈ from the torque.
  DivideVertexRowsByMass(q, a, dfdq, dfdv);
  AccelerateSegments<kMode>(q, v, alpha, beta, a, dfdq, dfdv);
}

template <int kMode>
void QuatFdModel::JacobianImpl(const Eigen::Ref<const Eigen::VectorXd>& q,
                               const Eigen::Ref<const Eigen::VectorXd>& v, double alpha,
                               double beta, BandedMatrix* dfdq, BandedMatrix* dfdv,
                               Eigen::VectorXd* a) const {
  const int n = size();
  if (dfdq->rows() != n || dfdq->lower() != L::kBandwidth || dfdq->upper() != L::kBandwidth)
    dfdq->Resize(n, L::kBandwidth, L::kBandwidth);
  if (dfdv->rows() != n || dfdv->lower() != L::kBandwidth || dfdv->upper() != L::kBandwidth)
    dfdv->Resize(n, L::kBandwidth, L::kBandwidth);
  if (a) {
    a->resize(n);
    Evaluate<kMode>(q, v, alpha, beta, *a, dfdq, dfdv, false);
  } else {
    Eigen::VectorXd tmp(n);
    Evaluate<kMode>(q, v, alpha, beta, tmp, dfdq, dfdv, false);
  }
}

void QuatFdModel::Jacobian(const Eigen::Ref<const Eigen::VectorXd>& q,
                           const Eigen::Ref<const Eigen::VectorXd>& v, double alpha, double beta,
                           BandedMatrix* dfdq, BandedMatrix* dfdv, Eigen::VectorXd* a) const {
  JacobianImpl<kAnalytic>(q, v, alpha, beta, dfdq, dfdv, a);
}

void QuatFdModel::JacobianAutoDiff(const Eigen::Ref<const Eigen::VectorXd>& q,
                                   const Eigen::Ref<const Eigen::VectorXd>& v, double alpha,
                                   double beta, BandedMatrix* dfdq, BandedMatrix* dfdv,
                                   Eigen::VectorXd* a) const {
  JacobianImpl<kAutoDiff>(q, v, alpha, beta, dfdq, dfdv, a);
}

}  // namespace cosserat::quatfd
