// The read-outs of a quaternion-FD state: projection onto |p| = 1, the constraint violation, mass,
// the RodState (poses, strains, wrenches, twists at the vertices) and the energy.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosserat/lie/quaternion.hpp"
#include "cosserat/loads/contact.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/quatfd/quatfd_kernels.hpp"
#include "cosserat/quatfd/quatfd_model.hpp"

namespace cosserat::quatfd {
namespace {

using L = QuatFdLayout;

/// The parabola P(ξ) = A + ξ c e + 4 d ξ(1 − ξ) n, ξ ∈ [0, 1], has the arc length
/// (c / 2k) [F(k) − F(k (1 − 2ξ))] from its start, k = 4d/c, F(u) = (u sqrt(1 + u²) + asinh u)/2;
/// in all (c/2) (sqrt(1 + k²) + asinh(k)/k).
double ParabolaF(double u) { return 0.5 * (u * std::sqrt(1 + u * u) + std::asinh(u)); }
double ParabolaArc(double c, double k, double xi) {
  return k == 0.0 ? c * xi : c / (2 * k) * (ParabolaF(k) - ParabolaF(k * (1 - 2 * xi)));
}

/// Bisection of a monotone increasing g on [lo, hi] for g(x) = target, to round-off.
template <typename G>
double Invert(const G& g, double target, double lo, double hi) {
  for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The plane in which a rod held at A and B hangs: up (against gravity, unit), u (horizontal,
/// unit, towards B), the rise h of B over A along up and its run l along u (m).
struct HangingPlane {
  Vec3 up, u;
  double h, l;
};

/// The inextensible catenary of length L through the rise h and run l of a plane (Irvine 1981,
/// ch. 1): y = a cosh((x − x0)/a) + C with L² − h² = (2a sinh(l/2a))²; sinh(−x0/a) is its slope
/// at the start.
struct CatenaryParameters {
  double a, x0, sinh_start;
};
CatenaryParameters Catenary(const HangingPlane& p, double L) {
  const double target = std::sqrt(L * L - p.h * p.h);
  const auto span = [&](double a) { return 2 * a * std::sinh(p.l / (2 * a)); };  // falls with a
  double hi = p.l;
  while (span(hi) > target) hi *= 2.0;
  const double a = Invert([&](double y) { return -span(y); }, -target, p.l / 1400.0, hi);
  const double x0 =
      -a * (std::log(L + p.h) - std::log(a) - p.l / a - std::log1p(-std::exp(-p.l / a)));
  return {a, x0, std::sinh(-x0 / a)};
}

/// That catenary from A at the arc lengths s.
void CatenaryPositions(const Vec3& A, const HangingPlane& p, double L, const std::vector<double>& s,
                       std::vector<Vec3>* x) {
  const CatenaryParameters c = Catenary(p, L);
  const double ya = c.a * std::cosh(-c.x0 / c.a);
  for (size_t v = 0; v < s.size(); ++v) {
    const double xv = c.x0 + c.a * std::asinh(s[v] / c.a + c.sinh_start);
    (*x)[v] = A + xv * p.u + (c.a * std::cosh((xv - c.x0) / c.a) - ya) * p.up;
  }
}

/// The mean tension of that catenary over its distributed load w (N/m), in m: its tension at s
/// is w a sqrt(1 + (s/a + sinh(−x0/a))²).
double CatenaryMeanTensionOverLoad(const HangingPlane& p, double L) {
  const CatenaryParameters c = Catenary(p, L);
  const int samples = 64;
  double sum = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double s = (k + 0.5) / samples * L;
    sum += c.a * std::hypot(1.0, s / c.a + c.sinh_start);
  }
  return sum / samples;
}

/// A line of length L from A lying on a bed (normal up) towards B, then rising to B as a catenary
/// with zero slope at touchdown: suspended length Ls = sqrt(h² + 2ah), run
/// L − Ls + a asinh(Ls/a) = l. False when no such shape exists (B is too far for a grounded part,
/// or too close for the line to leave the bed).
bool GroundedCatenaryPositions(const Vec3& A, const HangingPlane& p, double L,
                               const std::vector<double>& s, std::vector<Vec3>* x) {
  if (p.h <= 0 || L <= p.h) return false;
  const auto suspended = [&](double a) { return std::sqrt(p.h * p.h + 2 * a * p.h); };
  const auto run = [&](double a) { return L - suspended(a) + a * std::asinh(suspended(a) / a); };
  const double a_max = (L * L - p.h * p.h) / (2 * p.h);  // all of the line suspended
  if (p.l <= run(1e-9 * L) || p.l >= run(a_max)) return false;
  const double a = Invert(run, p.l, 1e-9 * L, a_max);
  const double grounded = L - suspended(a);
  for (size_t v = 0; v < s.size(); ++v) {
    const double sigma = std::max(0.0, s[v] - grounded);
    (*x)[v] = A + (std::min(s[v], grounded) + a * std::asinh(sigma / a)) * p.u +
              (std::hypot(a, sigma) - a) * p.up;
  }
  return true;
}

/// The part of a line laid on a bed (GroundedCatenaryPositions: at A's height along `up`) sunk to
/// where the bed's penalty k φ(δ) carries its net weight w (N/m): δ = w/k + ε/2 past the
/// smoothing ramp, sqrt(2 ε w/k) within it (contact.hpp). On the surface itself, with no
/// penetration, the line would meet no contact stiffness: its grounded part is then held only by
/// bending, and Newton's first steps run kilometres through the bed. The ends (held) stay; a bed
/// without stiffness is left alone.
void SinkOntoBed(const ContactSurface& bed, const Vec3& A, const Vec3& up, double w,
                 const std::vector<double>& diameter, std::vector<Vec3>* x) {
  if (!(bed.stiffness > 0.0)) return;
  const double length_scale = ((*x).back() - A).norm();
  const double settle = w / bed.stiffness;  // k φ(δ) = w: φ(δ) = w/k, m
  for (size_t v = 1; v + 1 < x->size(); ++v) {
    if (((*x)[v] - A).dot(up) > 1e-9 * length_scale) continue;  // risen off the bed
    Vec3 normal;
    const double eps = bed.smoothing > 0 ? bed.smoothing : 1e-3 * diameter[v];
    const double depth = settle >= 0.5 * eps ? settle + 0.5 * eps : std::sqrt(2.0 * eps * settle);
    const double gap = bed.Distance((*x)[v], &normal) - 0.5 * diameter[v];
    (*x)[v] -= (gap + depth) * normal;
  }
}

/// The chord from A to B, stretched uniformly when it is at least L long; else a parabola of
/// length L bowed along n (unit, normal to the chord).
void BowedChordPositions(const Vec3& A, const Vec3& B, const Vec3& n, double L,
                         const std::vector<double>& s, std::vector<Vec3>* x) {
  const Vec3 chord = B - A;
  const double c = chord.norm();
  double k = 0.0;  // 4 sag / chord
  if (c < L) {
    const auto arc = [&](double kk) { return ParabolaArc(c, kk, 1.0); };
    double hi = 1.0;
    while (arc(hi) < L) hi *= 2.0;
    k = Invert(arc, L, 0.0, hi);
  }
  const double total = ParabolaArc(c, k, 1.0);
  const size_t last = s.size() - 1;
  for (size_t v = 0; v <= last; ++v) {
    const double xi = v == 0      ? 0.0
                      : v == last ? 1.0
                                  : Invert([&](double y) { return ParabolaArc(c, k, y); },
                                           total * s[v] / L, 0.0, 1.0);
    (*x)[v] = A + xi * chord + k * c * xi * (1 - xi) * n;
  }
}

}  // namespace

void QuatFdModel::RestState(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> v) const {
  if (q.size() != size() || v.size() != size())
    throw std::invalid_argument("QuatFdModel::RestState: q and v need " + std::to_string(size()) +
                                " entries, not " + std::to_string(q.size()) + " and " +
                                std::to_string(v.size()));
  const int N = layout_.segments;
  v.setZero();
  if (options_.TipHeld()) {
    HeldShape(q);
    return;
  }
  // The relative rotation (rotation vector) whose discrete curvature over h is exactly k:
  // basic |K| = (2/h) sin(θ/2), variant 1 |K| = (4/h) tan(θ/4).
  const auto rotation_for = [&](const Vec3& k, double h) -> Vec3 {
    const double kn = k.norm();
    if (kn == 0.0) return Vec3::Zero();
    const double theta = options_.curvature == Curvature::kBasic
                             ? 2.0 * std::asin(std::min(1.0, 0.5 * kn * h))
                             : 4.0 * std::atan(0.25 * kn * h);
    return theta / kn * k;
  };
  Vec4 p = base_quat_;
  if (bend_active_[0])
    p = lie::QuatMultiply(p, lie::QuatFromAxisAngle(rotation_for(bend_[0].rest, bend_[0].h)));
  Vec3 x = base_.p;
  for (int i = 0; i < N; ++i) {
    if (i > 0 && bend_active_[i])
      p = lie::QuatMultiply(p, lie::QuatFromAxisAngle(rotation_for(bend_[i].rest, bend_[i].h)));
    q.segment<3>(L::X(i)) = x;
    q.segment<4>(L::P(i)) = p;
    x += lie::QuatRotate(p, segment_[i].rest) * segment_[i].ds;
  }
  q.segment<3>(L::X(N)) = x;
}

void QuatFdModel::HeldShape(Eigen::Ref<Eigen::VectorXd> q) const {
  const int N = layout_.segments;
  const Vec3 A = base_.p, B = options_.tip_position_W, chord = B - A;
  const double c = chord.norm(), length = this->length();
  // The line hangs in the net distributed load: its weight less the fluid's buoyancy plus any
  // uniform force. A hose lighter than the water it displaces hangs upwards; started from the
  // catenary in gravity, it converged to the mirrored shape, compressed (an equilibrium, and
  // unstable). Where the net load cancels (neutral buoyancy), in gravity.
  Vec3 net = Vec3::Zero();
  for (const Vec3& f : vertex_force_W_) net += f;
  const double weight = Mass() * loads_.gravity_W.norm();
  const Vec3 down = net.norm() > 1e-9 * weight ? net : Vec3(loads_.gravity_W);
  const double g = down.norm();
  std::vector<Vec3> x(N + 1);
  HangingPlane plane{Vec3::Zero(), Vec3::Zero(), 0.0, 0.0};
  if (g > 0) {
    plane.up = -down / g;
    plane.h = chord.dot(plane.up);
    const Vec3 across = chord - plane.h * plane.up;
    plane.l = across.norm();
    if (plane.l > 0) plane.u = across / plane.l;
  }
  if (c < length && g > 0 && plane.l > 1e-6 * c) {
    // Stretched by the line's mean tension (hanging free) over its axial stiffness: started
    // inextensible, it carried no tension and so no lateral stiffness, and Newton's first step
    // went metres astray (a 120 m riser in water: 2.6 m), through compressed shapes where the
    // stiffness is singular.
    const double stretch = 1.0 + net.norm() / length *
                                     CatenaryMeanTensionOverLoad(plane, length) /
                                     MeanAxialStiffness();
    std::vector<double> stretched(s_);
    for (double& si : stretched) si *= stretch;
    CatenaryPositions(A, plane, length * stretch, stretched, &x);
    // A base on a bed the catenary would hang through (a riser, a mooring): lying on it instead.
    for (int k = 0; k < loads_.contact.count; ++k) {
      const ContactSurface& bed = loads_.contact.surface[k];
      Vec3 normal;
      const double base_gap = bed.Distance(A, &normal) - 0.5 * vertex_diameter_[0];
      if (bed.shape != ContactSurface::Shape::kPlane || normal.dot(plane.up) < 0.999 ||
          std::abs(base_gap) > 1e-3 * length)
        continue;
      bool through = false;
      for (int v = 1; v < N && !through; ++v)
        through = bed.Distance(x[v], &normal) < 0.5 * vertex_diameter_[v];
      if (through && GroundedCatenaryPositions(A, plane, length * stretch, stretched, &x))
        SinkOntoBed(bed, A, plane.up, std::max(0.0, -net.dot(plane.up)) / length,
                    vertex_diameter_, &x);
    }
  } else {
    // The chord, stretched uniformly (a taut rod); or, with no gravity across the chord to hang
    // from, a parabola of the rod's length bowed along the base frame's x (or y).
    const Vec3 e = c > 0 ? Vec3(chord / c) : Vec3(base_.R.col(2));
    Vec3 n = Vec3::Zero();
    for (int k = 0; k < 2 && n.norm() <= 1e-9; ++k) n = base_.R.col(k) - base_.R.col(k).dot(e) * e;
    BowedChordPositions(A, B, n.normalized(), length, s_, &x);
  }
  x[N] = B;
  for (int v = 0; v <= N; ++v) q.segment<3>(L::X(v)) = x[v];
  // Each segment's frame: the last one (the base's for the first) turned by the least
  // rotation from the last chord onto its own, a parallel transport along the shape, so the
  // start carries no twist. (The base frame turned straight onto each chord twisted the rod
  // wherever the shape left the planes through the base frame's axis: a catenary hanging in a
  // gravity with a component across that axis started twisted by up to half a turn.)
  Vec4 previous = base_quat_;
  Vec3 last = lie::QuatToRotation(previous).col(2);
  for (int i = 0; i < N; ++i) {
    const Vec3 d = (q.segment<3>(L::X(i + 1)) - q.segment<3>(L::X(i))).normalized();
    const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(last, d);
    Vec4 p = lie::QuatMultiply(Vec4(turn.w(), turn.x(), turn.y(), turn.z()), previous);
    p.normalize();
    q.segment<4>(L::P(i)) = p;
    previous = p;
    last = d;
  }
}

double QuatFdModel::Project(Eigen::Ref<Eigen::VectorXd> q, Eigen::Ref<Eigen::VectorXd> v) const {
  double worst = 0.0;
  for (int i = 0; i < layout_.segments; ++i) {
    auto p = q.segment<4>(L::P(i));
    auto pd = v.segment<4>(L::P(i));
    const double norm = p.norm();
    worst = std::max(worst, std::abs(norm - 1.0));
    // p ← p/|p| and ṗ ← (ṗ − (p̂·ṗ) p̂)/|p| keep the rotation and ω = 2 Im(p̄ ṗ)/|p|² exactly.
    p /= norm;
    pd = (pd - p.dot(pd) * p) / norm;
  }
  return worst;
}

double QuatFdModel::ConstraintViolation(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  double worst = 0.0;
  for (int i = 0; i < layout_.segments; ++i)
    worst = std::max(worst, std::abs(q.segment<4>(L::P(i)).norm() - 1.0));
  return worst;
}

double QuatFdModel::min_rotational_inertia() const {
  double j = rotation_[0].inertia.minCoeff();
  for (const kernels::RotationConstants& r : rotation_) j = std::min(j, r.inertia.minCoeff());
  return j;
}

double QuatFdModel::MaxSegmentForce(const Eigen::Ref<const Eigen::VectorXd>& q) const {
  double f_max = 0.0;
  for (int i = 0; i < layout_.segments; ++i) {
    Vec3 force_a, torque, F;  // at rest: no strain rate, so F = C_Γ (Γ − Γ*)
    kernels::SegmentForcesOmega<double>(
        segment_[i], Vec3(q.segment<3>(L::X(i + 1)) - q.segment<3>(L::X(i))),
        Vec4(q.segment<4>(L::P(i))), Vec3::Zero(), Vec3::Zero(), &force_a, &torque, nullptr, &F);
    f_max = std::max(f_max, F.norm());
  }
  return f_max;
}

double QuatFdModel::MeanAxialStiffness() const {
  double length = 0.0, compliance = 0.0;  // m, m/N: the segments in series
  for (const kernels::SegmentConstants& seg : segment_) {
    length += seg.ds;
    compliance += seg.ds / seg.stiffness(2, 2);
  }
  return length / compliance;
}

double QuatFdModel::MaxStrainStiffness() const {
  double c = 0.0;
  for (const kernels::SegmentConstants& seg : segment_) c = std::max(c, seg.stiffness.maxCoeff());
  return c;
}

double QuatFdModel::Mass() const {
  double m = 0;
  for (double mn : mass_) m += mn;
  return m;
}

Vec4 QuatFdModel::VertexQuaternion(const Eigen::Ref<const Eigen::VectorXd>& q, int n) const {
  const int N = layout_.segments;
  Vec4 p;
  if (n == 0) {
    p = options_.base_end == EndCondition::kClamped ? base_quat_ : Vec4(q.segment<4>(L::P(0)));
  } else if (n == N) {
    p = options_.tip_end == EndCondition::kClamped
            ? tip_quat_
            : TipQuaternion<double>(q.segment<4>(L::P(N - 1)));
  } else {
    const Vec4 pa = q.segment<4>(L::P(n - 1));
    Vec4 pb = q.segment<4>(L::P(n));
    if (pa.dot(pb) < 0) pb = -pb;
    p = pa + pb;
  }
  p.normalize();
  return p;
}

void QuatFdModel::set_gust(const FluidGust& gust) {
  gust_ = gust;
  set_time(time_);
}

void QuatFdModel::set_time(double t) const {
  time_ = t;  // kept without a gust too, for one set later
  if (!gust_.present()) return;
  gusty_loads_.fluid = gust_.At(loads_.fluid, t);
}

void QuatFdModel::set_loads(const StaticLoads& loads) {
  loads_ = loads;
  gusty_loads_ = loads;
  set_time(time_);
  tip_wrench_ = TotalTipWrench(loads);
  motion_loads_ = HasMotionLoads(loads);
  // The distributed loads lumped on each vertex: its dual length and lumped mass.
  const int N = layout_.segments;
  vertex_force_W_.resize(N + 1);
  for (int n = 0; n <= N; ++n) vertex_force_W_[n] = TotalDistributedForce_W(loads, VertexSite(n));
  added_mass_.clear();
  if (loads.fluid.has_added_mass()) {
    added_mass_.resize(N + 1);
    for (int n = 0; n <= N; ++n) added_mass_[n] = TotalNormalAddedMass(loads, VertexSite(n));
  }
}

Vec3 QuatFdModel::VertexMotionForce_W(const Eigen::Ref<const Eigen::VectorXd>& q,
                                      const Eigen::Ref<const Eigen::VectorXd>& v, int n) const {
  if (!motion_loads_) return Vec3::Zero();
  const SectionMotion motion{q.segment<3>(L::X(n)), VertexChord(q, n).t, v.segment<3>(L::X(n))};
  return TotalMotionForce_W(motion_loads(), VertexSite(n), motion, nullptr);
}

void QuatFdModel::ToRodState(const Eigen::Ref<const Eigen::VectorXd>& q,
                             const Eigen::Ref<const Eigen::VectorXd>& v, RodState* state) const {
  const int N = layout_.segments;
  state->Resize(N + 1);
  // Per segment: strain Γ, force F (body), ω.
  std::vector<Vec3> gamma(N), force(N), omega(N);
  for (int i = 0; i < N; ++i) {
    Vec3 fa, tau;
    kernels::SegmentForces<double>(segment_[i], q.segment<3>(L::X(i + 1)) - q.segment<3>(L::X(i)),
                                   q.segment<4>(L::P(i)),
                                   v.segment<3>(L::X(i + 1)) - v.segment<3>(L::X(i)),
                                   v.segment<4>(L::P(i)), &fa, &tau, &gamma[i], &force[i]);
    omega[i] = kernels::AngularVelocity<double>(q.segment<4>(L::P(i)), v.segment<4>(L::P(i)));
  }
  for (int n = 0; n <= N; ++n) {
    state->s[n] = s_[n];
    state->position_W[n] = q.segment<3>(L::X(n));
    const Vec4 p = VertexQuaternion(q, n);
    const Mat3 R = lie::QuatToRotation(p);
    state->rotation_WB[n] = R;
    Vec3 K = Vec3::Zero(), M = Vec3::Zero();
    if (bend_active_[n]) {
      Vec3 ta, tb;
      const Vec4 pa = n == 0 ? base_quat_ : Vec4(q.segment<4>(L::P(n - 1)));
      const Vec4 pda = n == 0 ? Vec4::Zero() : Vec4(v.segment<4>(L::P(n - 1)));
      const Vec4 pb = n == N ? tip_quat_ : Vec4(q.segment<4>(L::P(n)));
      const Vec4 pdb = n == N ? Vec4::Zero() : Vec4(v.segment<4>(L::P(n)));
      kernels::BendTorques<double>(bend_[n], pa, pb, pda, pdb, &ta, &tb, &K, &M);
    }
    // Strain and force: mean of the neighbouring segments, rotated into this vertex's frame.
    Vec3 G = Vec3::Zero(), Fw = Vec3::Zero(), W = Vec3::Zero();
    int count = 0;
    for (int i : {n - 1, n}) {
      if (i < 0 || i >= N) continue;
      const Mat3 Ri = lie::QuatToRotation(q.segment<4>(L::P(i)).normalized());
      G += R.transpose() * Ri * gamma[i];
      Fw += Ri * force[i];
      W += Ri * omega[i];
      ++count;
    }
    G /= count;
    Fw /= count;
    W /= count;
    if (n == 0) {
      // The support reaction balances the first segment's pull and the load lumped at x_0:
      // W(0) = R_{1/2} F_{1/2} + f_0 (world), f_0 the distributed loads lumped on x_0 (dead and
      // motion-dependent): the wrench the rod beyond s = 0 exerts.
      Fw = lie::QuatToRotation(q.segment<4>(L::P(0)).normalized()) * force[0] + vertex_force_W_[0] +
           VertexMotionForce_W(q, v, 0);
    } else if (n == N) {
      Fw = lie::QuatToRotation(q.segment<4>(L::P(N - 1)).normalized()) * force[N - 1];
      // A held tip: the support's force, which balances the last segment's pull and the load
      // lumped at x_N.
      if (options_.TipHeld()) Fw -= vertex_force_W_[N] + VertexMotionForce_W(q, v, N);
    }
    // A pinned base that holds only the twist: its element's bending part has no stiffness, and
    // the bend between the base frame and p_{1/2} it sees is no curvature of the rod.
    if (n == 0 && options_.base_end == EndCondition::kPinned) K.head<2>().setZero();
    if (n == N && options_.tip_end != EndCondition::kClamped) {
      // The free or pinned end: K(L) = K* + C⁻¹ m, M(L) = the tip moment in the tip frame.
      Vec3 f, m;
      TipLoads<double>(q.segment<4>(L::P(N - 1)), &f, &m);
      M = R.transpose() * lie::QuatToRotation(q.segment<4>(L::P(N - 1)).normalized()) * m;
      K = tip_rest_ + tip_compliance_ * M;
      // A free end carries the tip force itself, n(L) = F_tip (the last segment's force, half a
      // segment in, also holds the load and inertia lumped at x_N).
      if (!options_.TipHeld()) Fw = f;
    }
    state->strain[n] << K, G;
    state->wrench_B[n] << M, R.transpose() * Fw;
    state->twist_B[n] << R.transpose() * W, R.transpose() * Vec3(v.segment<3>(L::X(n)));
  }
}

QuatFdEnergy QuatFdModel::Energy(const Eigen::Ref<const Eigen::VectorXd>& q,
                                 const Eigen::Ref<const Eigen::VectorXd>& v) const {
  const int N = layout_.segments;
  QuatFdEnergy e;
  for (int n = 0; n <= N; ++n) {
    const Vec3 x = q.segment<3>(L::X(n)), xd = v.segment<3>(L::X(n));
    e.kinetic += 0.5 * mass_[n] * xd.squaredNorm();
    e.potential -= vertex_force_W_[n].dot(x);
    if (added_mass_.empty()) continue;
    // The fluid's added mass moves with the vertex's velocity across the centreline.
    const Vec3& t = VertexChord(q, n).t;
    e.kinetic += 0.5 * added_mass_[n] * (xd - xd.dot(t) * t).squaredNorm();
  }
  for (int i = 0; i < N; ++i) {
    const Vec4 p = q.segment<4>(L::P(i)), pd = v.segment<4>(L::P(i));
    const Vec3 w = kernels::AngularVelocity<double>(p, pd);
    e.kinetic += 0.5 * w.dot(rotation_[i].inertia.cwiseProduct(w));
    const Vec3 gamma = kernels::ToBody<double>(
        p, Vec3((q.segment<3>(L::X(i + 1)) - q.segment<3>(L::X(i))) / segment_[i].ds));
    const Vec3 eg = gamma - segment_[i].rest;
    e.elastic += 0.5 * segment_[i].ds * eg.dot(segment_[i].stiffness * eg);
  }
  for (int n = 0; n <= N; ++n) {
    if (!bend_active_[n]) continue;
    const Vec4 pa = n == 0 ? base_quat_ : Vec4(q.segment<4>(L::P(n - 1)));
    const Vec4 pb = n == N ? tip_quat_ : Vec4(q.segment<4>(L::P(n)));
    kernels::BendConstants c = bend_[n];
    c.damping.setZero();
    Vec3 ta, tb, K;
    kernels::BendTorques<double>(c, pa, pb, Vec4::Zero(), Vec4::Zero(), &ta, &tb, &K);
    const Vec3 ek = K - c.rest;
    e.elastic += 0.5 * c.weight * ek.dot(c.stiffness * ek);
  }
  // Dead tip loads (world frame) have the potential −f·x_N; follower loads have none.
  e.loads -= tip_wrench_.dead_W.tail<3>().dot(q.segment<3>(L::X(N)));
  return e;
}

}  // namespace cosserat::quatfd
