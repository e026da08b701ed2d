#include "contact_report.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cosserat/loads/contact.hpp"
#include "cosserat/loads/total_load.hpp"
#include "cosserat/rod/grid.hpp"
#include "foundation_hint.hpp"
#include "result_rows.hpp"

namespace cosserat::run::detail {

namespace {

// The statics node table (one row per node, header "s,x,y,z,…") gets the contact force per unit
// length as three more columns. The dynamics trajectory table is left as it is.
void AppendContactColumns(const nlohmann::ordered_json& per_node, std::string* csv) {
  if (csv->rfind("s,", 0) != 0) return;
  std::istringstream in(*csv);
  std::ostringstream out;
  std::string line;
  std::getline(in, line);
  out << line << ",contact_fx,contact_fy,contact_fz\n";
  out.precision(17);
  for (const auto& f : per_node) {
    if (!std::getline(in, line)) return;  // rows do not match the nodes: leave the table alone
    out << line << ',' << f[0].get<double>() << ',' << f[1].get<double>() << ','
        << f[2].get<double>() << '\n';
  }
  *csv = out.str();
}

/// The contact force per unit length on the node at arc length s, position p and velocity v
/// (world): its section's outer diameter meets the surfaces.
Vec3 NodeContactForce_W(const io::Problem& problem, const PenaltyContact& contact, double s,
                        const Vec3& p, const Vec3& v) {
  const double d = problem.rod.section->At(s, problem.robot.actuation).outer_diameter;
  return contact.MotionForce_W({s, 1.0, 0.0, d}, {p, Vec3::UnitZ(), v}, nullptr);
}

/// SE(3) statics: the contact force the solver applied, from the rod's balance. Along the shot
/// d(R n)/ds = −f, so ∫ f = R n(0) − R n(L) = −(base reaction) − R n(L), to RK4's order in s
/// (it carries n in the body frame and integrates R, so the balance is O(h⁴), not exact), with
/// the contact at the stages' own poses: a contact concentrated in a segment or two, which the
/// node values resolve badly, comes out as the solver pressed it. Less the dead loads, on the
/// solver's own samples and Simpson weights, it is the surfaces' force. False where the balance
/// does not give it: quaternion FD (which lumps the contact on the nodes, so the trapezoid is
/// its own sum), dynamics, tendons (their loads on the backbone are internal), and other loads
/// that depend on the pose (a current's drag, which would have to be subtracted by a quadrature
/// of its own).
bool BalancedContactTotal(const io::Problem& problem, const nlohmann::ordered_json& json,
                          Vec3* total) {
  using io::Analysis;
  if (problem.formulation != io::Formulation::kSe3Shooting || problem.has_assembly ||
      !problem.rod.tendons.empty() || HasDrag(problem.loads) ||
      (problem.analysis != Analysis::kStatics && problem.analysis != Analysis::kModes))
    return false;
  if (!json.contains("base_wrench") || !json.contains("tip") ||
      !json["nodes"].contains("force_body"))
    return false;
  const auto& s = json["nodes"]["s"];
  const std::size_t n = s.size();
  Mat3 R_tip;
  for (int i = 0; i < 3; ++i) R_tip.row(i) = VectorAt(json["tip"]["rotation"][i]).transpose();
  const Vec3 applied = -VectorAt(json["base_wrench"]["force"]) -
                       R_tip * VectorAt(json["nodes"]["force_body"][n - 1]);
  std::vector<double> grid(n);
  for (std::size_t i = 0; i < n; ++i) grid[i] = s[i].get<double>();
  const std::vector<double> samples = SegmentSamplePoints(grid);  // start, middle, end
  Vec3 dead = Vec3::Zero();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double h = grid[i + 1] - grid[i];
    const double w[3] = {h / 6, 4 * h / 6, h / 6};
    for (int j = 0; j < 3; ++j) {
      const double sj = samples[3 * i + j];
      const SectionProperties sp = problem.rod.section->At(sj, problem.robot.actuation);
      dead += w[j] * TotalDistributedForce_W(problem.loads,
                                             LoadSite{sj, 1.0, sp.mass(5, 5), sp.outer_diameter});
    }
  }
  *total = applied - dead;
  return total->allFinite();
}

/// Statics, buckling and the equilibrium of modes leave contact friction out (Coulomb friction
/// of a regularised slip law needs a velocity); a surface given friction there is told so.
std::string StaticFrictionNote(const io::Problem& problem) {
  if (problem.analysis == io::Analysis::kDynamics) return "";
  for (int k = 0; k < problem.loads.contact.count; ++k) {
    const double mu = problem.loads.contact.surface[k].friction;
    if (mu > 0.0) {
      std::ostringstream note;
      note << "cosserat: note: environment.contact[" << k << "].friction = " << mu
           << " acts in dynamics only: at rest the surfaces push along their normals alone, so "
              "the rod slides on them until its own stiffness and supports hold the loads along "
              "them\n";
      return note.str();
    }
  }
  // No friction given, and a current along a plane the rod may rest on (a pipe on a sea bed in
  // a cross current drifted 155 m sideways in statics, without a word).
  const Fluid& fluid = problem.loads.fluid;
  if (!fluid.present() || fluid.velocity_W.isZero(0.0)) return "";
  for (int k = 0; k < problem.loads.contact.count; ++k) {
    const ContactSurface& surface = problem.loads.contact.surface[k];
    if (surface.shape != ContactSurface::Shape::kPlane) continue;
    const Vec3& n = surface.direction_W;
    const Vec3 along = fluid.velocity_W - fluid.velocity_W.dot(n) * n;
    if (along.norm() <= 1e-6 * fluid.velocity_W.norm()) continue;
    std::ostringstream note;
    note << "cosserat: note: the current runs along environment.contact[" << k
         << "], and statics have no friction: what rests on it slides with the drag until the "
            "rod's supports and stiffness hold it; dynamics with a \"friction\" coefficient "
            "hold it in place\n";
    return note.str();
  }
  return "";
}

/// Whether the problem's tip force (world, or turned with the result's tip frame) pushes against
/// `push`, the surfaces' force at the tip, by a tenth of its size or more.
bool PressesTheTipIn(const io::Problem& problem, const nlohmann::ordered_json& json,
                     const Vec3& push) {
  Vec3 force = problem.loads.tip_force;  // N
  if (problem.loads.tip_force_frame == LoadFrame::kBody) {
    if (!json.contains("tip") || !json["tip"].contains("rotation")) return false;
    Mat3 R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = json["tip"]["rotation"][i][j].get<double>();
    force = R * force;
  }
  return push.norm() > 0.0 && force.dot(push.normalized()) < -0.1 * force.norm();
}

/// Where the nodes' contact forces, summed by the trapezoid rule, differ from the force the
/// solve applied by more than 5 %: a patch narrow for the grid, which RK4's stages between the
/// nodes see and the nodes do not (a finger on a sphere: 10 % at 11 nodes, 4 % at 21, 2.9 % at
/// 33, 1.3 % at 41: about as h, unevenly, as the nodes fall on the patch). A note with the nodes
/// that bring it to about 1 % at that rate; else empty.
/// A patch on one or two nodes at an end of the rod (a tip pressed on a surface: 200 % off at any
/// grid, as the end node's half interval takes the whole patch) is a point contact there, which
/// no grid samples: the note then says to read the total.
std::string SampledContactNote(const Vec3& sampled, const Vec3& applied, std::size_t nodes,
                               bool point_at_an_end) {
  const double off = (sampled - applied).norm() / applied.norm();
  if (!(off > 0.05) || nodes < 2) return "";
  std::ostringstream note;
  note << std::setprecision(3) << "cosserat: note: nodes.contact_force samples the contact at "
       << "the nodes, and their sum along s is " << 100 * off << " % off contact.total_force, "
       << "the force the solve applied: ";
  if (point_at_an_end)
    note << "the contact is a point at an end of the rod, which the nodes' values per metre do "
            "not resolve on any grid; contact.total_force is the force it carries\n";
  else
    note << "the contact patch is narrow for the grid; rod.nodes ≥ "
         << static_cast<long>(std::ceil((nodes - 1) * off / 0.01)) + 1
         << " samples it within about 1 %\n";
  return note.str();
}
/// The gap between the rod's surface and the nearest contact surface at a node, m (< 0: pressed
/// in), and whether that surface is convex towards the rod (a sphere, or a cylinder from outside).
double Gap(const io::Problem& problem, double s, const Vec3& p, bool* convex = nullptr) {
  const double r_o = 0.5 * problem.rod.section->At(s, problem.robot.actuation).outer_diameter;
  double gap = std::numeric_limits<double>::infinity();
  Vec3 normal;
  for (int k = 0; k < problem.loads.contact.count; ++k) {
    const ContactSurface& surface = problem.loads.contact.surface[k];
    const double g = surface.Distance(p, &normal) - r_o;
    if (g >= gap) continue;
    gap = g;
    if (convex)
        *convex = surface.shape == ContactSurface::Shape::kSphere ||
                (surface.shape == ContactSurface::Shape::kCylinder && !surface.inside);
  }
  return gap;
}

/// A patch of contact on at most kNarrowPatchNodes nodes is sampled where the nodes happen to
/// fall, so the force it carries and the shape near it change with the grid: a steel rod
/// (r 2 mm) pressed on a 1 mm ball over about 2.5 mm, on 101 nodes (h 5 mm), carries 1.9 % too
/// much and its tip falls 4.3 % short (quaternion FD; SE(3) on 201 nodes 1.4 % too far). The
/// patch's width comes from the gap's parabola through its deepest node and their neighbours;
/// the note names the nodes that put kNodesOnAPatch on it. Only on a convex surface, whose own
/// curve sets the width: on a plane or inside a bore a patch is narrow only under a point load
/// (a kink), whose width follows the grid. Not at the rod's ends. Empty where no patch is narrow.
constexpr int kNarrowPatchNodes = 3;
constexpr int kNodesOnAPatch = 5;
std::string NarrowPatchNote(const std::vector<double>& s, const std::vector<double>& gap,
                            const std::vector<bool>& touching, const std::vector<bool>& convex) {
  const int n = static_cast<int>(s.size());
  for (int first = 1; first + 1 < n; ++first) {
    if (!touching[first] || touching[first - 1]) continue;
    int last = first;
    while (last + 1 < n && touching[last + 1]) ++last;
    if (last - first + 1 > kNarrowPatchNodes || last == n - 1) continue;
    int deepest = first;
    for (int i = first; i <= last; ++i)
      if (gap[i] < gap[deepest]) deepest = i;
    if (!convex[deepest]) continue;
    // g(s) ≈ g0 + b x + a x² about the deepest node, x = s − s_deepest.
    const double x1 = s[deepest - 1] - s[deepest], x2 = s[deepest + 1] - s[deepest];
    const double d1 = (gap[deepest - 1] - gap[deepest]) / x1,
                 d2 = (gap[deepest + 1] - gap[deepest]) / x2;
    const double a = (d2 - d1) / (x2 - x1), b = d1 - a * x1;
    const double disc = b * b - 4 * a * gap[deepest];
    if (!(a > 0) || !(disc > 0) || !std::isfinite(disc)) continue;
    const double width = std::sqrt(disc) / a;  // m, between the gap's roots
    const double h = 0.5 * (s[deepest + 1] - s[deepest - 1]);  // m, the local spacing
    const long nodes = static_cast<long>(std::ceil(s.back() * kNodesOnAPatch / width)) + 1;
    if (!(width < kNodesOnAPatch * h) || nodes <= n) continue;  // the grid already holds it
    std::ostringstream note;
    note << std::setprecision(3) << "cosserat: note: the contact at s = " << s[deepest]
         << " m spans " << last - first + 1 << (last == first ? " node" : " nodes")
         << " of the grid (h = " << h << " m) and about " << width
         << " m of the rod: the force it carries and the shape near it depend on where the nodes "
            "fall; rod.nodes ≥ "
         << nodes << " puts "
         << kNodesOnAPatch << " on it\n";
    return note.str();
  }
  return "";
}

}  // namespace

