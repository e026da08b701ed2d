// One shot of the BDF2 shooting stepper: the Cosserat equations in s with the BDF2 rates of
// strain and twist (Till, Aloi & Rucker 2019, eqs. 14-29), integrated by the explicit spatial
// scheme (spatial_scheme.hpp) with the exact tangent of the discrete map. The solve that drives
// its residual to zero is in bdf2_stepper.cpp.
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "cosserat/constitutive/tendon_law.hpp"
#include "cosserat/lie/se3.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/frame_tangent.hpp"
#include "cosserat/strong/shot_tangent.hpp"

namespace cosserat {

namespace {

using Sample = Bdf2ShootingStepper::Sample;
using Coefficients = Bdf2ShootingStepper::Coefficients;
using namespace internal;
using internal::Axpy;  // the scheme on states (spatial_scheme.hpp)
using internal::HeunUpdate;
using internal::Rk4Midpoint;
using internal::Rk4Update;

#if defined(__GNUC__)
#define COSSERAT_HOT inline __attribute__((always_inline))
#define COSSERAT_COLD __attribute__((noinline))
#else
#define COSSERAT_HOT inline
#define COSSERAT_COLD
#endif

// Integration state in s and its tangent along the 6 unknowns (cosserat_rhs.hpp,
// shot_tangent.hpp): the scheme on (state, tangent) is the exact derivative of the discrete shot.
using DynState = rhs::DynamicPoint<double>;
using DynTangent = rhs::DynamicTangent;
static_assert(sizeof(DynState) == 24 * sizeof(double), "DynState must be 24 packed doubles");

// Tip condition (eq. 28, with a rigid tip body of mass m_t and inertia J_t at the tip):
//   W(L) = [M_B − J_t ω_t − ω × J_t ω;  F_B − m_t (v_t + ω × v)]   (body frame),
// where [M_B; F_B] is the loads' tip wrench on the section and the body (its weight included,
// and a drill bit's friction torque about body z at the tip's spin ω_z),
// made dimensionless by scale. V_t is the BDF2 rate of the tip twist (zero in statics).
Vec6 TipResidual(const DynState& y, const StaticLoads& loads, const Bdf2Options& opt,
                 const Vec6& V_t, const Vec6& scale) {
  const Mat3 Rt = y.R.transpose();
  const Vec6 applied = TipWrenchInBody(TotalTipWrench(loads, opt.tip_mass), y.R);
  Vec3 M = applied.head<3>(), F = applied.tail<3>();
  if (loads.bit.present()) M.z() += loads.bit.Torque(y.w.z());  // a drill bit's friction
  if (opt.tip_mass > 0 || opt.tip_inertia_B.any()) {
    const Vec3 Jw = opt.tip_inertia_B.cwiseProduct(y.w);
    M -= opt.tip_inertia_B.cwiseProduct(V_t.head<3>()) + y.w.cross(Jw);
    F -= opt.tip_mass * (V_t.tail<3>() + y.w.cross(y.v));
  }
  Vec6 r;
  r << y.m - M, Rt * y.n - F;
  return r.cwiseQuotient(scale);
}

// A held tip (TipHold): position rows (p − p_h)/L, and rotation rows that vanish when the tip's
// frame R is the holder's R_h, ≈ θ for R = R_h Exp(θ):
//   θx ≈ −(R e₃)·(R_h e₂),  θy ≈ (R e₃)·(R_h e₁),  θz ≈ −(R e₂)·(R_h e₁);
// a joint that leaves a rotation free asks instead for no moment about it (the moment over its
// scale, body frame). Dot products of frame columns keep the exact Jacobian simple.
// A guided tip (a column's) slides along e = R_h e₃: rows across it, R_h e₁,₂ · (p − p_h)/L,
// and along it the force e · (n_W − F) over its scale, F the loads' dead tip force.
Vec6 HeldTipResidual(const DynState& y, const StepInput& in, double length, const Vec6& scale) {
  const Mat3& Rh = in.tip_pose.R;
  Vec6 r;
  r.tail<3>() = (y.p - in.tip_pose.p) / length;
  r(0) = -y.R.col(2).dot(Rh.col(1));
  r(1) = y.R.col(2).dot(Rh.col(0));
  r(2) = -y.R.col(1).dot(Rh.col(0));
  if (in.tip_hold == TipHold::kPinned || in.tip_hold == TipHold::kGuidedPinned)
    r.head<3>() = y.m.cwiseQuotient(scale.head<3>());
  if (in.tip_hold == TipHold::kTorsionFree) r(2) = y.m.z() / scale(2);
  if (in.tip_hold == TipHold::kGuidedClamped || in.tip_hold == TipHold::kGuidedPinned) {
    const Vec3 d = y.p - in.tip_pose.p;
    r(3) = Rh.col(0).dot(d) / length;
    r(4) = Rh.col(1).dot(d) / length;
    r(5) = Rh.col(2).dot(y.n - in.loads.tip_force) / scale(5);
  }
  return r;
}

DynTangent Axpy(const DynTangent& y, double a, const DynTangent& d) {
  return {y.p + a * d.p, {y.R[0] + a * d.R[0], y.R[1] + a * d.R[1], y.R[2] + a * d.R[2]},
          y.m + a * d.m, y.n + a * d.n,
          y.w + a * d.w, y.v + a * d.v};
}

template <int S>
void RkUpdate(double h, const double (&b)[4], const DynTangent (&k)[S], DynTangent* y) {
  for (int j = 0; j < S; ++j) {
    const double a = h * b[j];
    y->p += a * k[j].p;
    for (int c = 0; c < 3; ++c) y->R[c] += a * k[j].R[c];
    y->m += a * k[j].m;
    y->n += a * k[j].n;
    y->w += a * k[j].w;
    y->v += a * k[j].v;
  }
}

}  // namespace

void Bdf2ShootingStepper::PrepareHistory(const Coefficients& c) {
  if (history_ready_ && c.c0 == history_c_.c0 && c.c2 == history_c_.c2) return;
  // Written so that a constant history gives exactly zero rates:
  // ξ_t = c0 ξ + ξʰ with ξʰ = c2 (ξ₂ − ξ₁) − c0 ξ₁ (c1 = −c0 − c2), likewise for V. Each
  // std::vector of fixed-size vectors is one contiguous array of doubles: one vectorised
  // expression per quantity (element-wise loops over Vec6 were ~8 % of a Heun step).
  auto history = [&](auto& out, const auto& older, const auto& old) {
    using V = typename std::decay_t<decltype(out)>::value_type;
    const Eigen::Index size = static_cast<Eigen::Index>(out.size()) * V::SizeAtCompileTime;
    using Array = Eigen::Map<Eigen::ArrayXd>;
    using ConstArray = Eigen::Map<const Eigen::ArrayXd>;
    const ConstArray a(older.front().data(), size), b(old.front().data(), size);
    Array(out.front().data(), size) = c.c2 * (a - b) - c.c0 * b;
  };
  history(strain_h_, run_.strain2, run_.strain1);
  history(twist_h_, run_.twist2, run_.twist1);
  history(velocity_W_h_, run_.velocity_W2, run_.velocity_W1);
  history_c_ = c;
  history_ready_ = true;
}

// One shot in progress (Residual): the end condition at s = 0, the stages segment by segment with
// the tangent along the unknowns, and the tip condition. The state and its tangent are locals of
// Segments(), where the compiler can keep them in registers.
class Bdf2ShootingStepper::Shot {
 public:
  Shot(Bdf2ShootingStepper* stepper, const StepInput& in, const Coefficients& c, bool statics,
       bool tangent)
      : st_(*stepper),
        in_(in),
        c_(c),
        statics_(statics),
        tangent_(tangent),
        guess_(stepper->samples_.front().rest_strain),
        shot_this_step_(stepper->stage_strains_current_),
        motion_(HasMotionLoads(in.loads)),
        added_mass_(in.loads.fluid.has_added_mass()) {
    if (tangent_)
      for (Mat36* t : {&dy_.p, &dy_.R[0], &dy_.R[1], &dy_.R[2], &dy_.m, &dy_.n, &dy_.w, &dy_.v})
        t->setZero();
  }

