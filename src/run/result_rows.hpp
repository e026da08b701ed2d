#pragma once
/// \file
/// Reading a result document back: its [x, y, z] rows as vectors, and whether it holds an
/// equilibrium, for the checks and notes that run after a solve.

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

#include "cosserat/lie/types.hpp"
#include "cosserat/run/result.hpp"

namespace cosserat::run::detail {

/// A row [x, y, z] as a vector; NaN where the document has null (how it writes NaN).
inline Vec3 VectorAt(const nlohmann::ordered_json& row) {
  Vec3 v;
  for (int k = 0; k < 3; ++k) v(k) = row[k].is_number() ? row[k].get<double>() : NAN;
  return v;
}

/// Every row of an array of [x, y, z] rows, as VectorAt reads them.
inline std::vector<Vec3> Vectors(const nlohmann::ordered_json& rows) {
  std::vector<Vec3> out;
  out.reserve(rows.size());
  for (const auto& row : rows) out.push_back(VectorAt(row));
  return out;
}

/// Whether the result holds an equilibrium: converged, or converged on a grid too coarse for it
/// (status "under_resolved"); not a shot that ran away or a solve that stopped short.
inline bool HoldsEquilibrium(const Result& result) {
  return result.converged || result.json.value("status", "") == "under_resolved";
}

}  // namespace cosserat::run::detail
