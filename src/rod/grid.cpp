#include "cosserat/rod/grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosserat {

std::vector<double> MakeGrid(double length, int num_nodes, std::vector<double> breakpoints) {
  const double eps = 1e-12 * length;
  std::vector<double> cuts{0.0};
  std::sort(breakpoints.begin(), breakpoints.end());
  for (double b : breakpoints)
    if (b > eps && b < length - eps && b - cuts.back() > eps) cuts.push_back(b);
  cuts.push_back(length);

  const int pieces = static_cast<int>(cuts.size()) - 1;
  const int segments = num_nodes - 1;
  if (segments < pieces)
    throw std::invalid_argument("MakeGrid: " + std::to_string(num_nodes) + " nodes cannot hold " +
                                std::to_string(pieces - 1) + " breakpoints");

  // One segment per piece, then hand out the rest by largest remaining length per segment.
  std::vector<int> count(pieces, 1);
  for (int extra = segments - pieces; extra > 0; --extra) {
    int best = 0;
    double best_h = -1.0;
    for (int k = 0; k < pieces; ++k) {
      const double h = (cuts[k + 1] - cuts[k]) / count[k];
      if (h > best_h) best_h = h, best = k;
    }
    ++count[best];
  }

  std::vector<double> s;
  s.reserve(num_nodes);
  for (int k = 0; k < pieces; ++k)
    for (int j = 0; j < count[k]; ++j)
      s.push_back(cuts[k] + (cuts[k + 1] - cuts[k]) * j / count[k]);
  s.push_back(length);
  return s;
}

std::vector<double> ModelGrid(const RodModel& model, int num_nodes) {
  std::string why;
  if (!model.IsValid(&why)) throw std::invalid_argument("RodModel: " + why);
  if (num_nodes < 2) throw std::invalid_argument("num_nodes must be at least 2");
  return MakeGrid(model.length, num_nodes, model.Breakpoints());
}

std::vector<double> SegmentSamplePoints(const std::vector<double>& grid) {
  std::vector<double> at;
  at.reserve(3 * grid.size());
  for (size_t i = 0; i + 1 < grid.size(); ++i) {
    const double a = grid[i], b = grid[i + 1], h = b - a;
    at.push_back(a);
    at.push_back(a + 0.5 * h);
    at.push_back(b - 1e-9 * h);
  }
  return at;
}

}  // namespace cosserat