  // Cantilever (eq. 28): pose and twist of the base given, the unknown is W(0) = scale ⊙ x.
  void StartCantilever(const Vec6& x) {
    const Vec6 W0 = st_.scale_.cwiseProduct(x);
    st_.base_now_ = in_.base_pose;
    y_.m = W0.head<3>();
    y_.n = st_.base_now_.R * W0.tail<3>();
    y_.w = statics_ ? Vec3::Zero() : Vec3(in_.base_twist_B.head<3>());
    y_.v = statics_ ? Vec3::Zero() : Vec3(in_.base_twist_B.tail<3>());
    if (tangent_) {
      dy_.m.leftCols<3>() = st_.scale_.head<3>().asDiagonal();
      dy_.n.rightCols<3>() = st_.base_now_.R * st_.scale_.tail<3>().asDiagonal();
    }
    y_.p = st_.base_now_.p;
    y_.R = st_.base_now_.R;
  }

  // Free-free (eq. 29): W(0) = −applied wrench, the unknown is V(0) = twist_scale ⊙ x. The base
  // pose follows from BDF2 on the group in coordinates at g₁: g = g₁ Exp(ξ) with
  // ξ̇ = J_r(ξ)⁻¹ V, so c0 ξ + c2 ξ_back = J_r(ξ)⁻¹ V(0), solved by fixed point (ξ = O(dt),
  // contraction O(dt)).
  void StartFreeFree(const Vec6& x) {
    const Vec6 V0 = statics_ ? Vec6::Zero() : Vec6(st_.twist_scale_.cwiseProduct(x));
    Vec6 xi = Vec6::Zero();
    if (!statics_) {
      for (int k = 0; k < 4; ++k)
        xi = (lie::SE3RightJacobianInverse(xi) * V0 - c_.c2 * st_.xi_back_) / c_.c0;
    }
    const lie::SE3& base = st_.base_now_ = lie::Compose(st_.run_.base1, lie::SE3Exp(xi));
    y_.m = -in_.base_wrench_B.head<3>();
    y_.n = base.R * -in_.base_wrench_B.tail<3>();
    y_.w = V0.head<3>();
    y_.v = V0.tail<3>();
    if (tangent_ && !statics_) {
      // d g(0) = g(0) Exp(τ) with τ = J_r(ξ) dξ ≈ dV(0) / c0 (dropping the O(dt) change of J_r).
      const Mat6 tau = st_.twist_scale_.asDiagonal() * (1.0 / c_.c0);
      const Mat36 tau_w = tau.topRows<3>(), tau_v = tau.bottomRows<3>();
      dy_.w.leftCols<3>() = st_.twist_scale_.head<3>().asDiagonal();
      dy_.v.rightCols<3>() = st_.twist_scale_.tail<3>().asDiagonal();
      dy_.p = base.R * tau_v;
      for (int j = 0; j < 3; ++j) dy_.R[j] = base.R * CrossUnit(tau_w, j);  // R (τ_ω × e_j)
      dy_.n = RotateTangent(base.R, dy_.R, -in_.base_wrench_B.tail<3>(), Mat36::Zero());
    }
    y_.p = base.p;
    y_.R = base.R;
  }

