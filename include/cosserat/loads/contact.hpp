#pragma once
/// \file
/// Contact with rigid surfaces by a penalty per unit length (a Winkler foundation): a plane, a
/// sphere (an obstacle) and a cylinder the rod stays inside (a bore, a tube) or outside (a post, a
/// pipe). The gap is the centreline's distance to the surface minus the section's outer radius;
/// the normal force per unit length is k·φ(−g) along the surface normal n (towards the free side),
/// with φ the penetration smoothed over a width ε (a C¹ ramp: φ(δ) = δ²/(2ε) for 0 < δ < ε,
/// δ − ε/2 beyond; ε = the surface's `smoothing`, 1e-3 of the rod's outer diameter by default), so
/// that Newton's method sees a continuous stiffness. Damping −c ψ (v·n) n acts on the approach
/// velocity while in contact (ψ = min(δ/ε, 1)); the sum never pulls (a rod leaving faster than
/// the spring pushes it out feels no force). Coulomb friction opposes the slip velocity
/// v_s = (I − n nᵀ) v with the magnitude μ N, regularised near zero slip:
/// f_f = −μ N v_s / sqrt(|v_s|² + v_ε²), N = max(normal force, 0), v_ε the surface's
/// slip_velocity. Below v_ε the rod creeps instead of sticking: under a tangential load T < μN it
/// slides at v_ε (T/μN) / sqrt(1 − (T/μN)²). At rest (statics) there is no friction.
/// A plain aggregate: up to kMaxContactSurfaces surfaces in StaticLoads, so a controller may move
/// an obstacle every step without allocating.

#include <array>
#include <functional>
#include <string>

#include "cosserat/lie/types.hpp"
#include "cosserat/loads/load.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat {

struct ContactSurface {
  enum class Shape { kPlane, kSphere, kCylinder };
  Shape shape = Shape::kPlane;
  Vec3 point_W = Vec3::Zero();  ///< plane: a point on it; sphere: its centre; cylinder: on its axis
  Vec3 direction_W = Vec3::UnitZ();  ///< plane: its normal (free side); cylinder: its axis; unit
  double radius = 0.0;               ///< sphere, cylinder: m
  bool inside = false;               ///< cylinder: the rod stays within it
  double stiffness = 0.0;            ///< k, N/m per metre of rod
  double damping = 0.0;              ///< c, N·s/m per metre of rod (dynamics)
  double smoothing = 0.0;            ///< ε, m; 0: 1e-3 of the rod's outer diameter
  double friction = 0.0;             ///< Coulomb μ (dynamics)
  double slip_velocity = 1e-4;       ///< v_ε of the friction's regularisation, m/s

  /// Signed distance of the point p_W to the surface (positive on the free side, m) and the unit
  /// normal there (towards the free side); with dn, ∂n/∂p.
  double Distance(const Vec3& p_W, Vec3* normal, Mat3* dn = nullptr) const;
  bool operator==(const ContactSurface& o) const;
  /// Checks ranges; on failure writes the reason naming environment.contact[index].<key>.
  bool IsValid(int index, std::string* why) const;
};

inline constexpr int kMaxContactSurfaces = 8;

/// The rigid surfaces of a problem.
struct ContactSurfaces {
  int count = 0;
  std::array<ContactSurface, kMaxContactSurfaces> surface{};
  bool operator==(const ContactSurfaces& o) const;
  bool IsValid(std::string* why) const;
};

/// Whether the rod at `state` presses on `surface`: some node's centreline nearer to it than
/// the section's outer radius there (`outer_radius(s)`, m), where the penalty pushes.
bool PressesOn(const ContactSurface& surface, const RodState& state,
               const std::function<double(double)>& outer_radius);

/// The penalty contact of a rod's section with the surfaces (a load that depends on the pose and
/// velocity, load.hpp).
class PenaltyContact final : public Load {
 public:
  /// Keeps a reference: the surfaces must outlive the load (total_load.hpp makes one per call).
  explicit PenaltyContact(const ContactSurfaces& surfaces) : surfaces_(surfaces) {}
  bool DependsOnMotion() const override { return surfaces_.count > 0; }
  Vec3 MotionForce_W(const LoadSite& site, const SectionMotion& motion,
                     MotionJacobian* J) const override;

 private:
  /// Adds the regularised Coulomb friction of surface s (normal n, ∂n/∂p = dn) for the normal
  /// force `normal` > 0 (N) with its derivatives, at the centreline velocity v.
  static void AddFriction(const ContactSurface& s, const Vec3& n, const Mat3& dn, double normal,
                          const Vec3& d_normal_dp, const Vec3& d_normal_dv, const Vec3& v,
                          Vec3* force, MotionJacobian* J);

  const ContactSurfaces& surfaces_;
};

}  // namespace cosserat
