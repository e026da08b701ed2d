#include "mode_classification.hpp"

#include <algorithm>
#include <cmath>

namespace cosserat::detail {

void Classify(const std::vector<Vec3>& tangent_W, const std::vector<double>& mass,
              const std::vector<Mat3>& inertia_W, double length, Mode* mode) {
  double tr = 0, ax = 0, tw = 0, ti = 0;
  for (size_t n = 0; n < tangent_W.size(); ++n) {
    const Vec3& t = tangent_W[n];
    const Vec3& d = mode->displacement_W[n];
    const Vec3& r = mode->rotation_W[n];
    const double da = t.dot(d), ra = t.dot(r);
    ax += mass[n] * da * da;
    tr += mass[n] * (d - da * t).squaredNorm();
    const Vec3 r_axial = ra * t, r_tilt = r - r_axial;
    tw += r_axial.dot(inertia_W[n] * r_axial);
    ti += r_tilt.dot(inertia_W[n] * r_tilt);
  }
  const double sum = std::max(tr + ax + tw + ti, 1e-300);
  mode->share_transverse = tr / sum;
  mode->share_axial = ax / sum;
  mode->share_twist = tw / sum;
  mode->share_tilt = ti / sum;
  const double bending = mode->share_transverse + mode->share_tilt;
  mode->kind = ModeKind::kBending;
  if (mode->share_twist > bending && mode->share_twist > mode->share_axial)
    mode->kind = ModeKind::kTorsion;
  else if (mode->share_axial > bending)
    mode->kind = ModeKind::kAxial;

  double biggest = 0, signed_biggest = 0;
  for (size_t n = 0; n < tangent_W.size(); ++n)
    for (int k = 0; k < 3; ++k) {
      const double a = mode->displacement_W[n](k) / length, b = mode->rotation_W[n](k);
      if (std::abs(a) > biggest) biggest = std::abs(a), signed_biggest = a;
      if (std::abs(b) > biggest) biggest = std::abs(b), signed_biggest = b;
    }
  if (biggest == 0) return;
  const double scale = 1.0 / signed_biggest;
  for (Vec3& d : mode->displacement_W) d *= scale;
  for (Vec3& r : mode->rotation_W) r *= scale;
}

}  // namespace cosserat::detail