  // Segments(first, last) compiled for the scheme and for whether some load depends on the
  // state.
  void RunSegments(int first = 0, int last = -1) {
    const SpatialScheme scheme = st_.options_.spatial_scheme;
    if (motion_ || added_mass_) {
      if (scheme == SpatialScheme::kHeun)
        Segments<SpatialScheme::kHeun, true>(first, last);
      else if (scheme == SpatialScheme::kRk4Pairs)
        PairSegments<true>(first, last);
      else
        Segments<SpatialScheme::kRk4, true>(first, last);
    } else if (scheme == SpatialScheme::kHeun) {
      Segments<SpatialScheme::kHeun, false>(first, last);
    } else if (scheme == SpatialScheme::kRk4Pairs) {
      PairSegments<false>(first, last);
    } else {
      Segments<SpatialScheme::kRk4, false>(first, last);
    }
  }

  // Multiple shooting, a piece alone: start from the restart state of junction k.
  void StartAtJunction(int k) { y_ = st_.JunctionRestart<DynState>(k); }
  // ... and end at junction k: its mismatch against its restart state.
  void EndAtJunction(int k) { st_.RecordJunctionMismatch(k, y_, st_.JunctionRestart<DynState>(k)); }

  // The first junction a run of segments from node `first` crosses (those strictly after it).
  size_t FirstJunctionAfter(int first) const {
    size_t k = 0;
    while (k < st_.junction_nodes_.size() && st_.junction_nodes_[k] <= first) ++k;
    return k;
  }
  // At node i: restart the shot if junction *next sits there, and move on to the next one.
  COSSERAT_HOT void CrossJunction(int i, size_t* next, DynState* y) {
    if (st_.junctions_active_ && *next < st_.junction_nodes_.size() &&
        i == st_.junction_nodes_[*next])
      st_.ApplyJunction(static_cast<int>((*next)++), y);
  }

