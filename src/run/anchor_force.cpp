#include "anchor_force.hpp"

#include <iomanip>
#include <sstream>

namespace cosserat::run::detail {

std::string AnchorForceText(const RodState& state) {
  const Mat3& R = state.rotation_WB.back();
  const Vec3 f = R * state.wrench_B.back().tail<3>();
  const double axial = state.wrench_B.back()(5);  // n·t, the tip's body frame
  std::ostringstream out;
  out << "anchor force [" << std::setprecision(6) << f.x() << ", " << f.y() << ", " << f.z()
      << "] N ";
  if (axial >= 0)
    out << "(tension " << f.norm() << " N)";
  else
    out << "(compression, axial force " << axial << " N)";
  return out.str();
}

}  // namespace cosserat::run::detail
