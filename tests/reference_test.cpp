// The analytic oscillator flow is checked against Hamilton's equations, its group
// property and energy conservation, in every tier including the 100-digit one.
#include <gtest/gtest.h>

#include "mechcheck/integrators.hpp"
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

// --- the pendulum and the twist: start where they are started, follow the flow -------------

namespace pendulum_reference_test {
using namespace mechcheck;
using T = mpfr50;

/// (theta, p) after integrating H = p^2/(2 m l^2) - m g l cos(theta) to t with
/// Gauss-Legendre 4 (order 8) in n steps.
std::pair<T, T> integrated(const T& m, const T& l, const T& g, const T& theta0, const T& p0,
                           const T& t, long n) {
  const pendulum_system<T> sys(m, l, g);
  gauss_legendre<pendulum_system<T>, dynamic_vector<T>, 4> step{sys};
  phase_state<dynamic_vector<T>> x{dynamic_vector<T>(1), dynamic_vector<T>(1)};
  x.q << theta0;
  x.p << p0;
  for (long i = 0; i < n; ++i) step(x, T(t / n));
  return {x.q(0), x.p(0)};
}

TEST(pendulum_reference, starts_at_its_state_and_follows_the_flow_for_every_sign) {
  const T m = T(3) / 2, l = T(5) / 4, g = T(2);
  // Each quadrant of the start (theta0, p0), and the integrated motion at t = 7/4 (GL4,
  // 256 steps: h^8 C ~ 1e-20 of the state), agreeing to 1e-18.
  for (const auto& [theta0, p0] : std::vector<std::pair<T, T>>{
           {T(1) / 2, T(1)}, {T(1) / 2, T(-1)}, {T(-1) / 2, T(1)}, {T(-1) / 2, T(-1)}, {T(1), T(0)}}) {
    const reference::pendulum_motion<T> motion(m, l, g, theta0, p0);
    const auto [theta, p] = motion.state_at(T(0));
    EXPECT_TRUE(test::near_eps(theta, theta0, 64)) << theta0 << " " << p0;
    EXPECT_TRUE(test::near_eps(T(p + 1), T(p0 + 1), 64)) << theta0 << " " << p0;
    const T t = T(7) / 4;
    const auto [ti, pi] = integrated(m, l, g, theta0, p0, t, 256);
    const auto [tr, pr] = motion.state_at(t);
    using std::abs;
    EXPECT_LT(static_cast<double>(abs(T(ti - tr))), 1e-18) << theta0 << " " << p0;
    EXPECT_LT(static_cast<double>(abs(T(pi - pr))), 1e-18) << theta0 << " " << p0;
    // One period later, the start again.
    const auto [tp, pp] = motion.state_at(motion.period());
    EXPECT_LT(static_cast<double>(abs(T(tp - theta0))), 1e-45);
    EXPECT_LT(static_cast<double>(abs(T(pp - p0))), 1e-45);
  }
}

TEST(twist_reference, starts_at_its_state_and_turns_clockwise_at_rate_r2) {
  // H = (q^2 + p^2)^2/4: qdot = r^2 p, pdot = -r^2 q: clockwise in the (q, p) plane.
  const T q0 = T(1), p0 = T(1) / 2, dt = T(1) / 1024;
  const auto [q1, p1] = reference::twist_flow(q0, p0, dt);
  const T r2 = q0 * q0 + p0 * p0;
  using std::abs;
  // One small step: q1 - q0 = r^2 p0 dt + O(dt^2).
  EXPECT_LT(static_cast<double>(abs(T((q1 - q0) / dt - r2 * p0))), 1e-2);
  EXPECT_LT(static_cast<double>(abs(T((p1 - p0) / dt + r2 * q0))), 1e-2);
  const auto [qs, ps] = reference::twist_flow(q0, p0, T(0));
  EXPECT_EQ(qs, q0);
  EXPECT_EQ(ps, p0);
}
}  // namespace pendulum_reference_test
