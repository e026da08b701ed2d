#pragma once
/// \file
/// Quadratic fluid drag in Morison's form (Morison et al. 1950), per unit length, on the velocity
/// u = U(p) − v of the fluid relative to the centreline, split by the section's normal t = R e₃:
///   f = ½ ρ_f C_dn D |u_n| u_n + ½ ρ_f C_dt π D |u_t| u_t,   u_t = (t·u) t,  u_n = u − u_t,
/// with D the fluid's drag diameter (default: the section's outer diameter). Not stiff: its
/// derivative in u, t and p (MotionJacobian) goes into the solvers' exact Jacobians.

#include "cosserat/loads/fluid.hpp"
#include "cosserat/loads/load.hpp"

namespace cosserat {

class FluidDrag final : public Load {
 public:
  /// Keeps a reference: the fluid must outlive the load (total_load.hpp makes one per call).
  explicit FluidDrag(const Fluid& fluid) : fluid_(fluid) {}
  bool DependsOnMotion() const override { return fluid_.has_drag(); }
  Vec3 MotionForce_W(const LoadSite& site, const SectionMotion& motion,
                     MotionJacobian* J) const override;

 private:
  const Fluid& fluid_;
};

}  // namespace cosserat
