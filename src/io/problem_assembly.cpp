#include "problem_assembly.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "problem_rod.hpp"
#include "read_pose.hpp"

namespace cosserat::io::detail {
namespace {

using json = nlohmann::json;

/// The rods that set a body's pose in the inverse problem: one length per degree of freedom.
constexpr int kRodsPerBodyInverse = 6;

/// tip.joint's names, in TipJoint's order.
const std::vector<std::string>& TipJointNames() {
  static const std::vector<std::string> names{"free", "clamped", "torsion_free", "pinned"};
  return names;
}

/// The objects of the array at `key`, each read at its own index; a non-array, an empty array or
/// a non-object element is reported.
std::vector<ObjectReader> ReadObjects(const ObjectReader& o, const std::string& key,
                                      const std::string& expected) {
  std::vector<ObjectReader> out;
  const json* v = o.Find(key);
  if (!v) {
    o.report().Missing(o.PathOf(key), expected);
    return out;
  }
  if (!v->is_array() || v->empty()) {
    o.report().Expected(o.PathOf(key), expected, Describe(*v));
    return out;
  }
  for (std::size_t i = 0; i < v->size(); ++i) {
    const std::string path = ElementPath(o.PathOf(key), i);
    if ((*v)[i].is_object())
      out.emplace_back((*v)[i], path, &o.report());
    else
      o.report().Expected(path, "an object", Describe((*v)[i]));
  }
  return out;
}

/// "name": a non-empty string no earlier element has (`seen`: name -> path of its owner).
std::string ReadUniqueName(const ObjectReader& o, const std::string& what,
                           std::map<std::string, std::string>* seen) {
  const std::optional<std::string> name = ReadString(o, "name", Presence::kRequired);
  if (!name) return "";
  if (name->empty()) {
    o.Reject("name", "a non-empty name");
  } else if (const auto it = seen->find(*name); it != seen->end()) {
    o.report().Expected(o.PathOf("name"),
                        "a name no other " + what + " has (each " + what + " appears once)",
                        Quote(*name) + ", already the name of " + it->second);
  } else {
    (*seen)[*name] = o.path();
  }
  return *name;
}

/// The index of the body named at `key`, or -1 (reported).
int FindBody(const ObjectReader& o, const std::string& key, const std::vector<RigidBody>& bodies) {
  const std::optional<std::string> name = ReadString(o, key, Presence::kRequired);
  if (!name) return -1;
  std::vector<std::string> names;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (bodies[b].name == *name) return static_cast<int>(b);
    names.push_back(bodies[b].name);
  }
  o.report().Add(o.PathOf(key),
                 "names " + Quote(*name) + ", but " +
                     (names.empty() ? std::string("there are no bodies (assembly.bodies)")
                                    : "the bodies are " + QuotedList(names)));
  return -1;
}

RigidBody ParseBody(const ObjectReader& o, std::map<std::string, std::string>* names,
                    Problem::AssemblyProblem* spec) {
  o.AllowOnly({"name", "mass", "inertia", "pose", "force", "moment", "initial_force",
               "initial_moment"});
  RigidBody body;
  body.name = ReadUniqueName(o, "body", names);
  body.mass = ReadNumber(o, "mass", NonNegativeNumber(), Presence::kOptional).value_or(0.0);
  if (const auto pose = ReadObject(o, "pose", Presence::kOptional)) {
    pose->AllowOnly({"position", "rotation"});
    body.pose = ReadPose(*pose);
  }
  body.force_W = ReadVec3(o, "force", Presence::kOptional).value_or(Vec3::Zero());
  body.moment_W = ReadVec3(o, "moment", Presence::kOptional).value_or(Vec3::Zero());
  const NumberRule moment{"a principal moment of inertia >= 0 (kg·m², body frame)",
                          [](double x) { return x >= 0; }};
  if (const auto inertia = ReadVec3(o, "inertia", Presence::kOptional, moment))
    body.inertia_B = inertia->asDiagonal();
  spec->initial_force.push_back(
      ReadVec3(o, "initial_force", Presence::kOptional).value_or(body.force_W));
  spec->initial_moment.push_back(
      ReadVec3(o, "initial_moment", Presence::kOptional).value_or(body.moment_W));
  return body;
}

/// "base": {"position", "rotation", "joint"}.
/// "base": {"position", "rotation", "joint", "body"}: the pose in the world, or in the frame of
/// the body it names.
void ParseRodBase(const ObjectReader& base, const std::vector<RigidBody>& bodies,
                  AssemblyRod* rod) {
  base.AllowOnly({"position", "rotation", "joint", "body"});
  rod->base = ReadPose(base);
  if (base.Has("body")) rod->base_body = FindBody(base, "body", bodies);
  const auto joint = ReadChoice(base, "joint", {"clamped", "torsion_free"}, Presence::kOptional);
  rod->base_joint =
      joint == std::string("torsion_free") ? BaseJoint::kTorsionFree : BaseJoint::kClamped;
}

/// "tip": {"joint", "body", "attachment"}; a joined tip names its body, a free one none.
void ParseRodTip(const ObjectReader& tip, const std::vector<RigidBody>& bodies, AssemblyRod* rod) {
  tip.AllowOnly({"joint", "body", "attachment"});
  const std::vector<std::string>& joints = TipJointNames();
  const auto joint = ReadChoice(tip, "joint", joints, Presence::kOptional);
  if (joint)
    rod->tip_joint =
        static_cast<TipJoint>(std::find(joints.begin(), joints.end(), *joint) - joints.begin());
  if (tip.Has("joint") && !joint) return;  // reported; the rest would only echo it
  const std::string joint_name = joint.value_or("free");
  if (rod->tip_joint == TipJoint::kFree) {
    for (const char* key : {"body", "attachment"})
      if (tip.Has(key))
        tip.report().Add(tip.PathOf(key), std::string("a \"free\" tip joins no body (set ") +
                                              "tip.joint to \"clamped\", \"torsion_free\" or "
                                              "\"pinned\", or leave " +
                                              key + " out)");
    return;
  }
  if (!tip.Has("body")) {
    tip.report().Missing(tip.PathOf("body"),
                         "the name of the body a " + Quote(joint_name) + " tip is joined to");
    return;
  }
  rod->body = FindBody(tip, "body", bodies);
  if (const auto attachment = ReadObject(tip, "attachment", Presence::kOptional)) {
    attachment->AllowOnly({"position", "rotation"});
    rod->attachment = ReadPose(*attachment);
  }
}

AssemblyRod ParseAssemblyRod(const ObjectReader& o, const std::vector<RigidBody>& bodies,
                             std::map<std::string, std::string>* names) {
  o.AllowOnly({"name", "rod", "base", "tip"});
  AssemblyRod rod;
  rod.name = ReadUniqueName(o, "rod", names);
  if (const auto model = ReadObject(o, "rod", Presence::kRequired)) {
    Problem single;  // the top-level "rod" parser, on a problem of its own
    ParseRod(*model, &single);
    rod.model = single.rod;
    rod.nodes = single.nodes;
  }
  if (const auto base = ReadObject(o, "base", Presence::kOptional))
    ParseRodBase(*base, bodies, &rod);
  if (const auto tip = ReadObject(o, "tip", Presence::kOptional)) ParseRodTip(*tip, bodies, &rod);
  if (rod.base_joint == BaseJoint::kTorsionFree && rod.tip_joint != TipJoint::kClamped)
    o.report().Expected(o.PathOf("base") + ".joint",
                        "\"clamped\" unless the tip is clamped (a rod free to turn at both ends "
                        "would spin about itself)",
                        "\"torsion_free\" with a " +
                            Quote(TipJointNames()[static_cast<int>(rod.tip_joint)]) + " tip");
  return rod;
}

/// "lengths": one positive length per rod.
std::vector<double> ParseLengths(const ObjectReader& o, std::size_t rods) {
  const std::string path = o.PathOf("lengths");
  const json& v = *o.Find("lengths");
  if (!v.is_array() || v.size() != rods) {
    o.report().Expected(
        path, "an array of one length per rod (" + std::to_string(rods) + " in assembly.rods), m",
        Describe(v));
    return {};
  }
  std::vector<double> lengths;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (const auto L = CheckNumber(v[i], ElementPath(path, i), PositiveNumber(), o.report()))
      lengths.push_back(*L);
  return lengths.size() == rods ? lengths : std::vector<double>{};
}

/// The inverse problem's structure: every rod joined, six to each body.
void CheckInverseStructure(const ObjectReader& o, const Assembly& a) {
  std::vector<int> count(a.bodies.size(), 0);
  for (std::size_t i = 0; i < a.rods.size(); ++i) {
    if (a.rods[i].body >= 0) ++count[a.rods[i].body];
    if (a.rods[i].tip_joint == TipJoint::kFree)
      o.report().Expected(o.PathOf("inverse"),
                          "every rod joined to a body (a free rod's length moves no body)",
                          "a free tip on assembly.rods[" + std::to_string(i) + "]");
  }
  for (std::size_t b = 0; b < a.bodies.size(); ++b)
    if (count[b] != kRodsPerBodyInverse)
      o.report().Expected(o.PathOf("inverse"),
                          "six rods joined to each body (their lengths set its six degrees of "
                          "freedom)",
                          std::to_string(count[b]) + " on " + Quote(a.bodies[b].name));
}

/// "inverse": {"poses": [{"body", "position", "rotation"}, ...]}, one pose per body.
std::vector<lie::SE3> ParseInverse(const ObjectReader& inverse, const Assembly& a) {
  inverse.AllowOnly({"poses"});
  std::vector<std::optional<lie::SE3>> poses(a.bodies.size());
  const std::vector<ObjectReader> given =
      ReadObjects(inverse, "poses", "an array of poses {\"body\", \"position\", \"rotation\"}");
  bool ok = !given.empty();  // else reported
  for (const ObjectReader& pose : given) {
    pose.AllowOnly({"body", "position", "rotation"});
    const int b = FindBody(pose, "body", a.bodies);
    const lie::SE3 value = ReadPose(pose);
    if (b < 0) {
      ok = false;
    } else if (poses[b]) {
      pose.report().Expected(pose.PathOf("body"), "one pose per body",
                             "a second pose for " + Quote(a.bodies[b].name));
      ok = false;
    } else {
      poses[b] = value;
    }
  }
  std::vector<lie::SE3> out;
  for (std::size_t b = 0; b < poses.size(); ++b) {
    if (poses[b]) {
      out.push_back(*poses[b]);
    } else if (ok) {
      inverse.report().Expected(inverse.PathOf("poses"), "one pose per body",
                                "none for " + Quote(a.bodies[b].name));
      ok = false;
    }
  }
  return ok ? out : std::vector<lie::SE3>{};
}

}  // namespace

