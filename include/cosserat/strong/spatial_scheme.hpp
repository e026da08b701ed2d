#pragma once
/// \file
/// The explicit Runge–Kutta schemes the dynamic shot integrates with in s (bdf2_stepper.hpp).
///
/// Both are of the form where stage j sits at y + a_j h k_{j−1} (a_0 = 0) and
/// y_{i+1} = y_i + h Σ_j b_j k_j, so one loop serves both. BDF2 keeps its history at every stage
/// point, and the rod's integrals (mass, momentum, energy) use the weights b_j at the stage
/// points: the linear-momentum balance n_W' = −f + ρA a_W is then summed by exactly the
/// quadrature the shot uses, and momentum stays conserved to round-off with either scheme.
///
/// Choosing: RK4 is order 4 in s; Heun (explicit trapezoid) is order 2 for half the stage
/// evaluations, the same order as BDF2 in time. On the peer rod (steel, L = 0.5 m) at 40 nodes the
/// spatial error of either is far below BDF2's time error at dt = 2 ms (BENCHMARKS.md), so the
/// real-time path can use Heun; statics (static_shooting.hpp) always uses RK4.

#ifdef __GNUC__
#define COSSERAT_SCHEME_INLINE inline __attribute__((always_inline))
#else
#define COSSERAT_SCHEME_INLINE inline
#endif

namespace cosserat {

enum class SpatialScheme {
  kRk4,   ///< classic RK4: 4 stage evaluations per segment, order 4 (the default)
  kHeun,  ///< Heun / explicit trapezoid: 2 stage evaluations per segment, order 2
};

namespace internal {

/// Stage j of segment i: state y_i + step[j] h k_{j−1}; section sample `sample[j]` of the
/// segment (0: its start, 1: its middle, 2: its end, as SegmentSamplePoints lays them out);
/// quadrature weight weight[j] (times h). Offset in s of stage j: step[j] h for both schemes.
struct SchemeTable {
  int stages;
  double step[4];
  int sample[4];
  double weight[4];
};

inline constexpr SchemeTable kRk4Table{
    4, {0.0, 0.5, 0.5, 1.0}, {0, 1, 1, 2}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}};
inline constexpr SchemeTable kHeunTable{2, {0.0, 1.0, 0, 0}, {0, 2, 0, 0}, {0.5, 0.5, 0, 0}};

constexpr const SchemeTable& Table(SpatialScheme s) {
  return s == SpatialScheme::kHeun ? kHeunTable : kRk4Table;
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

}  // namespace internal
}  // namespace cosserat
