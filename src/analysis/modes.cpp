#include "cosserat/analysis/modes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cosserat/analysis/frequency_shooting.hpp"
#include "cosserat/loads/total_load.hpp"
#include "mode_classification.hpp"
#include "quatfd_reduction.hpp"
#include "damped_modes.hpp"
#include "sparse_modes.hpp"
#include "cosserat/constitutive/section_law.hpp"
#include "cosserat/lie/quaternion.hpp"

namespace cosserat {

const char* ToString(ModeKind kind) {
  switch (kind) {
    case ModeKind::kBending:
      return "bending";
    case ModeKind::kTorsion:
      return "torsion";
    case ModeKind::kAxial:
      return "axial";
  }
  return "unknown";
}

const char* ToString(ModalStatus status) {
  switch (status) {
    case ModalStatus::kNotRun:
      return "not_run";
    case ModalStatus::kConverged:
      return "converged";
    case ModalStatus::kStaticsFailed:
      return "statics_failed";
    case ModalStatus::kUnstable:
      return "unstable";
    case ModalStatus::kTooFewModes:
      return "too_few_modes";
  }
  return "unknown";
}

bool ModalOptions::IsValid(std::string* why) const {
  if (count < 1) {
    if (why) *why = "count: expected at least 1";
    return false;
  }
  if (sparse_above < 0 || max_dense < 0) {
    if (why) *why = sparse_above < 0 ? "sparse_above: expected >= 0" : "max_dense: expected >= 0";
    return false;
  }
  return true;
}

bool ShootingModalOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* msg) {
    if (why) *why = msg;
    return false;
  };
  if (!modal.IsValid(why)) return false;
  if (!(std::isfinite(omega_min) && omega_min >= 0)) return fail("omega_min: expected >= 0");
  if (!(std::isfinite(omega_max) && omega_max >= 0)) return fail("omega_max: expected >= 0");
  if (omega_max > 0 && omega_max <= omega_min) return fail("omega_max: expected > omega_min");
  if (!(relative_step > 0 && relative_step <= 0.1))
    return fail("relative_step: expected in (0, 0.1]");
  if (!(std::isfinite(tip_mass) && tip_mass >= 0)) return fail("tip_mass: expected >= 0");
  if (!(tip_inertia.allFinite() && (tip_inertia.array() >= 0).all()))
    return fail("tip_inertia: expected three moments >= 0");
  return statics.IsValid(why);
}

std::vector<double> ModalResult::frequencies_hz() const {
  std::vector<double> f;
  for (const Mode& m : modes) f.push_back(m.frequency_hz);
  return f;
}