const std::vector<std::string>& SingleRodKeys() {
  static const std::vector<std::string> keys{
      "rod", "base", "boundary", "anchor", "robot", "buckling", "modes", "environment"};
  return keys;
}

void CheckAssemblyDynamics(const ObjectReader& dynamics) {
  for (const char* key : {"tip_mass", "tip_inertia", "base_spin", "rotary_table",
                          "shooting_segments", "integrator_tolerance", "integrator_max_steps"})
    if (dynamics.Has(key))
      dynamics.report().Add(dynamics.PathOf(key),
                            "not read with \"assembly\" (a body carries mass and inertia: "
                            "assembly.bodies[i].mass and .inertia)");
}

void CheckAssemblyLoads(const ObjectReader& loads) {
  for (const char* key :
       {"tip_force", "tip_moment", "tip_force_frame", "tip_moment_frame", "bit_friction"})
    if (loads.Has(key))
      loads.report().Add(loads.PathOf(key),
                         "not read with \"assembly\" (load a body instead: assembly.bodies[i]"
                         ".force and .moment)");
}

void ParseAssembly(const ObjectReader& o, Problem* p) {
  o.AllowOnly({"rods", "bodies", "lengths", "inverse"});
  Assembly& a = p->assembly.assembly;
  std::map<std::string, std::string> body_names, rod_names;
  if (o.Has("bodies"))
    for (const ObjectReader& body : ReadObjects(o, "bodies", "an array of bodies"))
      a.bodies.push_back(ParseBody(body, &body_names, &p->assembly));
  for (const ObjectReader& rod : ReadObjects(o, "rods", "an array of rods"))
    a.rods.push_back(ParseAssemblyRod(rod, a.bodies, &rod_names));
  p->has_assembly = true;

  std::vector<int> held(a.bodies.size(), 0);
  for (const AssemblyRod& rod : a.rods) {
    if (rod.body >= 0) ++held[rod.body];
    if (rod.base_body >= 0) ++held[rod.base_body];
  }
  for (std::size_t b = 0; b < a.bodies.size(); ++b)
    if (held[b] == 0)
      o.report().Add(ElementPath(o.PathOf("bodies"), b),
                     "no rod holds " + Quote(a.bodies[b].name) +
                         " (no rod names it in tip.body or base.body; it would fall freely)");
  // Statics needs every body joined to the world by a chain of rods (a rod joins its base's body,
  // or the world, to its tip's body): a body that only carries rods hanging from it, or bodies
  // joined only to each other, float, and the load steps found nothing.
  if (p->analysis == Analysis::kStatics) {
    std::vector<bool> grounded(a.bodies.size(), false);
    for (bool changed = true; changed;) {
      changed = false;
      for (const AssemblyRod& rod : a.rods) {
        if (rod.body < 0) continue;
        const bool base = rod.base_body < 0 || grounded[rod.base_body];
        if (base != grounded[rod.body]) {
          if (rod.base_body >= 0) grounded[rod.base_body] = true;
          grounded[rod.body] = true;
          changed = true;
        }
      }
    }
    for (std::size_t b = 0; b < a.bodies.size(); ++b)
      if (held[b] > 0 && !grounded[b])
        o.report().Add(ElementPath(o.PathOf("bodies"), b),
                       "no chain of rods joins " + Quote(a.bodies[b].name) +
                           " to the world (a rod from the world, or from a body that is, must "
                           "end on it or on a body joined to it): in statics it floats "
                           "(dynamics runs a free assembly)");
  }

  if (o.Has("lengths") && o.Has("inverse"))
    o.report().Add(o.PathOf("lengths"),
                   "not read with \"inverse\" (the inverse problem solves "
                   "the lengths)");
  else if (o.Has("lengths") && !a.rods.empty())
    p->assembly.lengths = ParseLengths(o, a.rods.size());
  if (const auto inverse = ReadObject(o, "inverse", Presence::kOptional)) {
    CheckInverseStructure(o, a);
    p->assembly.inverse_poses = ParseInverse(*inverse, a);
  }
}

