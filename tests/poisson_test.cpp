// Poisson brackets of hand-computed cases, and the errors bad input gets.
#include <limits>

#include <gtest/gtest.h>

#include "mechcheck/harness/generators.hpp"
#include "mechcheck/poisson.hpp"
#include "tiers.hpp"

namespace {
using namespace mechcheck;
using mechcheck::test::near_eps;

template <class T>
class poisson : public ::testing::Test {};
TYPED_TEST_SUITE(poisson, mechcheck::test::all_tiers, mechcheck::test::tier_names);

template <class T>
phase_point<T> point(std::initializer_list<double> q, std::initializer_list<double> p) {
  dynamic_vector<T> qs(q.size()), ps(p.size());
  Eigen::Index i = 0;
  for (double v : q) qs(i++) = T(v);
  i = 0;
  for (double v : p) ps(i++) = T(v);
  return phase_point<T>(qs, ps);
}

TYPED_TEST(poisson, hand_computed_brackets) {
  using T = TypeParam;
  const auto x = point<T>({0.75, -1.5}, {0.5, 2.0});
  // {q0^2, p0} = 2 q0
  const auto q0_squared = []<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>&) -> S {
    return q(0) * q(0);
  };
  EXPECT_EQ(poisson_bracket(q0_squared, p_component{0}, x), T(1.5));
  // {q1 p0, p1} = q1 ... d(q1 p0)/dq1 * dp1/dp1 = p0
  const auto q1p0 = []<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& p) -> S {
    return q(1) * p(0);
  };
  EXPECT_EQ(poisson_bracket(q1p0, p_component{1}, x), T(0.5));
  EXPECT_EQ(poisson_bracket(q1p0, q_component{0}, x), T(1.5));  // -d/dp0 (q1 p0) * 1 * -1
  // Oscillator: {q_i, H} = p_i / m and {p_i, H} = -k q_i  (Hamilton's equations, eq 250)
  const harmonic_oscillator<T> h(T(2), T(3));
  EXPECT_TRUE(near_eps(poisson_bracket(q_component{1}, h, x), T(1), 2));
  EXPECT_TRUE(near_eps(poisson_bracket(p_component{0}, h, x), T(-2.25), 2));
  const auto v = hamiltonian_vector_field(h, x);
  EXPECT_TRUE(near_eps(v(0), T(0.25), 2));
  EXPECT_TRUE(near_eps(v(3), T(4.5), 2));
}

TYPED_TEST(poisson, bracket_sign_convention_is_eq_269) {
  using T = TypeParam;
  // {q, p} = +1 fixes the sign: {f, g} = f_q g_p - f_p g_q.
  const auto x = point<T>({0.25}, {-0.5});
  EXPECT_EQ(poisson_bracket(q_component{0}, p_component{0}, x), T(1));
  EXPECT_EQ(poisson_bracket(p_component{0}, q_component{0}, x), T(-1));
}

using mechcheck::test::message_of;

TEST(poisson_errors, function_returning_nan_names_function_and_value) {
  const auto x = point<double>({1.0}, {2.0});
  const auto bad = []<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>&) -> S {
    using std::sqrt;
    const S minus_one = lift<S>(-1) * q(0);
    return sqrt(minus_one);
  };
  EXPECT_THROW(poisson_bracket(bad, p_component{0}, x), non_finite_error);
  EXPECT_EQ(message_of([&] { poisson_bracket(bad, p_component{0}, x); }),
            "poisson_bracket: function f returned nan at q = (1), p = (2)");
}

TEST(poisson_errors, function_returning_infinity_names_g) {
  const auto x = point<mpfr50>({0.0}, {2.0});
  const auto bad = []<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>&) -> S {
    return lift<S>(1) / q(0);
  };
  EXPECT_THROW(poisson_bracket(q_component{0}, bad, x), non_finite_error);
  EXPECT_EQ(message_of([&] { poisson_bracket(q_component{0}, bad, x); }),
            "poisson_bracket: function g returned inf at q = (0), p = (2)");
}

TEST(poisson_errors, infinite_derivative_is_reported) {
  // |q| at the origin: finite value, derivative 0/0.
  const auto x = point<double>({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  const central_force_hamiltonian<double, power_law_potential<double>> h(
      1.0, power_law_potential<double>{1.0, 2});
  EXPECT_THROW(poisson_bracket(h, angular_momentum{2}, x), non_finite_error);
  EXPECT_NE(message_of([&] { poisson_bracket(h, angular_momentum{2}, x); })
                .find("poisson_bracket: function f has derivative d/dq[0] = "),
            std::string::npos);
}

TEST(poisson_errors, non_finite_point_is_named) {
  const auto x = point<double>({1.0, std::numeric_limits<double>::quiet_NaN()}, {0.0, 0.0});
  EXPECT_EQ(message_of([&] { poisson_bracket(q_component{0}, p_component{0}, x); }),
            "poisson_bracket: phase-space point has q[1] = nan at q = (1, nan), p = (0, 0)");
}

TEST(poisson_errors, dimensions_must_match) {
  dynamic_vector<double> q(3), p(2);
  q.setZero();
  p.setZero();
  EXPECT_THROW(phase_point<double>(q, p), dimension_error);
  EXPECT_EQ(message_of([&] { phase_point<double>(q, p); }),
            "phase_point: q has 3 components but p has 2");
  dynamic_vector<double> odd(5);
  odd.setZero();
  EXPECT_EQ(message_of([&] { phase_point<double>::from_stacked(odd); }),
            "phase_point::from_stacked: a phase-space vector needs an even length, got 5");
  const auto x2 = point<double>({1.0, 2.0}, {3.0, 4.0});
  EXPECT_THROW(poisson_bracket(angular_momentum{0}, angular_momentum{1}, x2), dimension_error);
  EXPECT_EQ(message_of([&] { poisson_bracket(angular_momentum{0}, angular_momentum{1}, x2); }),
            "angular_momentum: q needs 3 degrees of freedom (Cartesian r), got 2");
  mechcheck::generators::smooth_function f;
  f.dof = 3;
  EXPECT_EQ(message_of([&] { poisson_bracket(f, q_component{0}, x2); }),
            "smooth_function: defined on 3 degrees of freedom, called with q of 2 and p of 2");
}

TEST(poisson_errors, parameters_must_be_physical) {
  EXPECT_THROW(harmonic_oscillator<double>(-1.0, 1.0), domain_error);
  EXPECT_EQ(message_of([] { harmonic_oscillator<double>(-1.0, 1.0); }),
            "harmonic_oscillator: mass must be positive and finite, got -1");
  EXPECT_EQ(message_of([] { harmonic_oscillator<mpfr50>(mpfr50(1), mpfr50(0)); }),
            "harmonic_oscillator: stiffness must be positive and finite, got 0");
  EXPECT_EQ(message_of([] {
              central_force_hamiltonian<double, power_law_potential<double>>(
                  std::numeric_limits<double>::infinity(), {1.0, -1});
            }),
            "central_force_hamiltonian: mass must be positive and finite, got inf");
}
}  // namespace
