// The analytic oscillator flow is checked against Hamilton's equations, its group
// property and energy conservation, in every tier including the 100-digit one.
#include <gtest/gtest.h>

#include "mechcheck/poisson.hpp"
#include "mechcheck/reference.hpp"
#include "tiers.hpp"

namespace {
using namespace mechcheck;
using mechcheck::test::near_eps;

template <class T>
class oscillator_reference : public ::testing::Test {};
TYPED_TEST_SUITE(oscillator_reference, mechcheck::test::all_tiers, mechcheck::test::tier_names);

template <class T>
struct fixture {
  T m = T(3) / 2, k = T(5) / 3;
  reference::oscillator_flow<T> flow{m, k};
  harmonic_oscillator<T> h{m, k};
  dynamic_vector<T> q0, p0;
  fixture() : q0(2), p0(2) {
    q0 << T(1) / 3, T(-7) / 5;
    p0 << T(2) / 9, T(1) / 2;
  }
};

TYPED_TEST(oscillator_reference, solves_hamiltons_equations) {
  using T = TypeParam;
  using A = ad<T>;
  fixture<T> f;
  for (const T t : {T(0), T(1) / 7, T(5) / 2, T(-3)}) {
    // d/dt of the flow at t, by AD in t, against X_H at the flowed point (eq 250).
    dynamic_vector<A> q(2), p(2);
    for (int i = 0; i < 2; ++i) {
      q(i) = lift<A>(f.q0(i));
      p(i) = lift<A>(f.p0(i));
    }
    const auto xt = f.flow(q, p, A(t, dynamic_vector<T>::Constant(1, T(1))));
    dynamic_vector<T> qt(2), pt(2), velocity(4);
    for (int i = 0; i < 2; ++i) {
      qt(i) = xt.q()(i).value();
      pt(i) = xt.p()(i).value();
      velocity(i) = derivatives_of(xt.q()(i), 1)(0);
      velocity(2 + i) = derivatives_of(xt.p()(i), 1)(0);
    }
    const auto field = hamiltonian_vector_field(f.h, phase_point<T>(qt, pt));
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(near_eps(velocity(i), field(i), 64)) << i;
  }
}

TYPED_TEST(oscillator_reference, is_a_one_parameter_group_and_conserves_energy) {
  using T = TypeParam;
  fixture<T> f;
  const T s = T(2) / 3, t = T(9) / 4;
  const auto xs = f.flow(f.q0, f.p0, s);
  const auto xst = f.flow(xs.q(), xs.p(), t);
  const auto direct = f.flow(f.q0, f.p0, T(s + t));
  const T e0 = f.h(f.q0, f.p0);
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(near_eps(xst.q()(i), direct.q()(i), 64));
    EXPECT_TRUE(near_eps(xst.p()(i), direct.p()(i), 64));
  }
  EXPECT_TRUE(near_eps(T(f.h(direct.q(), direct.p())), e0, 32));
}

TEST(oscillator_reference_errors, rejects_bad_parameters) {
  try {
    reference::oscillator_flow<double>(1.0, -2.0);
    FAIL() << "no exception";
  } catch (const domain_error& e) {
    EXPECT_STREQ(e.what(), "oscillator_flow: stiffness must be positive and finite, got -2");
  }
}
}  // namespace
