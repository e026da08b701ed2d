#include "cosserat/loads/contact_entry.hpp"

#include <algorithm>

namespace cosserat {

double ContactEntryFraction(const ContactSurfaces& surfaces, const std::vector<Vec3>& before,
                            const std::vector<Vec3>& after,
                            const std::vector<double>& outer_diameter) {
  double fraction = 1.0;
  for (int k = 0; k < surfaces.count; ++k) {
    const ContactSurface& s = surfaces.surface[k];
    if (!(s.stiffness > 0.0)) continue;
    for (size_t v = 0; v < before.size(); ++v) {
      Vec3 normal;
      const double r_o = 0.5 * outer_diameter[v];
      const double depth_before = r_o - s.Distance(before[v], &normal);  // penetration, m
      if (depth_before > 0.0) continue;  // already in contact: the penalty is in the Jacobian
      const double eps = s.smoothing > 0 ? s.smoothing : 1e-3 * outer_diameter[v];
      const double allowed = std::max(eps, r_o);
      const double depth_after = r_o - s.Distance(after[v], &normal);
      if (depth_after <= allowed) continue;
      fraction = std::min(fraction, (allowed - depth_before) / (depth_after - depth_before));
    }
  }
  return fraction;
}

}  // namespace cosserat
