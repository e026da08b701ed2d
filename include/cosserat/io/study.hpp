#pragma once
/// \file
/// A study (`cosserat sweep STUDY.json`, docs/sweeps.md): a base problem, the parameters to vary
/// in it by JSON pointer, and the outputs to collect from each point's result, also by pointer.
///
///   {"format": "cosserat-study/1",
///    "problem": "robots/tendon_three_tendon.json"            (a path, relative to the study, or
///                                                             the problem object itself),
///    "parameters": [
///      {"path": "/robot/actuation/tension/0", "grid": {"from": 0, "to": 2, "count": 11}},
///      {"path": "/rod/material/youngs_modulus", "values": [2.0e11, 2.1e11]},
///      {"path": "/loads/tip_force/0", "random": {"distribution": "uniform", "low": -0.1, "high": 0.1}}],
///    "samples": 10, "seed": 7,                               (random draws per grid point)
///    "outputs": {"tip_x": "/tip/position/0", "status": "/status"}}
///
/// Points: the Cartesian product of the grid and list parameters (the first varying slowest),
/// each repeated `samples` times with fresh random draws. Point k's draws depend only on the
/// seed, k and the parameter's index (a counter-based generator), so any process or thread
/// computes the same point k.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace cosserat::io {

/// The most points a study may have (samples × the grids' counts): a sweep keeps each point's
/// row in memory, ~100 bytes, so this bounds it near a gigabyte.
constexpr std::uint64_t kMaxStudyPoints = 10'000'000;

struct StudyParameter {
  std::string path;            ///< JSON pointer into the problem document
  std::vector<double> values;  ///< a grid's or a list's values; empty for a random parameter
  enum class Distribution { kNone, kUniform, kNormal };
  Distribution distribution = Distribution::kNone;
  double a = 0.0, b = 0.0;  ///< uniform: [low, high); normal: mean, standard deviation
};

struct StudyOutput {
  std::string name;  ///< the CSV column
  std::string path;  ///< JSON pointer into the result document
};

struct Study {
  nlohmann::json problem;  ///< the base problem document
  std::vector<StudyParameter> parameters;
  std::vector<StudyOutput> outputs;
  int samples = 1;
  std::uint64_t seed = 1;

  std::uint64_t PointCount() const;
  /// The parameter values of point k, in the parameters' order.
  std::vector<double> Point(std::uint64_t k) const;
  /// The problem document of point k: the base with the point's values set.
  nlohmann::json PointProblem(std::uint64_t k) const;
};

struct StudyParseResult {
  std::optional<Study> study;       ///< set exactly when there are no errors
  std::vector<std::string> errors;  ///< one line per problem, naming the field
};

/// Parses a study; a relative problem path is read from `base_directory`. Checks every
/// parameter's path against the base problem (its parent must exist, and some point, of up to
/// 64 spread over the study, must be a valid problem), ranges and distributions.
StudyParseResult ParseStudy(const std::string& json_text, const std::string& source_name,
                            const std::string& base_directory);
StudyParseResult LoadStudyFile(const std::string& path);

/// Point k's parameter values in words: "/rod/length = 0.4, /loads/tip_force/2 = -60".
std::string PointWords(const Study& study, std::uint64_t k);

/// The study's first `limit` points (all when fewer) checked as problems: how many were checked,
/// how many are invalid (each runs as a row whose status gives the reason), and the first
/// invalid one's index and first error.
struct StudyPointCheck {
  std::uint64_t checked = 0, invalid = 0, first = 0;
  std::string first_error;
};
StudyPointCheck CheckStudyPoints(const Study& study, std::uint64_t limit);

}  // namespace cosserat::io
