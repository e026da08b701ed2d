#include "column_guide_note.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosserat::run::detail {

std::string GuideTakesTipForceNote(const io::Problem& problem, ColumnEnds ends) {
  if (ends == ColumnEnds::kClampedFree) return "";
  const Vec3& f = problem.loads.tip_force;  // N, world (or the tip's frame for "body")
  const bool body = problem.loads.tip_force_frame == LoadFrame::kBody;
  const Vec3 axis = body ? Vec3::UnitZ() : Vec3(problem.base.R.col(2));
  const Vec3 across = f - f.dot(axis) * axis;
  if (!(across.norm() > 1e-12 * f.norm())) return "";
  std::ostringstream note;
  note << std::setprecision(4) << "cosserat: note: the " << ToString(ends)
       << " column's tip guide slides only along its axis ([" << axis.x() << ", " << axis.y()
       << ", " << axis.z() << "], " << (body ? "the tip's frame" : "base.rotation's third column")
       << ") and takes the " << across.norm()
       << " N of loads.tip_force across it whole: that part bends nothing and is in no result "
          "field; a load across the span is loads.distributed_force or gravity (a point load "
          "along the span is not in this version)\n";
  return note.str();
}

}  // namespace cosserat::run::detail