  // Segment by segment with the explicit scheme's S stages (spatial_scheme.hpp), written out
  // per scheme: a loop over stage arrays made the RK4 shot ~25 % slower.
  // kStateLoads: some load depends on the state (drag, added mass); compiled apart, so the plain
  // shot stays as lean.
  // The segments from node `first` to node `last` (all of them by default); the junctions
  // strictly after `first` restart the shot.
  template <SpatialScheme kScheme, bool kStateLoads>
  void Segments(int first = 0, int last = -1) {
    constexpr int S = Table(kScheme).stages;
    if (last < 0) last = static_cast<int>(st_.grid_.size()) - 1;
    DynState y = y_;
    size_t next_junction = FirstJunctionAfter(first);
    // Every segment from `first` on is a step of S stages here (a plain scheme, or one segment
    // alone of kRk4Pairs).
    const int q_first = st_.step_slot_[first];
    for (int i = first; i < last; ++i) {
      CrossJunction(i, &next_junction, &y);
      const double h = st_.grid_[i + 1] - st_.grid_[i];
      const int q = q_first + S * (i - first);
      const int smp = 3 * i;
      const DynState k1 = Stage<kStateLoads>(q, 0, smp, y);
      RecordNode(i, y, st_.strain_now_[q]);
      if constexpr (S == 4) {
        const DynState y2 = Axpy(y, 0.5 * h, k1);
        const DynState k2 = Stage<kStateLoads>(q + 1, 1, smp + 1, y2);
        const DynState y3 = Axpy(y, 0.5 * h, k2);
        const DynState k3 = Stage<kStateLoads>(q + 2, 2, smp + 1, y3);
        const DynState y4 = Axpy(y, h, k3);
        const DynState k4 = Stage<kStateLoads>(q + 3, 3, smp + 2, y4);
        if (tangent_) Propagate<kScheme, kStateLoads>({&y, &y2, &y3, &y4}, q, smp, h);
        Rk4Update(h, k1, k2, k3, k4, &y);
      } else {
        const DynState y2 = Axpy(y, h, k1);
        const DynState k2 = Stage<kStateLoads>(q + 1, 1, smp + 2, y2);
        if (tangent_) Propagate<kScheme, kStateLoads>({&y, &y2}, q, smp, h);
        HeunUpdate(h, k1, k2, &y);
      }
    }
    y_ = y;
  }