std::vector<std::string> UnsupportedAssemblyFeatures(const Problem& p) {
  // Statics and dynamics on the SE(3) path (docs/assemblies.md, "Limits").
  std::vector<std::string> out;
  if (p.analysis != Analysis::kStatics && p.analysis != Analysis::kDynamics)
    out.push_back("analysis: " + Quote(ToString(p.analysis)) +
                  " of an \"assembly\" is not implemented in this version (supported: "
                  "\"statics\", \"dynamics\")");
  if (p.analysis == Analysis::kDynamics) {
    if (p.assembly.inverse())
      out.push_back("assembly.inverse: not read in dynamics (the forward problem only: the "
                    "rods' lengths are their rod.length)");
    if (!p.assembly.lengths.empty())
      out.push_back("assembly.lengths: not read in dynamics (each rod's length is its "
                    "rod.length)");
    const auto& rods = p.assembly.assembly.rods;
    for (std::size_t i = 0; i < rods.size(); ++i)
      if (rods[i].base_joint != BaseJoint::kClamped)
        out.push_back("assembly.rods[" + std::to_string(i) +
                      "].base.joint: \"torsion_free\" is statics only (dynamics clamps each "
                      "base)");
  }
  if (p.formulation != Formulation::kSe3Shooting)
    out.push_back("formulation: " + Quote(ToString(p.formulation)) +
                  " of an \"assembly\" is not implemented in this version (supported: "
                  "\"se3-shooting\")");
  return out;
}

}  // namespace cosserat::io::detail
