// The real-time path allocates nothing: every malloc (C and C++) inside Step() is counted while
// the guard is on, and the count must stay zero. glibc lets an executable interpose malloc and
// friends; the real allocator stays reachable as __libc_malloc and co.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include "cosserat/quatfd/quatfd_model.hpp"
#include "cosserat/quatfd/radau.hpp"
#include "cosserat/quatfd/sdirk.hpp"
#include "cosserat/strong/batch_stepper.hpp"
#include "cosserat/strong/bdf2_stepper.hpp"
#include "cosserat/strong/static_shooting.hpp"
#include "support/rods.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define COSSERAT_COUNT_MALLOC 0  // AddressSanitizer owns malloc; these tests skip themselves
#else
#define COSSERAT_COUNT_MALLOC 1
#endif

#if COSSERAT_COUNT_MALLOC
extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void __libc_free(void*);
}

namespace {
[[maybe_unused]] std::atomic<bool> g_guard{false};
std::atomic<long> g_allocations{0};
void Count() {
  if (g_guard.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
}

// Counts allocations made while alive.
class AllocationGuard {
 public:
  AllocationGuard() {
    g_allocations = 0;
    g_guard = true;
  }
  ~AllocationGuard() { g_guard = false; }
  long count() const { return g_allocations.load(); }
};
}  // namespace

extern "C" {
void* malloc(size_t n) {
  Count();
  return __libc_malloc(n);
}
void* calloc(size_t a, size_t b) {
  Count();
  return __libc_calloc(a, b);
}
void* realloc(void* p, size_t n) {
  Count();
  return __libc_realloc(p, n);
}
void free(void* p) { __libc_free(p); }
int posix_memalign(void** out, size_t alignment, size_t n) {
  Count();
  *out = __libc_memalign(alignment, n);
  return *out ? 0 : ENOMEM;
}
void* aligned_alloc(size_t alignment, size_t n) {
  Count();
  return __libc_memalign(alignment, n);
}
}
#endif

namespace cosserat {
namespace {

class NoAllocation : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!COSSERAT_COUNT_MALLOC) GTEST_SKIP() << "malloc is interposed by AddressSanitizer";
  }
};

TEST_F(NoAllocation, GuardSeesAllocations) {
  // The guard itself must work, or the tests below prove nothing. The pointers escape through a
  // volatile, or the compiler may elide a new/delete pair (clang does) and the count read 2.
  static void* volatile escaped = nullptr;
  long seen = 0;
  {
    AllocationGuard guard;
    auto* p = new std::vector<double>(100);
    void* q = std::malloc(10);
    escaped = p;
    escaped = q;
    seen = guard.count();
    std::free(q);
    delete p;
  }
  EXPECT_GE(seen, 3);
}

TEST_F(NoAllocation, Bdf2StepAllocatesNothing) {
  const RodModel model = testing::SteelRod{0.5, 0.001}.model();
  Bdf2ShootingStepper stepper(model, 40);
  StepInput in;
  in.loads.gravity_W = Vec3(-9.81, 0, 0);
  in.loads.tip_force = Vec3(-0.196, 0, 0);
  ASSERT_TRUE(stepper.InitializeAtRest(in).converged());
  in.loads.tip_force.setZero();
  long allocations = 0;
  int converged = 0;
  {
    AllocationGuard guard;
    for (int i = 0; i < 200; ++i) {
      // A moving base and a varying tip load exercise the Jacobian refresh and LM paths too.
      in.base_twist_B(4) = 0.05 * std::sin(0.1 * i);
      in.loads.tip_moment = Vec3(0, 1e-3 * std::cos(0.05 * i), 0);
      converged += stepper.Step(in).converged() ? 1 : 0;
    }
    allocations = guard.count();
  }
  EXPECT_EQ(converged, 200);
  EXPECT_EQ(allocations, 0);
}