  // kRk4Pairs: one RK4 step over each pair of segments (the node between from the step's
  // dense output), and a plain RK4 step on a segment without a partner. Apart from Segments so
  // that each keeps its stages inlined (together they made the shot ~10 % slower).
  template <bool kStateLoads>
  void PairSegments(int first = 0, int last = -1) {
    constexpr const SchemeTable& T = Table(SpatialScheme::kRk4Pairs);
    if (last < 0) last = static_cast<int>(st_.grid_.size()) - 1;
    DynState y = y_;
    size_t next_junction = FirstJunctionAfter(first);
    for (int i = first; i < last;) {
      CrossJunction(i, &next_junction, &y);
      // A pair never straddles `last`: junctions sit only where a step starts.
      if (!st_.pair_start_[i]) {
        y_ = y;
        SingleSegment<kStateLoads>(i);
        y = y_;
        ++i;
        continue;
      }
      const double H = st_.grid_[i + 2] - st_.grid_[i];
      const int q = st_.step_slot_[i];
      const int smp = 3 * i;
      const DynState k1 = Stage<kStateLoads>(q, 0, smp, y);
      RecordNode(i, y, st_.strain_now_[q]);
      const DynState y2 = Axpy(y, 0.5 * H, k1);
      const DynState k2 = Stage<kStateLoads>(q + 1, 1, smp + T.sample[1], y2);
      const DynState y3 = Axpy(y, 0.5 * H, k2);
      const DynState k3 = Stage<kStateLoads>(q + 2, 2, smp + T.sample[2], y3);
      const DynState y4 = Axpy(y, H, k3);
      const DynState k4 = Stage<kStateLoads>(q + 3, 3, smp + T.sample[3], y4);
      if (tangent_)
        Propagate<SpatialScheme::kRk4Pairs, kStateLoads>({&y, &y2, &y3, &y4}, q, smp, H);
      RecordSteppedOverNode(i + 1, q + 1, smp + T.sample[1], Rk4Midpoint(H, y, k1, k2, k3, k4));
      Rk4Update(H, k1, k2, k3, k4, &y);
      i += 2;
    }
    y_ = y;
  }

  // A plain RK4 step on segment i from y_ (kRk4Pairs' unpaired segments), kept out of line.
  template <bool kStateLoads>
  COSSERAT_COLD void SingleSegment(int i) {
    Segments<SpatialScheme::kRk4, kStateLoads>(i, i + 1);
  }

  // The tip node (its strain from the last stage's section with the final wrench, and a history
  // of its own: the last stage sits at y + h k_{S−1}, not at the tip), then the tip condition
  // and, with J, its exact derivative.
  Vec6 Finish(Mat6* J) {
    const int n = static_cast<int>(st_.grid_.size());
    const RunningState& run = st_.run_;
    Vec6 W_tip;
    W_tip << y_.m, y_.R.transpose() * y_.n;
    const int q_tip = 3 * (n - 2) + 2;
    const Sample& s_tip = st_.samples_[q_tip];
    Vec6 xi_h_tip = Vec6::Zero(), V_h_tip = Vec6::Zero();
    if (!statics_) {
      xi_h_tip = c_.c2 * (run.tip_strain2 - run.tip_strain1) - c_.c0 * run.tip_strain1;
      V_h_tip = c_.c2 * (run.tip_twist2 - run.tip_twist1) - c_.c0 * run.tip_twist1;
    }
    Vec6 xi_tip = statics_
                      ? Vec6(s_tip.rest_strain + s_tip.compliance.cwiseProduct(W_tip))
                      : Vec6(s_tip.implicit_offset + s_tip.implicit_compliance.cwiseProduct(W_tip) -
                             s_tip.implicit_damping.cwiseProduct(xi_h_tip));
    if (!st_.tendons_.empty()) xi_tip = TendonStrain(q_tip, guess_, xi_h_tip, W_tip, nullptr);
    RecordNode(n - 1, y_, xi_tip);
    st_.stage_strains_current_ = !statics_;
    st_.tip_strain_now_ = xi_tip;
    st_.tip_twist_now_ << y_.w, y_.v;
    Vec6 V_t_tip = Vec6::Zero();  // BDF2 rate of the tip twist
    if (!statics_) {
      V_t_tip << c_.c0 * y_.w, c_.c0 * y_.v;
      V_t_tip += V_h_tip;
    }
    if (in_.tip_hold != TipHold::kFree) {
      if (J) *J = HeldTipJacobian();
      return HeldTipResidual(y_, in_, st_.model_.length, st_.scale_);
    }
    if (J) *J = TipJacobian();
    return TipResidual(y_, in_.loads, st_.options_, V_t_tip, st_.scale_);
  }

 private:
  using RunningState = Bdf2ShootingStepper::Snapshot;

  Vec3 DistributedForce(const Sample& smp) const {
    return TotalDistributedForce_W(in_.loads, smp.Site());
  }

