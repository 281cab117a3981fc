// Steppers allocate nothing per step: on a fixed-size state in a built-in floating tier,
// a step of every library stepper (after the first, which may fill caches) performs no
// heap allocation. A program of its own: global operator new is replaced to count (the
// standard library's allocations), and Eigen is built with EIGEN_RUNTIME_NO_MALLOC and
// assertions on, so any Eigen heap allocation while forbidden aborts the test.
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "mechcheck/mechcheck.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {
using namespace mechcheck;

template <class Stepper, class Vec>
long allocations_per_100_steps(Stepper step, phase_state<Vec> x, double h) {
  step(x, h);  // the first step may fill a cache
  const long before = allocations.load();
  Eigen::internal::set_is_malloc_allowed(false);
  for (int i = 0; i < 100; ++i) step(x, h);
  Eigen::internal::set_is_malloc_allowed(true);
  return allocations.load() - before;
}

template <class Vec, class System>
void expect_no_allocation(const System& sys, const phase_state<Vec>& x0, double h) {
  EXPECT_EQ(allocations_per_100_steps(explicit_euler<System, Vec>(sys), x0, h), 0) << "explicit_euler";
  EXPECT_EQ(allocations_per_100_steps(rk4<System, Vec>(sys), x0, h), 0) << "rk4";
  EXPECT_EQ(allocations_per_100_steps(symplectic_euler<System, Vec>(sys), x0, h), 0)
      << "symplectic_euler";
  EXPECT_EQ(allocations_per_100_steps(stormer_verlet<System, Vec>(sys), x0, h), 0)
      << "stormer_verlet";
  EXPECT_EQ((allocations_per_100_steps(composition<System, Vec, 4>(sys), x0, h)), 0)
      << "composition<4>";
  EXPECT_EQ((allocations_per_100_steps(composition<System, Vec, 6>(sys), x0, h)), 0)
      << "composition<6>";
  EXPECT_EQ((allocations_per_100_steps(mclachlan4<System, Vec>(sys), x0, h)), 0)
      << "mclachlan4";
  EXPECT_EQ((allocations_per_100_steps(gauss_legendre<System, Vec, 2>(sys), x0, h)), 0)
      << "gauss_legendre<2>";
  EXPECT_EQ((allocations_per_100_steps(gauss_legendre<System, Vec, 4>(sys), x0, h)), 0)
      << "gauss_legendre<4>";
}

TEST(allocation, no_step_allocates_on_fixed_size_states) {
  // The counter counts: a std::vector allocates through operator new.
  const long before = allocations.load();
  {
    std::vector<double> v(8);
    volatile double* keep = v.data();
    static_cast<void>(keep);
  }
  EXPECT_GE(allocations.load() - before, 1);

  using V3 = Eigen::Matrix<double, 3, 1>;
  expect_no_allocation<V3>(kepler_system<double>(1.0, 1.0),
                           phase_state<V3>{V3(1, 0, 0), V3(0, 1.2, 0.1)}, 0.01);
  using V1 = Eigen::Matrix<double, 1, 1>;
  expect_no_allocation<V1>(pendulum_system<double>(1.0, 1.0, 1.0),
                           phase_state<V1>{V1(0.5), V1(0.0)}, 0.05);
  using V2 = Eigen::Matrix<double, 2, 1>;
  expect_no_allocation<V2>(harmonic_oscillator_system<double>(1.0, 2.0),
                           phase_state<V2>{V2(1, 0), V2(0, 1)}, 0.05);
}

}  // namespace
