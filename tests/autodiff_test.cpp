// Automatic differentiation against hand-derived derivatives, in every tier.
#include <gtest/gtest.h>

#include "mechcheck/core.hpp"
#include "tiers.hpp"

namespace {
using namespace mechcheck;
using mechcheck::test::near_eps;

template <class T>
class autodiff : public ::testing::Test {};
TYPED_TEST_SUITE(autodiff, mechcheck::test::all_tiers, mechcheck::test::tier_names);

// f(x, y) = x^2 y + 3 sin y + 1 / sqrt(x^2 + y^2)
struct test_function {
  template <class S>
  S operator()(const dynamic_vector<S>& z) const {
    using std::sin;
    using std::sqrt;
    const S r2 = z(0) * z(0) + z(1) * z(1);
    const S a = z(0) * z(0) * z(1);
    const S b = lift<S>(3) * sin(z(1));
    const S c = lift<S>(1) / sqrt(r2);
    return a + b + c;
  }
};

TYPED_TEST(autodiff, gradient_matches_hand_derivative) {
  using T = TypeParam;
  using std::cos;
  using std::sqrt;
  const T x = T(1) / 3, y = T(2) / 7;
  dynamic_vector<T> z(2);
  z << x, y;
  const T r = sqrt(x * x + y * y), r3 = r * r * r;
  const auto [value, g] = value_and_gradient(test_function{}, z);
  EXPECT_TRUE(near_eps(value, T(x * x * y + 3 * sin(y) + 1 / r), 8));
  EXPECT_TRUE(near_eps(g(0), T(2 * x * y - x / r3), 8));
  EXPECT_TRUE(near_eps(g(1), T(x * x + 3 * cos(y) - y / r3), 8));
}

TYPED_TEST(autodiff, nested_hessian_matches_hand_derivative) {
  using T = TypeParam;
  using std::sin;
  using std::sqrt;
  const T x = T(1) / 3, y = T(2) / 7;
  dynamic_vector<T> z(2);
  z << x, y;
  const T r = sqrt(x * x + y * y), r3 = r * r * r, r5 = r3 * r * r;
  const auto h = hessian(test_function{}, z);
  EXPECT_TRUE(near_eps(h(0, 0), T(2 * y - 1 / r3 + 3 * x * x / r5), 16));
  EXPECT_TRUE(near_eps(h(0, 1), T(2 * x + 3 * x * y / r5), 16));
  EXPECT_TRUE(near_eps(h(1, 0), T(2 * x + 3 * x * y / r5), 16));
  EXPECT_TRUE(near_eps(h(1, 1), T(-3 * sin(y) - 1 / r3 + 3 * y * y / r5), 16));
}

TYPED_TEST(autodiff, jacobian_of_vector_map) {
  using T = TypeParam;
  using std::exp;
  // F(x, y) = (x y, exp(x) - y^2): J = [[y, x], [exp(x), -2y]]
  const auto map = []<class S>(const dynamic_vector<S>& z) -> dynamic_vector<S> {
    using std::exp;
    dynamic_vector<S> out(2);
    out(0) = z(0) * z(1);
    const S e = exp(z(0));
    const S y2 = z(1) * z(1);
    out(1) = e - y2;
    return out;
  };
  const T x = T(-3) / 5, y = T(5) / 4;
  dynamic_vector<T> z(2);
  z << x, y;
  const auto j = jacobian(map, z);
  EXPECT_TRUE(near_eps(j(0, 0), y, 2));
  EXPECT_TRUE(near_eps(j(0, 1), x, 2));
  EXPECT_TRUE(near_eps(j(1, 0), T(exp(x)), 4));
  EXPECT_TRUE(near_eps(j(1, 1), T(-2 * y), 2));
}

TYPED_TEST(autodiff, directional_derivative_is_gradient_dot_direction) {
  using T = TypeParam;
  dynamic_vector<T> z(2), v(2);
  z << T(1) / 3, T(2) / 7;
  v << T(3) / 4, T(-1) / 8;
  const auto g = gradient(test_function{}, z);
  EXPECT_TRUE(near_eps(directional_derivative(test_function{}, z, v), T(g.dot(v)), 16));
}

TYPED_TEST(autodiff, lift_builds_nested_constants) {
  using T = TypeParam;
  using A2 = ad<ad<T>>;
  const A2 c = lift<A2>(3);
  EXPECT_EQ(innermost_value(c), T(3));
  EXPECT_EQ(c.derivatives().size(), 0);
  const A2 d = lift<A2>(T(1) / 3);
  EXPECT_EQ(innermost_value(d), T(1) / 3);
  static_assert(std::is_same_v<real_type_t<A2>, T>);
}

TYPED_TEST(autodiff, constant_function_has_zero_gradient_and_hessian) {
  using T = TypeParam;
  const auto constant = []<class S>(const dynamic_vector<S>&) -> S { return lift<S>(7); };
  dynamic_vector<T> z(3);
  z << T(1), T(2), T(3);
  EXPECT_TRUE(gradient(constant, z).isZero(0));
  EXPECT_TRUE(hessian(constant, z).isZero(0));
}

TEST(precision, tiers_have_names_digits_and_epsilon) {
  EXPECT_EQ(tier_traits<double>::name, "double");
  EXPECT_EQ(tier_digits<double>(), 15);
  EXPECT_EQ(tier_traits<float128>::name, "float128");
  EXPECT_EQ(tier_digits<float128>(), 33);
  EXPECT_EQ(tier_traits<mpfr50>::name, "mpfr50");
  EXPECT_GE(tier_digits<mpfr50>(), 50);
  EXPECT_GE(tier_digits<mpfr100>(), 100);
  // epsilon is the gap above 1: 1 + eps != 1 and 1 + eps/2 == 1 (round to nearest even).
  EXPECT_NE(float128(1) + tier_epsilon<float128>(), float128(1));
  EXPECT_EQ(float128(1) + tier_epsilon<float128>() / 2, float128(1));
  EXPECT_NE(mpfr50(1) + tier_epsilon<mpfr50>(), mpfr50(1));
  EXPECT_EQ(mpfr50(1) + tier_epsilon<mpfr50>() / 2, mpfr50(1));
  EXPECT_LT(tier_epsilon<mpfr50>(), mpfr50("1e-49"));
}

// The MPFR tiers keep their limbs in the number (allocate_stack), whose Boost 1.81 backend
// prints a negative zero without its sign: the text of every tier keeps it, as reference
// keys are made of it (a start like the three bodies' has -0 components).
TEST(precision, a_negative_zero_keeps_its_sign_in_every_tiers_text) {
  EXPECT_EQ(to_text(-0.0), "-0");
  EXPECT_EQ(to_text(-mpfr50(0)), "-0");
  EXPECT_EQ(to_text(mpfr50(0)), "0");
  EXPECT_EQ(to_text(-mpfr100(0)), "-0");
  EXPECT_EQ(scientific_text(-mpfr50(0), 3), "-0.000e+00");
  EXPECT_EQ(scientific_text(mpfr50(0), 3), "0.000e+00");
  EXPECT_EQ(scientific_text(-mpfr100(1) / 4, 3), "-2.500e-01");
}
}  // namespace