  // Inlined into the segment loop (out of line it cost ~5 % of a Heun shot).
  COSSERAT_HOT void RecordNode(int i, const DynState& y, const Vec6& xi) {
    RodState& trial = st_.trial_;
    trial.position_W[i] = y.p;
    trial.rotation_WB[i] = y.R;
    trial.wrench_B[i].head<3>() = y.m;
    trial.wrench_B[i].tail<3>() = rhs::RotateToBody(y.R, y.n);
    trial.twist_B[i].head<3>() = y.w;
    trial.twist_B[i].tail<3>() = y.v;
    trial.strain[i] = xi;
  }

  // A node the shot steps over (kRk4Pairs): its state y interpolated, its strain from the
  // section law at `sample_index` with the history of stage q (the stage on that node).
  COSSERAT_HOT void RecordSteppedOverNode(int i, int q, int sample_index, const DynState& y) {
    const Sample& smp = st_.samples_[sample_index];
    Vec6 W;
    W << y.m, rhs::RotateToBody(y.R, y.n);
    const Vec6& xh = statics_ ? zero6_ : st_.strain_h_[q];
    if (!st_.tendons_.empty())
      RecordNode(i, y, TendonStrain(sample_index, StageGuess(q), xh, W, nullptr));
    else if (statics_)
      RecordNode(i, y, smp.rest_strain + smp.compliance.cwiseProduct(W));
    else
      RecordNode(i, y,
                 smp.implicit_offset + smp.implicit_compliance.cwiseProduct(W) -
                     smp.implicit_damping.cwiseProduct(xh));
  }

  // In dynamics a stage's strain moves little between shots and steps: the best first guess for
  // the tendon law is its value in the last shot of this step, or at the last step (about 3
  // simplified-Newton iterations per stage from the neighbouring stage's strain, 2 from these).
  const Vec6& StageGuess(int q) const {
    if (statics_) return guess_;
    const Vec6& last = shot_this_step_ ? st_.strain_now_[q] : st_.run_.strain1[q];
    return last.allFinite() ? last : guess_;
  }

  // With tendons: the strain of K (ξ − ξ*) + D ξ_t + Σ τ a(ξ) = W (tendon_law.hpp) at a sample,
  // written as K' (ξ − ξ') + Σ τ a(ξ) = W with K' = K + c0 D, ξ' = its offset; from `start`.
  Vec6 TendonStrain(int sample_index, const Vec6& start, const Vec6& xi_h, const Vec6& W, Mat6* H) {
    const Sample& smp = st_.samples_[sample_index];
    Mat6 K = Mat6::Zero();
    Vec6 offset;
    if (statics_) {
      K.diagonal() = smp.stiffness;
      offset = smp.rest_strain;
    } else {
      K.diagonal() = smp.stiffness + c_.c0 * smp.damping;  // the implicit stiffness K + c0 D
      offset = smp.implicit_offset - smp.implicit_damping.cwiseProduct(xi_h);
    }
    Vec6 xi = start;
    if (!SolveTendonStrain(K, offset, st_.tendons_[sample_index],
                           st_.actuation_.tendon_tension.data(), W, &xi, H))
      xi.setConstant(NAN);
    guess_ = xi;
    return xi;
  }

  // Stage j of a step, kept in slot q, at state ys: record it for the history and return its
  // derivative.
  template <bool kStateLoads>
  COSSERAT_HOT DynState Stage(int q, int j, int sample_index, const DynState& ys) {
    const Sample& smp = st_.samples_[sample_index];
    const Vec6& xh = statics_ ? zero6_ : st_.strain_h_[q];  // history terms ξʰ, Vʰ
    const Vec6& Vh = statics_ ? zero6_ : st_.twist_h_[q];
    st_.position_now_[q] = ys.p;
    std::memcpy(st_.rotation_now_[q].data(), ys.R.data(), sizeof(Mat3));  // inlined: 72 bytes
    Vec6 given;
    if (!st_.tendons_.empty()) {
      Vec6 W;
      W << ys.m, ys.R.transpose() * ys.n;
      given = TendonStrain(sample_index, StageGuess(q), xh, W, tangent_ ? &H_stage_[j] : nullptr);
    }
    const rhs::StageHistory history{&xh, &Vh, statics_ ? &zero3_ : &st_.velocity_W_h_[q], c_.c0,
                                    statics_};
    const Vec6* strain = st_.tendons_.empty() ? nullptr : &given;
    if constexpr (!kStateLoads) {
      return rhs::DynamicDerivative<double>(smp, DistributedForce(smp), ys, history,
                                            &st_.strain_now_[q], &st_.twist_now_[q],
                                            &st_.velocity_W_now_[q], strain);
    } else {
      Vec3 f = DistributedForce(smp);
      if (motion_) {
        // Loads that depend on the motion (drag): at this stage's pose and velocity.
        const SectionMotion at{ys.p, ys.R.col(2), ys.R * ys.v};
        f += TotalMotionForce_W(in_.loads, smp.Site(), at,
                                tangent_ ? &motion_jacobian_[j] : nullptr);
      }
      const double added = added_mass_ ? TotalNormalAddedMass(in_.loads, smp.Site()) : 0.0;
      stage_added_mass_[j] = added;
      return rhs::DynamicDerivative<double>(smp, f, ys, history, &st_.strain_now_[q],
                                            &st_.twist_now_[q], &st_.velocity_W_now_[q], strain,
                                            added);
    }
  }

