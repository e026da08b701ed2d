#pragma once
/// \file
/// The explicit Runge–Kutta schemes the dynamic shot integrates with in s (bdf2_stepper.hpp).
///
/// All are of the form where stage j sits at y + a_j h k_{j−1} (a_0 = 0) and
/// y_{i+1} = y_i + h Σ_j b_j k_j, so one loop serves them. BDF2 keeps its history at every stage
/// point, and the rod's integrals (mass, momentum, energy) use the weights b_j at the stage
/// points: the linear-momentum balance n_W' = −f + ρA a_W is then summed by exactly the
/// quadrature the shot uses, and momentum stays conserved to round-off with any scheme.
///
/// Choosing (docs/dynamics.md, "Choosing the scheme in s"): RK4 is order 4 in s; Heun (explicit
/// trapezoid) is order 2 for half the stage evaluations, the same order as BDF2 in time; RK4
/// across pairs of segments is order 4 for Heun's stage evaluations where the pair is short
/// against the step's exponent (2hλ ≤ ½) and plain RK4 elsewhere, the default. On the peer rod
/// (steel, L = 0.5 m, 40 nodes, dt = 2 ms) the pairs' spatial error is 1/1000 of BDF2's time error
/// at 62 % of RK4's cost (BENCHMARKS.md). Statics (static_shooting.hpp) always uses RK4.

#ifdef __GNUC__
#define COSSERAT_SCHEME_INLINE inline __attribute__((always_inline))
#else
#define COSSERAT_SCHEME_INLINE inline
#endif

namespace cosserat {

enum class SpatialScheme {
  kRk4,   ///< classic RK4: 4 stage evaluations per segment, order 4
  kHeun,  ///< Heun / explicit trapezoid: 2 stage evaluations per segment, order 2
  /// RK4 across pairs of equal segments: 4 stage evaluations per pair (2 per segment, as Heun),
  /// order 4 in the pair's length; the node between is RK4's dense output at θ = ½. A pair forms
  /// only where 2hλ ≤ ½ and not over a section breakpoint; RK4 on the other segments (the default)
  kRk4Pairs,
};

namespace internal {

/// Stage j of the step from node i (h: the step's length, one segment or a pair): state
/// y_i + step[j] h k_{j−1}; section sample 3 i + sample[j] (3 samples per segment: start,
/// middle, end, as SegmentSamplePoints lays them out; 3 and 5 are the next segment's start and
/// end); quadrature weight weight[j] (times h). Offset in s of stage j: step[j] h.
struct SchemeTable {
  int stages;
  double step[4];
  int sample[4];
  double weight[4];
};

inline constexpr SchemeTable kRk4Table{
    4, {0.0, 0.5, 0.5, 1.0}, {0, 1, 1, 2}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}};
inline constexpr SchemeTable kHeunTable{2, {0.0, 1.0, 0, 0}, {0, 2, 0, 0}, {0.5, 0.5, 0, 0}};
/// RK4 over the pair of segments i, i + 1 (h: the pair's length): the middle stages sit on node
/// i + 1 (sample 3 = the second segment's start), the last at the pair's end (sample 5).
inline constexpr SchemeTable kRk4PairTable{
    4, {0.0, 0.5, 0.5, 1.0}, {0, 3, 3, 5}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}};

constexpr const SchemeTable& Table(SpatialScheme s) {
  return s == SpatialScheme::kHeun       ? kHeunTable
         : s == SpatialScheme::kRk4Pairs ? kRk4PairTable
                                         : kRk4Table;
}

/// The scheme's vector operations on a shot's point (cosserat_rhs.hpp), which is a packed array
/// of doubles: one flat loop per operation, which the compiler vectorises.
template <typename Point>
inline constexpr int kFlatSize = static_cast<int>(sizeof(Point) / sizeof(double));

/// y + a d.
template <typename Point>
COSSERAT_SCHEME_INLINE Point Axpy(const Point& y, double a, const Point& d) {
  Point out;
  double* o = out.p.data();
  const double* py = y.p.data();
  const double* pd = d.p.data();
  for (int i = 0; i < kFlatSize<Point>; ++i) o[i] = py[i] + a * pd[i];
  return out;
}

/// y += h/6 (k1 + 2 k2 + 2 k3 + k4): the RK4 step.
template <typename Point>
COSSERAT_SCHEME_INLINE void Rk4Update(double h, const Point& k1, const Point& k2, const Point& k3,
                                      const Point& k4, Point* y) {
  const double a = h / 6, b = h / 3;
  const double *p1 = k1.p.data(), *p2 = k2.p.data(), *p3 = k3.p.data(), *p4 = k4.p.data();
  double* o = y->p.data();
  for (int i = 0; i < kFlatSize<Point>; ++i) o[i] += a * (p1[i] + p4[i]) + b * (p2[i] + p3[i]);
}

/// y += h/2 (k1 + k2): the Heun step.
template <typename Point>
COSSERAT_SCHEME_INLINE void HeunUpdate(double h, const Point& k1, const Point& k2, Point* y) {
  const double a = 0.5 * h;
  const double *p1 = k1.p.data(), *p2 = k2.p.data();
  double* o = y->p.data();
  for (int i = 0; i < kFlatSize<Point>; ++i) o[i] += a * (p1[i] + p2[i]);
}

/// RK4's continuous extension at θ = ½ of its step (Hairer, Nørsett & Wanner 1993, II.6):
/// y(½) ≈ y + h (5/24 k1 + 1/6 k2 + 1/6 k3 − 1/24 k4), local error O(h⁴).
template <typename Point>
COSSERAT_SCHEME_INLINE Point Rk4Midpoint(double h, const Point& y, const Point& k1, const Point& k2,
                                         const Point& k3, const Point& k4) {
  Point out;
  const double a = h * 5.0 / 24, b = h / 6, c = -h / 24;
  const double *py = y.p.data(), *p1 = k1.p.data(), *p2 = k2.p.data(), *p3 = k3.p.data(),
               *p4 = k4.p.data();
  double* o = out.p.data();
  for (int i = 0; i < kFlatSize<Point>; ++i)
    o[i] = py[i] + a * p1[i] + b * (p2[i] + p3[i]) + c * p4[i];
  return out;
}

}  // namespace internal
}  // namespace cosserat