namespace {

using Clock = std::chrono::steady_clock;
using detail::Classify;
using detail::DampedOfModes;
using detail::MassTimes;
using detail::NodeWeights;
using detail::Reduce;
using detail::Reduction;
using detail::TimesMass;
constexpr double kTwoPi = 6.283185307179586;

// Round-off in a spectrum: an eigenvalue carries about ε of the largest one's magnitude.
constexpr double kEpsilon = 2.2e-16;
/// Whether the spectrum's low end (magnitude `smallest`) loses more than 1e-9 of itself to the
/// round-off of its high end (`largest`): its lowest modes must then come from the inverse.
bool LowEndUnresolved(double largest, double smallest) {
  return kEpsilon * largest > 1e-9 * smallest;
}
/// Whether a magnitude stands clear of the round-off of the spectrum's largest (1e3 ε of it).
bool AboveRoundOff(double magnitude, double largest) {
  return magnitude > 1e3 * kEpsilon * largest;
}

/// Why an ω² < 0 (rad²/s²) makes the equilibrium unstable: the direction grows at √(−ω²) /s.
std::string DivergenceReason(double w2) {
  std::ostringstream why;
  why << std::setprecision(4) << "divergence: the stiffness is indefinite";
  if (w2 < 0) why << ", ω² = " << w2 << " rad²/s² (growing at " << std::sqrt(-w2) << " /s)";
  return why.str();
}

/// Why a complex pair λ = −ω² of |λ| = `magnitude` (rad²/s²) makes the equilibrium unstable. A
/// pair counts below the modes returned only: one among a discretisation's highest modes (a dead
/// tip moment couples its near-double shear pairs, ω ~ 1e5 rad/s growing at ~30 /s on a
/// 100-segment rod) says nothing of the rod.
std::string FlutterReason(double magnitude) {
  std::ostringstream why;
  why << std::setprecision(4) << "flutter: a complex pair of eigenvalues near "
      << std::sqrt(magnitude) / (2 * M_PI) << " Hz";
  return why.str();
}

/// ω from ω² (a negative ω² gives −sqrt(−ω²), the growth rate of an unstable direction).
double SignedSqrt(double w2) { return w2 >= 0 ? std::sqrt(w2) : -std::sqrt(-w2); }

// ---- quaternion FD -------------------------------------------------------------------------

/// Node shape of a reduced vector y: vertex displacements, and vertex rotations (world) from
/// the neighbouring segments (the mean inside, the clamp's zero at a clamped base, the last
/// segment's at the tip), as ToRodState places the node frames.
void QuatFdShape(const quatfd::QuatFdModel& model, const Reduction& red, const Eigen::VectorXd& q,
                 const Eigen::VectorXd& y, Mode* mode) {
  using L = quatfd::QuatFdLayout;
  const int N = model.layout().segments;
  std::vector<Vec3> seg(N);
  for (int nu = 0; nu < N; ++nu)
    seg[nu] = lie::QuatToRotation(q.segment<4>(L::P(nu))) * y.segment<3>(red.segment_column[nu]);
  mode->displacement_W.assign(N + 1, Vec3::Zero());
  mode->rotation_W.assign(N + 1, Vec3::Zero());
  for (int n = 0; n <= N; ++n) {
    if (red.vertex_column[n] >= 0) mode->displacement_W[n] = y.segment<3>(red.vertex_column[n]);
    if (n == 0)
      mode->rotation_W[n] =
          model.options().base_end == quatfd::EndCondition::kClamped ? Vec3::Zero() : seg[0];
    else if (n == N)
      mode->rotation_W[n] =
          model.options().tip_end == quatfd::EndCondition::kClamped ? Vec3::Zero() : seg[N - 1];
    else
      mode->rotation_W[n] = 0.5 * (seg[n - 1] + seg[n]);
  }
}

/// The quatfd vertices' weights: the lumped vertex masses, half of each segment's inertia on
/// either end vertex (for the shares only), the mean of the neighbouring segments' tangents.
NodeWeights QuatFdNodeWeights(const quatfd::QuatFdModel& model, const Eigen::VectorXd& q) {
  using L = quatfd::QuatFdLayout;
  const int N = model.layout().segments;
  NodeWeights w;
  w.tangent_W.assign(N + 1, Vec3::Zero());
  w.mass.resize(N + 1);
  w.inertia_W.assign(N + 1, Mat3::Zero());
  for (int n = 0; n <= N; ++n) w.mass[n] = model.vertex_mass()[n];
  for (int nu = 0; nu < N; ++nu) {
    const Mat3 R = lie::QuatToRotation(q.segment<4>(L::P(nu)));
    const Mat3 J = R * model.segment_inertia(nu).asDiagonal() * R.transpose();
    w.inertia_W[nu] += 0.5 * J;
    w.inertia_W[nu + 1] += 0.5 * J;
    w.tangent_W[nu] += R.col(2);
    w.tangent_W[nu + 1] += R.col(2);
  }
  for (Vec3& t : w.tangent_W) t.normalize();
  return w;
}

/// The asymmetry |S_ij − S_ji| a stiffness about an equilibrium may show and still be taken
/// symmetric: 1e-8 of the pair and 1e-13 of the largest entry (round-off); under loads known to
/// be conservative (LoadsAreConservative) also 1e-6 of the pair's own scale √|S_ii S_jj|, what
/// the equilibrium's residual, left by its solve's tolerance, turns its forces by. A 0.006 m²
/// stay cable of I = 1e-15 m⁴ under 4 MN showed 1e-4 N/m (1e-13 of its largest entry, 4e-7 of
/// √|S_ii S_jj|) and was taken for non-conservative, its two lowest modes 1 % and 3 % off in
/// the general dense spectrum. Not under other loads: a follower force's asymmetry P stands
/// against √|S_θθ S_uu| ≈ κGA (shear sets both), 0.7 λ (r/L)² of it at P = λ EI/L², under
/// 1e-6 on a slender rod, and Beck's column of a 0.1 mm wire read 20 % low.
bool AsymmetryWithinRoundOff(double s_ij, double s_ji, double s_ii, double s_jj, double s_max,
                             bool conservative) {
  const double residual = conservative ? 1e-6 * std::sqrt(std::abs(s_ii * s_jj)) : 0.0;
  return std::abs(s_ij - s_ji) <=
         1e-8 * std::max(std::abs(s_ij), std::abs(s_ji)) + 1e-13 * s_max + residual;
}

/// Whether the reduced stiffness S is symmetric to round-off (AsymmetryWithinRoundOff): true
/// for conservative loads about an equilibrium.
bool IsSymmetric(const Eigen::MatrixXd& S, bool conservative) {
  const int m = static_cast<int>(S.rows());
  const double s_max = S.cwiseAbs().maxCoeff();
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < i; ++j)
      if (!AsymmetryWithinRoundOff(S(i, j), S(j, i), S(i, i), S(j, j), s_max, conservative))
        return false;
  return true;
}