  // The tangent dy through the stages ys of the step from node i (the exact derivative of the
  // shot).
  template <SpatialScheme kScheme, bool kStateLoads, int S = Table(kScheme).stages>
  void Propagate(const std::array<const DynState*, S>& ys, int q, int smp, double h) {
    constexpr const SchemeTable& T = Table(kScheme);
    DynTangent dk[S];
    for (int j = 0; j < S; ++j) {
      DynTangent stage;
      if (j > 0) stage = Axpy(dy_, T.step[j] * h, dk[j - 1]);
      const DynTangent& dyj = j == 0 ? dy_ : stage;
      const Sample& sample = st_.samples_[smp + T.sample[j]];
      rhs::StageLoadTangent loads;
      if constexpr (kStateLoads) LoadTangent(j, q + j, *ys[j], dyj, &loads);
      dk[j] = rhs::DynamicTangentDerivative(sample, *ys[j], dyj, st_.strain_now_[q + j], c_.c0,
                                            statics_, st_.tendons_.empty() ? nullptr : &H_stage_[j],
                                            kStateLoads ? &loads : nullptr);
    }
    RkUpdate<S>(h, T.weight, dk, &dy_);
  }

  // What the state-dependent loads add to stage j's tangent (stage index q): the drag's
  // derivative along dy, d f = ∂f/∂p dp + ∂f/∂t d(R e₃) + ∂f/∂v d(R v), and the added mass.
  void LoadTangent(int j, int q, const DynState& y, const DynTangent& dy,
                   rhs::StageLoadTangent* out) const {
    if (motion_) {
      const MotionJacobian& mj = motion_jacobian_[j];
      out->force_W = mj.position * dy.p + mj.tangent * dy.R[2] +
                     mj.velocity * RotateTangent(y.R, dy.R, y.v, dy.v);
    }
    if (added_mass_ && !statics_) {
      out->added_mass = stage_added_mass_[j];  // as the stage's primal used it
      out->acceleration_W = c_.c0 * st_.velocity_W_now_[q] + st_.velocity_W_h_[q];
    }
  }

  // d r / d x of HeldTipResidual: the columns of R and the moment along the tangent.
  Mat6 HeldTipJacobian() const {
    const Mat3& Rh = in_.tip_pose.R;
    const Vec6& scale = st_.scale_;
    Mat6 J;
    J.bottomRows<3>() = dy_.p / st_.model_.length;
    J.row(0) = -Rh.col(1).transpose() * dy_.R[2];
    J.row(1) = Rh.col(0).transpose() * dy_.R[2];
    J.row(2) = -Rh.col(0).transpose() * dy_.R[1];
    const TipHold hold = in_.tip_hold;
    if (hold == TipHold::kPinned || hold == TipHold::kGuidedPinned)
      J.topRows<3>() = scale.head<3>().cwiseInverse().asDiagonal() * dy_.m;
    if (hold == TipHold::kTorsionFree) J.row(2) = dy_.m.row(2) / scale(2);
    if (hold == TipHold::kGuidedClamped || hold == TipHold::kGuidedPinned) {
      J.row(3) = Rh.col(0).transpose() * dy_.p / st_.model_.length;
      J.row(4) = Rh.col(1).transpose() * dy_.p / st_.model_.length;
      J.row(5) = Rh.col(2).transpose() * dy_.n / scale(5);  // n is n_W
    }
    return J;
  }

