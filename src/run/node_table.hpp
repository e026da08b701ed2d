#pragma once
/// \file
/// The node tables of Result::nodes_csv, as text.

#include <sstream>
#include <string>
#include <vector>

#include "cosserat/io/result_writer.hpp"

namespace cosserat::run::detail {

/// io::WriteNodesCsv into a string.
inline std::string NodesCsv(const RodState& state) {
  std::ostringstream out;
  io::WriteNodesCsv(out, state);
  return out.str();
}

/// io::WriteTrajectoryCsv into a string.
inline std::string TrajectoryCsv(const io::DynamicRun& run, const std::vector<double>& grid) {
  std::ostringstream out;
  io::WriteTrajectoryCsv(out, run, grid);
  return out.str();
}

}  // namespace cosserat::run::detail
