// Kepler's equation on a dense (e, M) grid in every tier, typed errors for bad input, and
// the analytic Kepler orbit against high-precision integration (>= 40 digits in mpfr50).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "mechcheck/central.hpp"
#include "mechcheck/integrators.hpp"
#include "tiers.hpp"

namespace {
using namespace mechcheck;
using mechcheck::test::message_of;

template <class T>
class kepler_solver : public ::testing::Test {};
TYPED_TEST_SUITE(kepler_solver, mechcheck::test::all_tiers, mechcheck::test::tier_names);

/// Eccentricities from 0 to 1 - 1e-12 (and the case e = 0.1, M = 0.991 that a popular
/// solver fails), mean anomalies from 0 through 1e-12 to pi, negative, and beyond 2 pi.
template <class T>
std::vector<T> eccentricities() {
  std::vector<T> e{T(0), T(1) / 1000, T(1) / 10, T(1) / 2, T(9) / 10, T(99) / 100};
  for (int k = 3; k <= 12; ++k) e.push_back(T(1) - T(std::pow(10.0, -k)));
  return e;
}
template <class T>
std::vector<T> mean_anomalies() {
  std::vector<T> m{T(0), T(991) / 1000, T(100), T(-100)};
  for (int k = 1; k <= 12; ++k) {
    m.push_back(T(std::pow(10.0, -k)));
    m.push_back(T(-std::pow(10.0, -k)));
  }
  const T pi = boost::math::constants::pi<T>();
  for (int j = -64; j <= 64; ++j) m.push_back(pi * j / 64);
  return m;
}

// The residual, evaluated in mpfr100 from the tier's values, is bounded by the rounding
// of E (|E f'(E)| eps <= 3 |M| eps) and the reduction of M to [-pi, pi] (|M| eps).
TYPED_TEST(kepler_solver, converges_on_a_dense_grid) {
  using T = TypeParam;
  using W = mpfr100;
  const T eps = tier_epsilon<T>();
  for (const T& e : eccentricities<T>())
    for (const T& m : mean_anomalies<T>()) {
      const T ecc = solve_kepler(e, m);
      const W residual = mean_anomaly_from_eccentric(W(e), W(ecc)) - W(m);
      using std::abs;
      const T bound = 8 * eps * (abs(m) + 4);
      EXPECT_LE(abs(T(residual)), bound) << "e = " << to_text(e) << ", M = " << to_text(m);
    }
  const T ecc = solve_kepler(T(1) / 10, T(991) / 1000);
  EXPECT_NEAR(static_cast<double>(ecc), 1.0791559676390989, 4e-16);
}

TYPED_TEST(kepler_solver, hyperbolic_converges_on_a_dense_grid) {
  using T = TypeParam;
  using W = mpfr100;
  const T eps = tier_epsilon<T>();
  std::vector<T> es{T(1) + T(1e-12), T(1) + T(1e-6), T(11) / 10, T(2), T(10)};
  for (const T& e : es)
    for (const T& m : mean_anomalies<T>()) {
      const T h = solve_hyperbolic_kepler(e, m);
      const W wh = W(h);
      const W residual = W(e) * sinh(wh) - wh - W(m);
      using std::abs;
      EXPECT_LE(abs(T(residual)), 8 * eps * (abs(m) + 4))
          << "e = " << to_text(e) << ", M = " << to_text(m);
    }
}

TEST(kepler_errors, typed_and_named) {
  EXPECT_EQ(message_of([] { solve_kepler(1.0, 0.5); }),
            "solve_kepler: eccentricity 1 is not in [0, 1) (an ellipse is required)");
  EXPECT_THROW(solve_kepler(-0.1, 0.5), domain_error);
  EXPECT_THROW(solve_kepler(0.5, std::nan("")), non_finite_error);
  EXPECT_EQ(message_of([] { solve_hyperbolic_kepler(0.5, 1.0); }),
            "solve_hyperbolic_kepler: eccentricity 0.5 is not above 1 (a hyperbola is required)");
  const kepler_constants<double> c(1, 1);
  EXPECT_EQ(message_of([&] { semi_major_axis(c, 0.25); }),
            "semi_major_axis: energy E = 0.25 >= 0: the orbit is not bound");
  EXPECT_THROW(orbital_period(c, vector3<double>(1, 0, 0), vector3<double>(0, 2, 0)),
               domain_error);
  EXPECT_EQ(message_of([&] {
              elements_from_state(c, vector3<double>(1, 0, 0), vector3<double>(2, 0, 0));
            }),
            "elements_from_state: zero angular momentum at r = (1, 0, 0), v = (2, 0, 0) "
            "(radial motion has no orbit elements)");
  EXPECT_THROW(c.circular_radius(0.0), domain_error);
  EXPECT_THROW(kepler_constants<double>(1, -1), domain_error);
  EXPECT_EQ(message_of([] { radial_orbit<double>(1, 1, -1, 0.5, 1.0); }),
            "radial_orbit: U = c r^n needs c n > 0 (attractive), got c = 1, n = -1");
  EXPECT_THROW(radial_orbit<double>(1, -1, -1, 1.0, 0.5), domain_error);
  orbit_elements<double> beyond{1, 2, 0, 0, 0, 3};  // 1 + 2 cos 3 < 0
  EXPECT_THROW(state_from_elements(c, beyond), domain_error);
}

/// Integrate the Kepler problem with s-stage Gauss-Legendre to t.
template <class T, int Stages>
std::pair<dynamic_vector<T>, dynamic_vector<T>> integrated(const kepler_constants<T>& c,
                                                           const vector3<T>& r0,
                                                           const vector3<T>& v0, const T& t,
                                                           long steps) {
  const kepler_system<T> system(c.mu, c.k);
  gauss_legendre<kepler_system<T>, dynamic_vector<T>, Stages> step{system};
  phase_state<dynamic_vector<T>> s{dynamic_vector<T>(r0), dynamic_vector<T>(c.mu * v0)};
  integrate(step, s, T(t / steps), steps);
  return {s.q, s.p};
}

// Gauss-Legendre 8 (order 16) with h = 1/1024 over t in [0, 1/8] has a truncation error
// near 1e-45 relative; the analytic orbit (elements, Kepler's equation, state) must agree
// to >= 40 digits, from pericentre, apocentre and a generic point of orbits with
// e = 0.1, 0.5, 0.9, and of a hyperbola; and the LRL vector is conserved as well.
TEST(kepler_reference, agrees_with_integration_to_40_digits) {
  using T = mpfr50;
  const kepler_constants<T> c(T(3) / 2, T(5) / 4);
  for (const double e : {0.1, 0.5, 0.9, 1.5}) {
    for (const double nu : {0.0, 2.0, 3.0}) {
      if (e > 1 && nu > 2) continue;
      const orbit_elements<T> el{T(1), T(e), T(1) / 3, T(1) / 5, T(-1) / 7, T(nu)};
      const auto [r0, v0] = state_from_elements(c, el);
      const kepler_orbit<T> analytic(c, r0, v0);
      const T t = T(1) / 8;
      const auto [r1, v1] = analytic.state_at(t);
      const auto [q, p] = integrated<T, 8>(c, r0, v0, t, 128);
      using std::log10;
      const T digits_r = -log10(T((q - dynamic_vector<T>(r1)).norm() / r1.norm()));
      const T digits_v = -log10(T((p / c.mu - dynamic_vector<T>(v1)).norm() / v1.norm()));
      EXPECT_GE(digits_r, 40) << "e = " << e << ", nu = " << nu;
      EXPECT_GE(digits_v, 40) << "e = " << e << ", nu = " << nu;
      // The LRL vector of eq 77 along the integration: conserved to the same digits.
      const dynamic_vector<T> q0(r0), p0(dynamic_vector<T>(c.mu * v0));
      const vector3<T> a0 = lrl_vector(q0, p0, c.mu, c.k), a1 = lrl_vector(q, p, c.mu, c.k);
      EXPECT_GE(T(-log10(T((a1 - a0).norm() / (c.mu * c.k)))), 40) << "e = " << e;
    }
  }
}

// The parabola: E = 0 exactly for r = (2, 0, 0), v = (0, 1, 0), mu = k = 1; Barker's
// equation against Gauss-Legendre 4 with h = 1/256 over t = 1 (error ~1e-15 in double
// is far below the 1e-10 tolerance; a wrong mean motion would be off by ~1e-1).
TEST(kepler_reference, parabola_follows_barker) {
  const kepler_constants<double> c(1, 1);
  const vector3<double> r0(2, 0, 0), v0(0, 1, 0);
  const kepler_orbit<double> analytic(c, r0, v0);
  EXPECT_EQ(analytic.elements().eccentricity, 1.0);
  const auto [r1, v1] = analytic.state_at(1.0);
  const auto [q, p] = integrated<double, 4>(c, r0, v0, 1.0, 256);
  EXPECT_LT((q - dynamic_vector<double>(r1)).norm(), 1e-10);
  EXPECT_LT((p - dynamic_vector<double>(v1)).norm(), 1e-10);
}

}  // namespace