/// The same for a sparse S (an entry missing on one side is a zero there).
bool IsSymmetric(const Eigen::SparseMatrix<double>& S, bool conservative) {
  const Eigen::SparseMatrix<double> St = S.transpose();
  const Eigen::SparseMatrix<double> D = S - St;
  double s_max = 0.0;
  for (int j = 0; j < S.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it)
      s_max = std::max(s_max, std::abs(it.value()));
  const Eigen::VectorXd d = S.diagonal();
  for (int j = 0; j < D.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(D, j); it; ++it) {
      const Eigen::Index r = it.row(), c = it.col();
      if (!AsymmetryWithinRoundOff(S.coeff(r, c), St.coeff(r, c), d(r), d(c), s_max,
                                   conservative))
        return false;
    }
  return true;
}

/// ω² with the reduced shape (empty without shapes), ascending.
using Spectrum = std::vector<std::pair<double, Eigen::VectorXd>>;

/// The direct spectrum of H = M^−½ K M^−½ resolves ω² only to ~ε ω²_max, and a slender rod's
/// shear and rotation modes (ω² ≈ κGA/ρI, 1e15 times a thin hanging wire's first) swamp its
/// lowest ones: the two planes of a round wire came out 0.9 % apart, and a cable-like section
/// gave negative frequencies. Where that costs the lowest mode more than 1e-9 of its ω², the
/// spectrum comes from H⁻¹ = M^½ K⁻¹ M^½ instead, if H is positive definite: its Cholesky
/// factor is accurate relative to H's diagonal (Demmel & Veselić 1992), so the largest
/// eigenvalues 1/ω² of H⁻¹ keep their digits. True with the ω² it resolves (ascending, those
/// above 1e3 ε of the largest 1/ω² left out) and, with `vectors`, H's orthonormal eigenvectors
/// for them; false where the direct spectrum serves, with *indefinite set when that is because H
/// is not positive definite.
bool InverseSpectrum(const Eigen::MatrixXd& H, const Eigen::VectorXd& direct, bool vectors,
                     Eigen::VectorXd* w2, Eigen::MatrixXd* psi, bool* indefinite) {
  const int m = static_cast<int>(H.rows());
  if (m == 0) return false;
  const double w2_max = direct.cwiseAbs().maxCoeff();
  if (!LowEndUnresolved(w2_max, std::abs(direct(0)))) return false;
  const Eigen::LLT<Eigen::MatrixXd> llt(H);
  if (llt.info() != Eigen::Success) {
    // Not positive definite: an unstable direction the direct spectrum cannot resolve from
    // round-off (a 2 m wire standing past its self-weight buckling length: ω² = −2.9 against
    // ω²_max ~1e17), but the factorisation, exact relative to the diagonal, does.
    *indefinite = true;
    return false;
  }
  Eigen::MatrixXd G = llt.solve(Eigen::MatrixXd::Identity(m, m));
  G = 0.5 * (G + G.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(
      G, vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& mu = es.eigenvalues();  // ascending: the lowest ω² last
  int k = 0;
  while (k < m && AboveRoundOff(mu(m - 1 - k), mu(m - 1))) ++k;
  w2->resize(k);
  if (vectors) psi->resize(m, k);
  for (int j = 0; j < k; ++j) {
    (*w2)(j) = 1.0 / mu(m - 1 - j);
    if (vectors) psi->col(j) = es.eigenvectors().col(m - 1 - j);
  }
  return true;
}

/// The symmetric problem K φ = ω² M φ with the reduced mass M (diagonal, or with 3×3 vertex blocks
/// of an added mass), as that of M^−½ K M^−½. When damped, also
/// the first-order form of λ² M + λ C + K = 0 in the undamped modal coordinates (Ψ orthonormal,
/// Ω² = eigenvalues) with z = [Ω η; η̇]: ż = [[0, Ω], [−Ω, −Ψᵀ M^−½ C M^−½ Ψ]] z. Its norm is
/// ω_max and it is nearly normal, so the damping ratios of the low modes keep their digits (the
/// plain companion matrix of M⁻¹K, of norm ω_max², loses them). Br = ∂f/∂v reduced (C = −M Br).
/// *indefinite is set when the inverse spectrum finds K not positive definite (InverseSpectrum).
Spectrum SymmetricSpectrum(const Eigen::MatrixXd& S, const Reduction& red,
                           const Eigen::MatrixXd& Br, bool shapes, bool damped,
                           Eigen::MatrixXd* companion, bool* indefinite) {
  const Eigen::VectorXd inv_sqrt_m = red.mass.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd Ssym = 0.5 * (S + S.transpose());
  const Eigen::MatrixXd H =
      TimesMass(red, inv_sqrt_m, -0.5, MassTimes(red, inv_sqrt_m, -0.5, Ssym));
  const bool vectors = shapes || damped;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(
      H, vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  Eigen::VectorXd w2 = es.eigenvalues();
  Eigen::MatrixXd Psi;
  if (!InverseSpectrum(H, es.eigenvalues(), vectors, &w2, &Psi, indefinite) && vectors)
    Psi = es.eigenvectors();
  const Eigen::Index k = w2.size();
  if (damped) {
    const Eigen::VectorXd sqrt_m = red.mass.cwiseSqrt();
    const Eigen::MatrixXd Cm =
        -TimesMass(red, inv_sqrt_m, -0.5, MassTimes(red, sqrt_m, 0.5, Br));
    const Eigen::VectorXd Om = w2.cwiseMax(0.0).cwiseSqrt();
    *companion = Eigen::MatrixXd::Zero(2 * k, 2 * k);
    companion->topRightCorner(k, k) = Om.asDiagonal();
    companion->bottomLeftCorner(k, k) = -Eigen::MatrixXd(Om.asDiagonal());
    companion->bottomRightCorner(k, k) = -(Psi.transpose() * Cm * Psi);
  }
  Spectrum eig;
  for (Eigen::Index i = 0; i < k; ++i)
    eig.emplace_back(w2(i), shapes ? Eigen::VectorXd(MassTimes(red, inv_sqrt_m, -0.5, Psi.col(i)))
                                   : Eigen::VectorXd());
  return eig;
}

/// The real eigenvalues −λ of Ar (ω² = −λ), ascending. A pair with an imaginary part (flutter: no
/// real mode) is left out; *lowest_complex becomes the smallest |λ| of those. As in the
/// symmetric case, a slender rod's spectrum spans more than double precision resolves at its
/// low end (Beck's column of a 1 mm rod at 41 nodes read "unstable" at a fifth of its flutter
/// load, its lowest modes lost): there the eigenvalues come from Ar⁻¹, whose largest ones are
/// the lowest modes, those below 1e3 ε of the largest left out.
Spectrum GeneralSpectrum(const Eigen::MatrixXd& Ar, bool shapes, double* lowest_complex) {
  const Eigen::EigenSolver<Eigen::MatrixXd> es(Ar, shapes);
  Eigen::VectorXcd lambda = es.eigenvalues();
  Eigen::MatrixXcd vectors;
  if (shapes) vectors = es.eigenvectors();
  const double l_max = lambda.cwiseAbs().maxCoeff(), l_min = lambda.cwiseAbs().minCoeff();
  if (LowEndUnresolved(l_max, l_min)) {
    const Eigen::MatrixXd inverse = Ar.partialPivLu().inverse();
    if (inverse.allFinite()) {
      const Eigen::EigenSolver<Eigen::MatrixXd> inv(inverse, shapes);
      const double nu_max = inv.eigenvalues().cwiseAbs().maxCoeff();
      std::vector<Eigen::Index> kept;
      for (Eigen::Index i = 0; i < inverse.rows(); ++i)
        if (AboveRoundOff(std::abs(inv.eigenvalues()(i)), nu_max)) kept.push_back(i);
      lambda.resize(static_cast<Eigen::Index>(kept.size()));
      if (shapes) vectors.resize(inverse.rows(), static_cast<Eigen::Index>(kept.size()));
      for (size_t j = 0; j < kept.size(); ++j) {
        lambda(j) = 1.0 / inv.eigenvalues()(kept[j]);
        if (shapes) vectors.col(j) = inv.eigenvectors().col(kept[j]);
      }
    }
  }
  Spectrum eig;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    const std::complex<double> l = lambda(i);
    if (std::abs(l.imag()) > 1e-6 * std::abs(l)) {
      *lowest_complex = std::min(*lowest_complex, std::abs(l));
      continue;
    }
    eig.emplace_back(-l.real(),
                     shapes ? Eigen::VectorXd(vectors.col(i).real()) : Eigen::VectorXd());
  }
  std::sort(eig.begin(), eig.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return eig;
}

/// What the modes are read from: ω² with the reduced shapes (ascending), and for the dense
/// path the reduced Jacobians, the damped first-order form and what the spectra found.
struct Spectra {
  Spectrum eig;
  Eigen::MatrixXd Ar, Br;     ///< ∂f/∂q, ∂f/∂v reduced (dense path only)
  Eigen::MatrixXd companion;  ///< first-order form of λ² M + λ C + K = 0 when damped
  bool damped = false;        ///< damping to resolve
  bool indefinite = false;    ///< a stiffness the direct spectrum cannot resolve, not definite
  bool too_large = false;     ///< the dense spectrum was beyond ModalOptions::max_dense
  int dense_size = 0;         ///< its size: the reduced coordinates, twice them when damped
  bool has_damping = false;   ///< ∂f/∂v has an entry: the model is damped
  double lowest_complex = std::numeric_limits<double>::infinity();  ///< flutter (GeneralSpectrum)
  /// max |(M⁻¹K)_ii|, rad²/s²: the stiffest coordinate's own ω², the scale of the round-off a
  /// zero ω² picks up in the factorisation (each entry in rad²/s², whatever its coordinate's unit)
  double diagonal = 0.0;
};

/// The neutral entries of a spectrum (Mode::neutral): its lowest |ω²|, up to six of them, when
/// they are round-off of zero, below ε times `diagonal` (the largest |(M⁻¹K)_ii|: a relative
/// round-off of ε in the stiffest coordinate moves an ω² that far), and the next |ω²| stands
/// clear of that and more than 1e4 above them. A neutral ω² comes out at either sign, so the
/// sign test alone called a riser bowed about a vertical chord, free to turn about it, unstable
/// or (at ω² = +6e-11, in the grid check that divides by ω) under-resolved by 1e9 %. Measured,
/// such zeros lie at 4e-5 to 0.1 of the bound (a riser on 301 nodes, banded and dense; a 10 m rod
/// on 41), while a bow on a chord tilted 3e-4 rad from gravity, truly unstable at ω² = −4.2e-3,
/// lies at 55 times it and a column 0.3 % past its critical load at 1.6e4: both stay unstable.
/// `omega_below` (rad/s): the gap's geometric middle in ω, under which no damped pair is judged
/// either; 0 when none.
struct NeutralEntries {
  std::vector<bool> neutral;
  double omega_below = 0.0;
};
NeutralEntries FindNeutralEntries(const Spectrum& eig, double diagonal) {
  NeutralEntries out;
  out.neutral.assign(eig.size(), false);
  std::vector<size_t> order(eig.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::abs(eig[a].first) < std::abs(eig[b].first);
  });
  constexpr size_t kMostNeutral = 6;  // the rigid motions of a body
  constexpr double kGap = 1e4;        // in ω²: 1e2 in frequency
  for (size_t m = 1; m < order.size() && m <= kMostNeutral; ++m) {
    const double below = std::abs(eig[order[m - 1]].first), above = std::abs(eig[order[m]].first);
    if (!(below <= kEpsilon * diagonal) || !(above > kEpsilon * diagonal) ||
        !(above > kGap * below))
      continue;
    for (size_t j = 0; j < m; ++j) out.neutral[order[j]] = true;
    out.omega_below = std::sqrt(std::sqrt(below * above));
    break;
  }
  return out;
}

/// The spectrum of the linearisation A = ∂f/∂q, B = ∂f/∂v: from the banded factorisation on a
/// large grid without damping to resolve, when the stiffness is symmetric and definite
/// (LowestModesSparse); else dense. Sets result->symmetric and result->sparse; `conservative`:
/// the loads are (AsymmetryWithinRoundOff).
Spectra ComputeSpectrum(const BandedMatrix& A, const BandedMatrix& B, const Reduction& red,
                        bool conservative,
                        const ModalOptions& options, ModalResult* result) {
  Spectra out;
  out.has_damping = B.ToSparse().nonZeros() > 0;
  if (red.T.cols() > options.sparse_above && !(options.damped && out.has_damping)) {
    const Eigen::SparseMatrix<double> Ar = red.P * (A.ToSparse() * red.T);
    const Eigen::SparseMatrix<double> S = -(SparseMassPower(red, 1.0) * Ar);
    result->symmetric = IsSymmetric(S, conservative);
    for (int j = 0; j < Ar.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(Ar, j); it; ++it)
        if (it.row() == it.col()) out.diagonal = std::max(out.diagonal, std::abs(it.value()));
    // One more than asked for: the next mode tells a neutral one (FindNeutralEntries).
    if (result->symmetric)
      result->sparse = LowestModesSparse(S, red, options.count + 1, options.shapes, &out.eig);
    if (result->sparse) return out;
  }
  // Damped modes take the companion problem, twice the coordinates (and the general solver).
  out.dense_size = static_cast<int>(red.T.cols()) * (options.damped && out.has_damping ? 2 : 1);
  if (out.dense_size > options.max_dense) {
    out.too_large = true;
    return out;
  }
  out.Ar = red.P * (A.ToDense() * red.T);
  out.Br = red.P * (B.ToDense() * red.T);
  out.diagonal = out.Ar.diagonal().cwiseAbs().maxCoeff();
  // Stiffness S = −M Ar (at an equilibrium, where the forces vanish, the turning of an added
  // mass's block adds nothing to Ar); ω² and reduced eigenvectors, ascending.
  const Eigen::MatrixXd S = -MassTimes(red, red.mass, 1.0, out.Ar);
  result->symmetric = IsSymmetric(S, conservative);
  out.damped = options.damped && out.Br.cwiseAbs().maxCoeff() > 0;
  out.eig = result->symmetric ? SymmetricSpectrum(S, red, out.Br, options.shapes, out.damped,
                                                  &out.companion, &out.indefinite)
                              : GeneralSpectrum(out.Ar, options.shapes, &out.lowest_complex);
  return out;
}

/// Why a spectrum larger than ModalOptions::max_dense was declined (ModalResult::declined).
std::string DeclinedReason(const ModalOptions& options, const Spectra& sp, bool symmetric) {
  return std::string("the stiffness is ") +  // damped first: symmetry not judged
         (options.damped && sp.has_damping ? "damped, and the damped modes need the whole spectrum"
          : !symmetric                     ? "not symmetric (follower loads, drag)"
                                           : "not positive definite (an unstable equilibrium)") +
         ", so its spectrum would be dense, on " + std::to_string(sp.dense_size) +
         " coordinates (at most " + std::to_string(options.max_dense) + ")";
}

}  // namespace

ModalResult ComputeModes(quatfd::QuatFdModel* model, const StaticLoads& loads,
                         const ModalOptions& options, const Eigen::VectorXd* q_guess,
                         Eigen::VectorXd* q_equilibrium,
                         const quatfd::QuatFdStaticsOptions& statics) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("ModalOptions: " + why);
  const auto start = Clock::now();
  ModalResult result;
  const int n_full = model->size();
  Eigen::VectorXd q(n_full), v(n_full);
  model->RestState(q, v);
  if (q_guess) q = *q_guess;
  const quatfd::QuatFdStaticsSummary st = quatfd::SolveStatics(model, loads, q, statics);
  result.statics_status = st.status;
  result.statics_iterations = st.iterations;
  result.statics_residual = st.residual;
  if (q_equilibrium) *q_equilibrium = q;
  result.s = model->grid();
  model->ToRodState(q, Eigen::VectorXd::Zero(n_full), &result.equilibrium);
  auto finish = [&](ModalStatus status) {
    result.status = status;
    result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  };
  if (!st.converged()) return finish(ModalStatus::kStaticsFailed);
  v.setZero();
  model->Project(q, v);

  BandedMatrix A, B;
  model->Jacobian(q, v, &A, &B);
  const Reduction red = Reduce(*model, q);
  Spectra sp = ComputeSpectrum(A, B, red, LoadsAreConservative(loads), options, &result);
  if (sp.too_large) {
    result.declined = DeclinedReason(options, sp, result.symmetric);
    result.declined_dense_size = sp.dense_size;
    return finish(ModalStatus::kNotRun);
  }
  const Spectrum& eig = sp.eig;
  const double lowest_complex = sp.lowest_complex;
  const bool damped = sp.damped;
  const bool indefinite = sp.indefinite;
  bool unstable = false;
  auto mark = [&](std::string why) {  // the first reason found is the one reported
    if (!unstable) result.instability = std::move(why);
    unstable = true;
  };
  const double w2_max = eig.empty() ? 0.0 : std::abs(eig.back().first);
  const NeutralEntries neutral = FindNeutralEntries(eig, sp.diagonal);
  const NodeWeights weights = QuatFdNodeWeights(*model, q);
  for (int i = 0;
       i < static_cast<int>(eig.size()) && static_cast<int>(result.modes.size()) < options.count;
       ++i) {
    Mode mode;
    const double w2 = eig[i].first;
    mode.neutral = neutral.neutral[i];
    if (mode.neutral) mode.computed_omega_squared = w2;
    if (!mode.neutral && lowest_complex <= std::abs(w2)) mark(FlutterReason(lowest_complex));
    if (!mode.neutral && AboveRoundOff(-w2, w2_max)) mark(DivergenceReason(w2));
    mode.omega = mode.neutral ? 0.0 : SignedSqrt(w2);
    mode.frequency_hz = mode.omega / kTwoPi;
    if (options.shapes) {
      QuatFdShape(*model, red, q, eig[i].second, &mode);
      Classify(weights.tangent_W, weights.mass, weights.inertia_W, model->length(), &mode);
    }
    result.modes.push_back(std::move(mode));
  }

  // The factorisation found the stiffness indefinite where the spectrum's low end is round-off.
  // (Not when its most negative ω² is a neutral one: then every negative one is.)
  if (indefinite && !(eig.empty() ? false : neutral.neutral.front()))
    mark(DivergenceReason(eig.empty() ? 0.0 : eig.front().first));
  if (damped && DampedOfModes(result.symmetric, sp.Ar, sp.Br, result.modes, neutral.omega_below,
                              &sp.companion, &result.damped))
    mark("a damped mode grows (Re λ > 0)");
  // Fewer real modes than asked for: any complex pair is below the last one there could be.
  if (static_cast<int>(result.modes.size()) < options.count && std::isfinite(lowest_complex))
    mark(FlutterReason(lowest_complex));
  if (unstable) return finish(ModalStatus::kUnstable);
  if (static_cast<int>(result.modes.size()) < options.count)
    return finish(ModalStatus::kTooFewModes);
  return finish(ModalStatus::kConverged);
}

}  // namespace cosserat