double TouchdownS(const io::Problem& problem, const RodState& state) {
  double touchdown = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < state.size(); ++i) {
    const bool touching = Gap(problem, state.s[i], state.position_W[i]) < 0.0;
    if (touching) touchdown = state.s[i];
    if (!touching && !std::isnan(touchdown)) break;  // the end of the first stretch in contact
  }
  return touchdown;
}

void AddContactReport(const io::Problem& problem, Result* result) {
  if (problem.loads.contact.count == 0) return;
  result->log += StaticFrictionNote(problem);
  auto& json = result->json;
  if (!json.contains("nodes") || !json["nodes"].contains("position")) return;
  const auto& s = json["nodes"]["s"];
  const auto& position = json["nodes"]["position"];
  const PenaltyContact contact(problem.loads.contact);
  nlohmann::ordered_json per_node = nlohmann::ordered_json::array();
  nlohmann::ordered_json intervals = nlohmann::ordered_json::array();
  Vec3 total = Vec3::Zero(), previous = Vec3::Zero();
  double s_previous = 0.0, start = -1.0;
  const std::size_t n = s.size();
  std::vector<double> grid(n), gaps(n);
  std::vector<bool> in_contact(n), convex(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double si = s[i].get<double>();
    const Vec3 p = VectorAt(position[i]);
    const Vec3 v = result->node_velocity_W.size() == n ? result->node_velocity_W[i] : Vec3::Zero();
    const Vec3 f = NodeContactForce_W(problem, contact, si, p, v);
    per_node.push_back({f.x(), f.y(), f.z()});
    if (i > 0) total += 0.5 * (si - s_previous) * (f + previous);
    const bool touching = !f.isZero(0.0);
    grid[i] = si;
    bool on_convex = false;
    gaps[i] = Gap(problem, si, p, &on_convex);
    convex[i] = on_convex;
    in_contact[i] = touching;
    if (touching && start < 0) start = si;
    if (!touching && start >= 0) {
      intervals.push_back({start, s_previous});
      start = -1.0;
    }
    previous = f;
    s_previous = si;
  }
  // A tip force pressing the tip into a surface (the tip touches it, and a tenth of the force or
  // more pushes against the surface's push there): a point load on the foundation, whose layer
  // the grid must resolve (a load spread along the rod, a riser's weight, costs ~1e-5; a pull
  // along the surface nothing).
  const bool point_load_on_surface = start >= 0 && PressesTheTipIn(problem, json, previous);
  if (start >= 0) intervals.push_back({start, s_previous});
  if (point_load_on_surface && result->converged && problem.analysis == io::Analysis::kStatics &&
      problem.formulation == io::Formulation::kQuaternionFd)
    result->log += FoundationGridWarning(problem);
  // A solve that stopped short applied a part of the loads: its nodes' sum is no sampling.
  const std::string narrow =
      result->converged ? NarrowPatchNote(grid, gaps, in_contact, convex) : "";
  result->log += narrow;
  Vec3 balanced;
  if (BalancedContactTotal(problem, json, &balanced)) {
    // The nodes in contact: the end node, or it and its neighbour, and none elsewhere, at either
    // end, is a point there.
    const auto touching = std::count(in_contact.begin(), in_contact.end(), true);
    const bool point_at_an_end =
        n > 4 && ((in_contact[0] && touching == 1 + (in_contact[1] ? 1 : 0)) ||
                  (in_contact[n - 1] && touching == 1 + (in_contact[n - 2] ? 1 : 0)));
    if (result->converged) result->log += SampledContactNote(total, balanced, n, point_at_an_end);
    total = balanced;
  }
  AppendContactColumns(per_node, &result->nodes_csv);
  json["nodes"]["contact_force"] = per_node;
  json["contact"] = {{"total_force", {total.x(), total.y(), total.z()}}, {"intervals", intervals}};
}

void AddFrameContactForces(const io::Problem& problem, Result* result) {
  if (problem.loads.contact.count == 0 || result->frames.empty() || problem.has_assembly) return;
  const PenaltyContact contact(problem.loads.contact);
  for (io::VtkFrame& frame : result->frames) {
    frame.contact_force.clear();
    for (const RodState& st : frame.rods) {
      std::vector<Vec3> f(st.size());
      for (int i = 0; i < st.size(); ++i)
        f[i] = NodeContactForce_W(problem, contact, st.s[i], st.position_W[i],
                                  st.rotation_WB[i] * st.twist_B[i].tail<3>());
      frame.contact_force.push_back(std::move(f));
    }
  }
}

}  // namespace cosserat::run::detail
