#include "cosserat/rod/rest_shape.hpp"

namespace cosserat {

std::vector<Vec3> RestCentreline_W(const RodModel& rod, const lie::SE3& base, int points) {
  std::vector<Vec3> out;
  out.reserve(points);
  lie::SE3 g = base;
  out.push_back(g.p);
  const double h = rod.length / (points - 1);
  for (int i = 1; i < points; ++i) {
    const Vec6 xi = rod.RestStrainAt((i - 0.5) * h);
    g = lie::Compose(g, lie::SE3Exp(Vec6(h * xi)));
    out.push_back(g.p);
  }
  return out;
}

}  // namespace cosserat
