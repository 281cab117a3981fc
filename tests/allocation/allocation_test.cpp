// Steppers allocate nothing per step: on a fixed-size state, a step of every library
// stepper (after the first, which may fill caches and its scratch) performs no heap
// allocation, in double and, for the explicit steppers, in mpfr50. A program of its own:
// global operator new is replaced to count (the standard library's allocations), GMP's
// memory functions are replaced to count MPFR's (its temporaries; mpfr50 keeps its own
// limbs inside the number, an MPFR number of dynamic allocation allocates them), and Eigen
// is built with EIGEN_RUNTIME_NO_MALLOC and assertions on, so any Eigen heap allocation
// while forbidden aborts the test.
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <gmp.h>
#include <gtest/gtest.h>

#include "mechcheck/mechcheck.hpp"

namespace {
std::atomic<long> allocations{0};

void* counted_mp_allocate(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size)) return p;
  std::abort();  // GMP's own allocator aborts too
}
void* counted_mp_reallocate(void* p, std::size_t, std::size_t size) {
  ++allocations;
  if (void* q = std::realloc(p, size)) return q;
  std::abort();
}
void counted_mp_free(void* p, std::size_t) { std::free(p); }

/// Counts GMP's (hence MPFR's) allocations from the first test on.
const bool mp_counted = [] {
  mp_set_memory_functions(counted_mp_allocate, counted_mp_reallocate, counted_mp_free);
  return true;
}();
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
long allocations_per_100_steps(Stepper step, phase_state<Vec> x,
                               const typename Vec::Scalar& h) {
  step(x, h);  // the first step may fill a cache
  const long before = allocations.load();
  Eigen::internal::set_is_malloc_allowed(false);
  for (int i = 0; i < 100; ++i) step(x, h);
  Eigen::internal::set_is_malloc_allowed(true);
  return allocations.load() - before;
}

template <class Vec, class System>
void expect_explicit_steppers_allocate_nothing(const System& sys, const phase_state<Vec>& x0,
                                               const typename Vec::Scalar& h) {
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
}

template <class Vec, class System>
void expect_no_allocation(const System& sys, const phase_state<Vec>& x0, double h) {
  expect_explicit_steppers_allocate_nothing<Vec>(sys, x0, h);
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

// In mpfr50 the explicit steppers keep their temporaries and the Kepler and oscillator
// systems compute into kept numbers (mechcheck/core/inplace.hpp). Gauss-Legendre's stage
// iteration still builds numbers (not claimed here).
TEST(allocation, explicit_steppers_allocate_nothing_in_mpfr50) {
  ASSERT_TRUE(mp_counted);
  const long before = allocations.load();
  {
    // The counter sees MPFR's allocations: a number of dynamic allocation allocates its
    // limbs (mpfr50 holds them inside the number, allocate_stack: nothing to see there).
    const boost::multiprecision::mpfr_float_50 x = boost::multiprecision::mpfr_float_50(1) / 3;
    static_cast<void>(x);
  }
  EXPECT_GE(allocations.load() - before, 1);

  using T = mpfr50;
  using V3 = Eigen::Matrix<T, 3, 1>;
  const T h = T(1) / 100;
  expect_explicit_steppers_allocate_nothing<V3>(
      kepler_system<T>(T(1), T(1)), phase_state<V3>{V3(T(1), T(0), T(0)), V3(T(0), T(6) / 5, T(1) / 10)},
      h);
  expect_explicit_steppers_allocate_nothing<V3>(
      harmonic_oscillator_system<T>(T(1), T(2)),
      phase_state<V3>{V3(T(1), T(0), T(0)), V3(T(0), T(1), T(0))}, h);
}

}  // namespace