  // d r / d x from the tangent at the tip: the section's wrench, the dead part of the applied
  // tip wrench turning with the tip (the tip body's weight included), the tip body's inertia.
  Mat6 TipJacobian() const {
    const Bdf2Options& opt = st_.options_;
    Mat6 J;
    J.topRows<3>() = dy_.m;
    J.bottomRows<3>() = y_.R.transpose() * dy_.n + TransposeTimesFixed(dy_.R, y_.n);
    const SplitWrench tip = TotalTipWrench(in_.loads, opt.tip_mass);
    J.topRows<3>() -= TransposeTimesFixed(dy_.R, Vec3(tip.dead_W.head<3>()));
    J.bottomRows<3>() -= TransposeTimesFixed(dy_.R, Vec3(tip.dead_W.tail<3>()));
    if (in_.loads.bit.present()) {
      double dtorque;
      in_.loads.bit.Torque(y_.w.z(), &dtorque);
      J.row(2) -= dtorque * dy_.w.row(2);
    }
    const double rate = statics_ ? 0.0 : c_.c0;
    const Vec3& Jt = opt.tip_inertia_B;
    const double mt = opt.tip_mass;
    if (mt > 0 || Jt.any()) {
      const Mat36 Jt_dw = Jt.asDiagonal() * dy_.w;
      J.topRows<3>() +=
          rate * Jt_dw + Cross(dy_.w, Vec3(Jt.cwiseProduct(y_.w))) + Cross(y_.w, Jt_dw);
      J.bottomRows<3>() += mt * (rate * dy_.v + Cross(dy_.w, y_.v) + Cross(y_.w, dy_.v));
    }
    return st_.scale_.cwiseInverse().asDiagonal() * J;
  }

  Bdf2ShootingStepper& st_;
  const StepInput& in_;
  const Coefficients& c_;
  const bool statics_;
  const bool tangent_;
  DynState y_;
  DynTangent dy_;
  Vec6 guess_;  // the tendon law's first guess: the last stage's strain
  Mat6 H_stage_[4];
  const bool shot_this_step_;
  const bool motion_;                  // some load depends on the motion (drag)
  const bool added_mass_;              // the fluid adds mass
  MotionJacobian motion_jacobian_[4];  // of the current segment's stages
  double stage_added_mass_[4] = {};    // kg/m, of the current segment's stages
  const Vec6 zero6_ = Vec6::Zero();
  const Vec3 zero3_ = Vec3::Zero();
};

Vec6 Bdf2ShootingStepper::Residual(const StepInput& in, const Coefficients& c, bool statics,
                                   const Vec6& x, Mat6* J) {
  Shot shot(this, in, c, statics, J != nullptr);
  if (options_.ends == EndConditions::kFreeFree)
    shot.StartFreeFree(x);
  else
    shot.StartCantilever(x);
  if (!statics) PrepareHistory(c);
  shot.RunSegments();
  return shot.Finish(J);
}

Vec6 Bdf2ShootingStepper::ShootPiece(const StepInput& in, const Coefficients& c, bool statics,
                                     int piece, const Vec6& x) {
  Shot shot(this, in, c, statics, false);
  const int junctions = static_cast<int>(junction_nodes_.size());
  const int first = piece == 0 ? 0 : junction_nodes_[piece - 1];
  const int last = piece < junctions ? junction_nodes_[piece] : static_cast<int>(grid_.size()) - 1;
  if (piece > 0)
    shot.StartAtJunction(piece - 1);
  else if (options_.ends == EndConditions::kFreeFree)
    shot.StartFreeFree(x);
  else
    shot.StartCantilever(x);
  if (!statics) PrepareHistory(c);
  shot.RunSegments(first, last);
  if (piece < junctions) {
    shot.EndAtJunction(piece);
    return Vec6::Zero();
  }
  return shot.Finish(nullptr);
}

}  // namespace cosserat