// 16 rods on two threads: the team's hand-out (a function pointer, a counter, a condition
// variable) and every rod's step allocate nothing, on the worker thread as on the caller's (the
// guard counts every thread's mallocs).
TEST_F(NoAllocation, BatchStepAllocatesNothing) {
  const RodModel model = testing::SteelRod{0.5, 0.001}.model();
  const int M = 16;
  BatchStepper batch(model, 21, Bdf2Options{}, M, 2);
  StepInput rest;
  rest.loads.gravity_W = Vec3(-9.81, 0, 0);
  ASSERT_EQ(batch.InitializeAtRest(rest), M);
  std::vector<StepInput> inputs(M, rest);
  long allocations = 0;
  int converged = 0;
  {
    AllocationGuard guard;
    for (int k = 0; k < 50; ++k) {
      for (int i = 0; i < M; ++i) inputs[i].loads.tip_force = Vec3(-0.01 * (i % 4), 1e-3 * k, 0);
      converged += batch.Step(inputs.data());
    }
    allocations = guard.count();
  }
  EXPECT_EQ(converged, 50 * M);
  EXPECT_EQ(allocations, 0);
}

TEST_F(NoAllocation, WarmStaticSolveAllocatesNothing) {
  const RodModel model = testing::SteelRod{0.5, 0.001}.model();
  StaticShootingSolver solver(model, 41);
  StaticLoads loads;
  loads.tip_force = Vec3(-0.5, 0, 0);
  ASSERT_TRUE(solver.Solve(lie::SE3{}, loads).converged());
  long allocations = 0;
  {
    AllocationGuard guard;
    for (int i = 0; i < 100; ++i) {
      loads.tip_force.x() = -0.5 * (1 + 0.01 * std::sin(0.3 * i));
      solver.Solve(lie::SE3{}, loads);
    }
    allocations = guard.count();
  }
  EXPECT_EQ(allocations, 0);
  // A new actuation re-samples the sections in place (its header says so).
  Actuation softer;
  softer.stiffness_scale = 0.9;
  {
    AllocationGuard guard;
    solver.SetActuation(softer);
    allocations = guard.count();
  }
  EXPECT_EQ(allocations, 0);
}

// A quaternion-FD integrator after construction on the swinging rubber rod (10 segments, shear
// damped): 0.5 s in ten output intervals — steps, rejections, Newton failures, Jacobian refreshes,
// refactorisations and (Radau) the extrapolation polynomial all run on the constructor's buffers.
template <typename Integrator>
void ExpectQuatFdAdvanceAllocatesNothing() {
  quatfd::QuatFdOptions opt;
  opt.segments = 10;
  lie::SE3 base;
  base.R << 0, 0, 1, 0, 1, 0, -1, 0, 0;  // horizontal: the rod swings down under gravity
  Material m = Material::FromPoissonRatio(5e6, 0.5, 1100);
  m.damping.shear = 0.01 * m.shear_modulus * CrossSection::Circle(0.005).area;
  quatfd::QuatFdModel model(RodModel::Uniform(0.5, CrossSection::Circle(0.005), m), base, opt);
  StaticLoads loads;
  loads.gravity_W = Vec3(0, 0, -9.81);
  model.set_loads(loads);
  Eigen::VectorXd q(model.size()), v(model.size());
  model.RestState(q, v);
  Integrator integ(model);
  double t = 0;
  quatfd::IntegratorStatus status = quatfd::IntegratorStatus::kNotRun;
  long allocations = 0;
  {
    AllocationGuard guard;
    for (int k = 1; k <= 10 && (k == 1 || status == quatfd::IntegratorStatus::kOk); ++k)
      status = integ.Advance(0.05 * k, &t, q, v);
    allocations = guard.count();
  }
  EXPECT_EQ(status, quatfd::IntegratorStatus::kOk);
  EXPECT_GT(integ.stats().jacobian_evaluations, 1);  // the refresh path ran
  EXPECT_EQ(allocations, 0);
}

TEST_F(NoAllocation, QuatFdSdirkAdvanceAllocatesNothing) {
  ExpectQuatFdAdvanceAllocatesNothing<quatfd::SdirkIntegrator>();
}

TEST_F(NoAllocation, QuatFdRadauAdvanceAllocatesNothing) {
  ExpectQuatFdAdvanceAllocatesNothing<quatfd::RadauIntegrator>();
}

}  // namespace
}  // namespace cosserat
