// Parameter sweeps: the parallel result equals the serial one solve for solve (each point is a
// converged equilibrium, so threads and warm starts may only change it within the tolerance),
// and ParallelFor visits every index exactly once.
#include <gtest/gtest.h>

#include <atomic>

#include "cosserat/analysis/sweep.hpp"

namespace cosserat {
namespace {

TEST(Sweep, ParallelForVisitsEveryIndexOnce) {
  std::vector<std::atomic<int>> hits(1001);
  const int used = ParallelFor(1001, 3, [&](int i, int) { ++hits[i]; });
  EXPECT_EQ(used, 3);
  for (const auto& h : hits) EXPECT_EQ(h.load(), 1);
  EXPECT_THROW(ParallelFor(10, 2,
                           [](int i, int) {
                             if (i == 7) throw std::runtime_error("boom");
                           }),
               std::runtime_error);
}

TEST(Sweep, TwoThreadsGiveTheSerialWorkspace) {
  RodModel model = RodModel::Uniform(0.25, CrossSection::Circle(0.0004),
                                     Material::FromShearModulus(210e9, 80e9, 7800));
  model.tendons = {{"x", TendonRoute::Parallel(Vec2(0.008, 0))},
                   {"y", TendonRoute::Parallel(Vec2(0, 0.008))}};
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  std::vector<Actuation> points;
  for (int a = 0; a < 10; ++a)
    for (int b = 0; b < 10; ++b) {
      Actuation act;
      act.tendon_tension[0] = 0.2 * a;
      act.tendon_tension[1] = 0.2 * (a % 2 ? 9 - b : b);  // serpentine: neighbours stay close
      points.push_back(act);
    }
  SweepOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const WorkspaceSweep serial = SweepWorkspace(model, 41, {}, lie::SE3{}, loads, points, one);
  const WorkspaceSweep parallel = SweepWorkspace(model, 41, {}, lie::SE3{}, loads, points, two);
  ASSERT_EQ(serial.converged(), 100);
  ASSERT_EQ(parallel.converged(), 100);
  EXPECT_EQ(parallel.threads, 2);
  for (int i = 0; i < 100; ++i)  // both converged to 1e-10 of EI/L: positions agree to ~1e-12 m
    EXPECT_LT((serial.tip_position_W[i] - parallel.tip_position_W[i]).norm(), 1e-9 * 0.25) << i;
  // Tensions bend the tip towards their tendons: the sweep covers a real workspace.
  EXPECT_GT(serial.tip_position_W.back().x(), 0.01);
}

}  // namespace
}  // namespace cosserat
