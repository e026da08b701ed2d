// What this version runs: the combinations of analysis, formulation, boundary and features a
// valid problem may still ask for in vain (io::UnsupportedFeatures).
#include <algorithm>
#include <initializer_list>
#include <string>
#include <vector>

#include "cosserat/io/problem.hpp"
#include "cosserat/io/json_reader.hpp"
#include "problem_assembly.hpp"

namespace cosserat::io {

namespace {

/// "<key>: "<value>" is not implemented in this version (supported: ...)" unless `value` is one
/// of `supported`.
template <typename Enum>
void CheckSupported(const char* key, Enum value, std::initializer_list<Enum> supported,
                    std::vector<std::string>* out) {
  if (std::find(supported.begin(), supported.end(), value) != supported.end()) return;
  std::vector<std::string> names;
  for (Enum e : supported) names.push_back(ToString(e));
  out->push_back(std::string(key) + ": " + detail::Quote(ToString(value)) +
                 " is not implemented in this version (supported: " + detail::QuotedList(names) +
                 ")");
}

/// What the drill string's drives (table speed, motor, bit) and a gusting flow run on.
void DriveAndFlowFeatures(const Problem& p, std::vector<std::string>* out) {
  const bool quatfd = p.formulation == Formulation::kQuaternionFd;
  const bool cantilever = p.boundary == Boundary::kCantilever;
  if (p.gust.present() && p.analysis != Analysis::kDynamics)
    out->push_back("environment.fluid.gust: a gusting flow needs \"analysis\": \"dynamics\"");
  const bool spin = p.dynamics.base_spin != 0.0 || p.dynamics.base_spin_given;  // 0 reports too
  if (quatfd && (p.loads.bit.present() || spin))
    out->push_back(
        std::string(p.loads.bit.present() ? "loads.bit_friction" : "dynamics.base_spin") +
        ": runs on the \"se3-shooting\" formulation's dynamics in this version");
  if (p.dynamics.rotary_table.present() && (quatfd || !cantilever))
    out->push_back(
        "dynamics.rotary_table: turns a clamped base (\"boundary\": \"cantilever\") on the "
        "\"se3-shooting\" formulation");
  if (!quatfd && spin && !cantilever)
    out->push_back("dynamics.base_spin: turns a clamped base (\"boundary\": \"cantilever\")");
}

/// A rigid body at the tip (dynamics.tip_mass, tip_inertia) is part of the SE(3) stepper's and
/// the SE(3) cantilever modes' tip condition only: the quaternion-FD dynamics and modes, and a
/// column's guided tip, would leave it out.
void TipBodyFeatures(const Problem& p, std::vector<std::string>* out) {
  if (!(p.dynamics.tip_mass > 0.0 || !p.dynamics.tip_inertia.isZero())) return;
  const char* field = p.dynamics.tip_mass > 0.0 ? "dynamics.tip_mass" : "dynamics.tip_inertia";
  if (p.formulation == Formulation::kQuaternionFd && p.analysis == Analysis::kDynamics)
    out->push_back(std::string(field) +
                   ": a body at the tip runs on the \"se3-shooting\" formulation's dynamics in "
                   "this version");
  if (p.analysis == Analysis::kModes && p.formulation == Formulation::kQuaternionFd)
    out->push_back(std::string(field) +
                   ": the quaternion-FD modes leave a body at the tip out in this version "
                   "(\"formulation\": \"se3-shooting\" takes it on a cantilever)");
  else if (p.analysis == Analysis::kModes && p.boundary != Boundary::kCantilever)
    out->push_back(std::string(field) + ": a body at the tip takes a cantilever's free tip "
                                        "(\"boundary\": \"cantilever\")");
}

/// A column's tip in dynamics slides along the axis under the loads' dead tip force: a follower
/// force, a moment at a pinned tip, a body or a bit there have no place in that guide.
void GuidedTipDynamicsFeatures(const Problem& p, std::vector<std::string>* out) {
  if (p.analysis != Analysis::kDynamics ||
      (p.boundary != Boundary::kClampedClamped && p.boundary != Boundary::kClampedPinned))
    return;
  const std::string ends = " (\"boundary\": " + detail::Quote(ToString(p.boundary)) + ")";
  GuidedTipLoadFeatures(p.loads, p.boundary, out);
  if (p.dynamics.initial_loads) {  // the start's loads, named as such
    std::vector<std::string> initial;
    GuidedTipLoadFeatures(*p.dynamics.initial_loads, p.boundary, &initial);
    for (const std::string& line : initial) out->push_back("dynamics.initial_" + line);
  }
  if (p.dynamics.tip_mass > 0.0 || !p.dynamics.tip_inertia.isZero())
    out->push_back("dynamics.tip_mass: a body at a column's guided tip is not modelled" + ends);
  if (p.loads.bit.present())
    out->push_back("loads.bit_friction: a drill bit acts at a free tip (\"boundary\": "
                   "\"cantilever\")");
}

/// A clamped tip holds its rotation: a moment there acts on the clamp, not the rod.
void ClampedTipFeatures(const Problem& p, std::vector<std::string>* out) {
  if (p.boundary != Boundary::kClampedClamped) return;
  const bool moment_path =
      p.analysis == Analysis::kBuckling && p.buckling.load == BucklingLoad::kTipMoment;
  if (!p.loads.tip_moment.isZero() || moment_path)
    out->push_back(
        std::string(p.loads.tip_moment.isZero() ? "buckling.load" : "loads.tip_moment") +
        ": a moment at a clamped tip (\"boundary\": \"clamped-clamped\") acts on the clamp, not "
        "the rod");
}

void BoundaryFeatures(const Problem& p, std::vector<std::string>* out, bool explain = true);

/// Where the problem's boundary runs, by formulation: "; \"pinned-pinned\" runs statics,
/// buckling and modes on \"se3-shooting\"" (a boundary refused for one analysis works in
/// another, and the refusal alone read as if it did not exist).
std::string WhereBoundaryRuns(const Problem& p) {
  std::string where;
  for (const Formulation f : {Formulation::kSe3Shooting, Formulation::kQuaternionFd}) {
    std::vector<std::string> runs;
    for (const Analysis a :
         {Analysis::kStatics, Analysis::kDynamics, Analysis::kBuckling, Analysis::kModes}) {
      Problem q;
      q.boundary = p.boundary;
      q.analysis = a;
      q.formulation = f;
      std::vector<std::string> refused;
      BoundaryFeatures(q, &refused, false);
      if (refused.empty()) runs.push_back(ToString(a));
    }
    if (runs.empty()) continue;
    where += where.empty() ? "; " + detail::Quote(ToString(p.boundary)) + " runs " : ", and ";
    for (size_t i = 0; i < runs.size(); ++i)
      where += (i == 0 ? "" : i + 1 == runs.size() ? " and " : ", ") + runs[i];
    where += std::string(" on ") + detail::Quote(ToString(f));
  }
  return where;
}

/// The boundary each analysis and formulation runs with; with `explain`, a refusal names the
/// analysis and formulation it is for and where the boundary runs.
void BoundaryFeatures(const Problem& p, std::vector<std::string>* out, bool explain) {
  using A = Analysis;
  const size_t before = out->size();
  using B = Boundary;
  const bool quatfd = p.formulation == Formulation::kQuaternionFd;
  // Every analysis and formulation runs; the boundary depends on both.
  if (p.boundary == B::kAnchored && p.analysis == A::kBuckling)
    out->push_back("boundary: \"anchored\" runs statics, dynamics and modes in this version");
  else if (p.boundary == B::kAnchored && !quatfd && p.analysis != A::kStatics)
    out->push_back(
        "boundary: \"anchored\" runs dynamics and modes on the \"quaternion-fd\" formulation "
        "in this version (statics on both)");
  else if (quatfd && p.analysis != A::kBuckling)  // rod.nodes >= 3 is checked by the parser
    CheckSupported("boundary", p.boundary, {B::kCantilever, B::kAnchored}, out);
  else if (quatfd)
    CheckSupported("boundary", p.boundary, {B::kCantilever}, out);
  else if (p.analysis == A::kDynamics)
    CheckSupported("boundary", p.boundary,
                   {B::kCantilever, B::kFreeFree, B::kClampedClamped, B::kClampedPinned}, out);
  else if (p.analysis == A::kBuckling)
    CheckSupported("boundary", p.boundary,
                   {B::kCantilever, B::kPinnedPinned, B::kClampedClamped, B::kClampedPinned}, out);
  else if (p.analysis == A::kStatics)
    CheckSupported("boundary", p.boundary,
                   {B::kCantilever, B::kPinnedPinned, B::kClampedClamped, B::kClampedPinned,
                    B::kAnchored},
                   out);
  else  // modes
    CheckSupported("boundary", p.boundary,
                   {B::kCantilever, B::kPinnedPinned, B::kClampedClamped, B::kClampedPinned}, out);
  if (explain && out->size() > before &&
      out->back().find(" is not implemented in this version (supported: ") != std::string::npos)
    out->back() += " for \"analysis\": " + detail::Quote(ToString(p.analysis)) + " on " +
                   detail::Quote(ToString(p.formulation)) + WhereBoundaryRuns(p);
  // Modes of a rod held at both ends on the quaternion-FD path: the anchored rod has them.
  const bool held_ends = p.boundary == B::kPinnedPinned || p.boundary == B::kClampedClamped ||
                         p.boundary == B::kClampedPinned;
  if (p.analysis == A::kModes && quatfd && held_ends && !out->empty())
    out->back() +=
        "; modes of a rod held at both ends run as \"boundary\": \"anchored\" (with anchor.base "
        "or anchor.tip \"clamped\" for a clamped end) on \"formulation\": \"quaternion-fd\", "
        "or as a column on \"se3-shooting\"";
  if (!quatfd && p.analysis != A::kBuckling && p.boundary != B::kCantilever &&
      p.boundary != B::kFreeFree && p.has_robot)
    out->push_back(std::string("robot: a robot runs with \"boundary\": \"cantilever\" in ") +
                   ToString(p.analysis) + " (got " +
                   detail::Quote(ToString(p.boundary)) + ")");
}

/// How many nodes of the rod's grid have no mass per length.
int MasslessNodes(const Problem& p) {
  const int n = std::max(p.nodes, 2);
  int massless = 0;
  for (int i = 0; i < n; ++i) {
    const double s = p.rod.length * i / (n - 1);
    massless += !(p.rod.section->At(s, p.robot.actuation).mass(5, 5) > 0.0);
  }
  return massless;
}
bool MasslessSomewhere(const Problem& p) { return MasslessNodes(p) > 0; }
bool MasslessEverywhere(const Problem& p) { return MasslessNodes(p) == std::max(p.nodes, 2); }

}  // namespace

void GuidedTipLoadFeatures(const StaticLoads& loads, Boundary boundary,
                           std::vector<std::string>* out) {
  if (boundary != Boundary::kClampedClamped && boundary != Boundary::kClampedPinned) return;
  const std::string ends = " (\"boundary\": " + detail::Quote(ToString(boundary)) + ")";
  if (loads.tip_force_frame == LoadFrame::kBody && !loads.tip_force.isZero())
    out->push_back("loads.tip_force_frame: a column's guided tip in dynamics takes a dead (world) "
                   "tip force" + ends);
  if (boundary == Boundary::kClampedPinned && !loads.tip_moment.isZero())
    out->push_back("loads.tip_moment: a column's pinned tip in dynamics carries no moment" + ends);
}

std::vector<std::string> UnsupportedFeatures(const Problem& p) {
  using A = Analysis;
  std::vector<std::string> out;
  const bool quatfd = p.formulation == Formulation::kQuaternionFd;
  if (p.has_assembly) return detail::UnsupportedAssemblyFeatures(p);
  BoundaryFeatures(p, &out);
  DriveAndFlowFeatures(p, &out);
  TipBodyFeatures(p, &out);
  ClampedTipFeatures(p, &out);
  GuidedTipDynamicsFeatures(p, &out);
  if (quatfd && p.rod.section && MasslessSomewhere(p))
    out.push_back(
        "rod.material.density: a massless rod (density 0) runs on the \"se3-shooting\" "
        "formulation only; the \"quaternion-fd\" model divides its forces by the nodes' masses");
  else if (p.analysis == A::kModes && p.rod.section && MasslessEverywhere(p))
    out.push_back("rod.material.density: a massless rod (density 0) has no natural frequencies; "
                  "modes need a positive density");
  if (p.analysis == A::kBuckling && quatfd) {
    // The quaternion-FD stiffness is the Hessian of a potential: conservative tip loads only.
    if (p.loads.tip_force_frame == LoadFrame::kBody)
      out.push_back(
          "loads.tip_force_frame: \"body\" (a follower force) is not conservative; buckling on "
          "the \"quaternion-fd\" formulation needs \"world\"");
    if (p.loads.tip_moment_frame == LoadFrame::kBody)
      out.push_back(
          "loads.tip_moment_frame: \"body\" (a follower moment) is not conservative; buckling "
          "on the \"quaternion-fd\" formulation needs \"world\"");
    // A moment of fixed direction on a free end is not conservative in 3-D either (Ziegler
    // 1977): the stiffness then says nothing about its stability.
    if (p.buckling.load == BucklingLoad::kTipMoment)
      out.push_back(
          "buckling.load: \"tip_moment\" (a moment of fixed direction) is not conservative in "
          "3-D; buckling under it runs on the \"se3-shooting\" formulation");
    else if (!p.loads.tip_moment.isZero(0.0))
      out.push_back(
          "loads.tip_moment: a tip moment of fixed direction is not conservative in 3-D; "
          "buckling on the \"quaternion-fd\" formulation needs it zero (\"se3-shooting\" "
          "takes it)");
  }
  if (p.analysis == A::kBuckling && quatfd &&
      (p.buckling.load == BucklingLoad::kTendonTension ||
       p.buckling.load == BucklingLoad::kPressure))
    out.push_back("buckling.load: " + detail::Quote(ToString(p.buckling.load)) +
                  " runs on the \"se3-shooting\" formulation only in this version");
  if (p.has_robot) {
    if (p.robot.kind == RobotKind::kEversion && p.analysis != A::kStatics)
      out.push_back(
          "robot.kind: an \"eversion\" robot runs in statics (quasi-static growth) only "
          "in this version");
    // A pneumatic robot is a rod of actuated rest strain (SectionLaw): the quaternion-FD model
    // takes it, at the one actuation it is built with (statics, modes).
    const bool quatfd_pneumatic = p.robot.kind == RobotKind::kPneumatic && p.rod.tendons.empty() &&
                                  (p.analysis == A::kStatics || p.analysis == A::kModes);
    if (quatfd && !quatfd_pneumatic)
      out.push_back(
          "robot: robots run on the \"se3-shooting\" formulation only in this version (a "
          "\"pneumatic\" robot without tendons also runs statics and modes on \"quaternion-fd\")");
    if (p.analysis == A::kModes && !p.rod.tendons.empty())
      out.push_back("robot: modes of a robot with tendons are not implemented in this version");
    if (p.robot.tendon_lengths && p.analysis != A::kStatics)
      out.push_back(
          "robot.actuation.length: displacement control runs in statics only in this "
          "version (use \"tension\" in dynamics)");
  }
  return out;
}

}  // namespace cosserat::io
