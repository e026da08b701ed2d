#include "obstacle_core_watch.hpp"

#include <iomanip>
#include <sstream>

#include "cosserat/loads/obstacle_core.hpp"

namespace cosserat::run::detail {

void ObstacleCoreWatch::Observe(double t, const std::vector<Vec3>& positions) {
  if (surface_ >= 0) return;  // the first entry is the one reported
  surface_ = ObstacleCoreReached(surfaces_, last_, positions);
  if (surface_ >= 0) t_ = t;
  last_ = positions;  // no allocation once the first call has sized it
}

std::string ObstacleCoreWatch::Warning(bool fixed_step) const {
  if (surface_ < 0) return "";
  const ContactSurface& s = surfaces_.surface[surface_];
  using Shape = ContactSurface::Shape;
  const bool far_side = s.shape == Shape::kPlane || (s.shape == Shape::kCylinder && s.inside);
  std::ostringstream out;
  out << std::setprecision(6) << "cosserat: warning: at t = " << t_
      << " s the rod went through environment.contact[" << surface_ << "] ("
      << (far_side ? "its centreline beyond the surface, pressed in by more than its radius"
                   : s.shape == Shape::kSphere
                         ? "its centreline within half the sphere's radius of its centre"
                         : "its centreline within half the cylinder's radius of its axis")
      << "), which the statics refuse: the penalty (stiffness " << std::setprecision(3)
      << s.stiffness << " N/m²) is too soft for this motion"
      << (fixed_step ? ", or a step jumped the obstacle" : "") << "; a stiffer environment.contact["
      << surface_ << "].stiffness" << (fixed_step ? ", or a smaller dynamics.dt," : "")
      << " holds the rod out\n";
  return out.str();
}

}  // namespace cosserat::run::detail
