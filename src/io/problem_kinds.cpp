#include "cosserat/io/problem_kinds.hpp"

namespace cosserat::io {
namespace {

template <typename Enum>
const std::string& NameOf(Enum value) {
  return Names<Enum>()[static_cast<std::size_t>(value)];
}

}  // namespace

template <>
const std::vector<std::string>& Names<Analysis>() {
  static const std::vector<std::string> names = {"statics", "dynamics", "buckling", "modes"};
  return names;
}
template <>
const std::vector<std::string>& Names<Formulation>() {
  static const std::vector<std::string> names = {"se3-shooting", "quaternion-fd"};
  return names;
}
template <>
const std::vector<std::string>& Names<Boundary>() {
  static const std::vector<std::string> names = {"cantilever",      "free-free",
                                                 "pinned-pinned",   "clamped-clamped",
                                                 "clamped-pinned",  "anchored"};
  return names;
}
template <>
const std::vector<std::string>& Names<ShotScheme>() {
  static const std::vector<std::string> names = {"rk4", "heun", "rk4-pairs"};
  return names;
}
template <>
const std::vector<std::string>& Names<RobotKind>() {
  static const std::vector<std::string> names = {"none", "tendon", "jamming", "eversion",
                                                 "pneumatic"};
  return names;
}
template <>
const std::vector<std::string>& Names<BucklingLoad>() {
  static const std::vector<std::string> names = {"tip_force",         "tip_moment",     "gravity",
                                                 "distributed_force", "tendon_tension", "pressure"};
  return names;
}

const std::string& ToString(Analysis value) { return NameOf(value); }
const std::string& ToString(Formulation value) { return NameOf(value); }
const std::string& ToString(Boundary value) { return NameOf(value); }
const std::string& ToString(ShotScheme value) { return NameOf(value); }
const std::string& ToString(RobotKind value) { return NameOf(value); }
const std::string& ToString(BucklingLoad value) { return NameOf(value); }

}  // namespace cosserat::io
