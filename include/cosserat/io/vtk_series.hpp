#pragma once
/// \file
/// A ParaView time series of rod states: one VTK XML PolyData file (.vtp) per frame, each rod a
/// polyline piece, and a .pvd collection that lists every frame with its time. ParaView opens the
/// .pvd; its Tube filter, sized by the "radius" point data, draws the rods as tubes.
///
/// Point data per node (world frame unless the name says otherwise):
///   rod (the rod's index in the frame), s (m), radius (m: the section's outer radius), d1, d2,
///   d3 (the section's directors, the columns of R_WB), curvature (body frame K, 1/m),
///   shear_stretch (body frame Γ), force (the internal force R n, N), moment (the internal
///   moment R m, N·m), velocity (R v, m/s), and with contact surfaces contact_force (N/m).
/// Positions and values are written as text with 17 significant digits: read back, they are the
/// doubles that were written.

#include <string>
#include <vector>

#include "cosserat/lie/se3.hpp"
#include "cosserat/state/rod_state.hpp"

namespace cosserat::io {

/// One output frame: its time and the state of every rod in it.
struct VtkFrame {
  double t = 0.0;  ///< s
  std::vector<RodState> rods;
  /// With contact surfaces: each rod's contact force per unit length at its nodes (N/m, world),
  /// written as the point data "contact_force"; empty otherwise.
  std::vector<std::vector<Vec3>> contact_force;
  /// An assembly's rigid bodies: their poses (world) and velocities (m/s, world), written as the
  /// separate series `stem`_bodies (one vertex per body); empty for a single rod.
  std::vector<lie::SE3> bodies;
  std::vector<Vec3> body_velocity_W;
  /// Each rod's outer radius at its nodes in this frame (m), where the nodes change between
  /// frames (a growing body); empty: the series' `radius`.
  std::vector<std::vector<double>> radius;
};

/// Writes `directory`/`stem`_NNNNNN.vtp for every frame and `directory`/`stem`.pvd listing them
/// (the directory is created if missing); with bodies, `stem`_bodies.pvd and its frames too.
/// `radius[r]` holds rod r's outer radius at each of its nodes (m), unless the frame holds its
/// own. Returns false with *error set
/// ("<path>: <why>") when a file cannot be written.
bool WriteVtkSeries(const std::string& directory, const std::string& stem,
                    const std::vector<VtkFrame>& frames,
                    const std::vector<std::vector<double>>& radius, std::string* error);

}  // namespace cosserat::io
