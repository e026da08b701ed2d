#pragma once
/// \file
/// The anchor force of a rod held at both ends, as the one-line summaries print it.

#include <string>

#include "cosserat/state/rod_state.hpp"

namespace cosserat::run::detail {

/// "anchor force [fx, fy, fz] N (tension |f| N)": the force the tip's anchor exerts on the rod
/// (world frame). When it pushes into the rod along the tip's tangent (the axial force
/// n·t < 0), "(compression, axial force n·t N)" instead: a line held in compression is not
/// hanging as a cable does.
std::string AnchorForceText(const RodState& state);

}  // namespace cosserat::run::detail
