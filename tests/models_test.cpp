// Each model by its definition: energies, forces and documented features (a minimum's
// position and depth, a zero crossing, an equilibrium, a small-oscillation frequency)
// against their closed forms at documented points, in every tier. The laws check the
// models through invariances any potential of their kind has; these pin which potential.

#include <gtest/gtest.h>

#include <cmath>

#include <boost/math/constants/constants.hpp>

#include "mechcheck/integrators.hpp"
#include "mechcheck/lagrangian.hpp"
#include "mechcheck/models.hpp"
#include "tiers.hpp"

namespace models_test {
namespace models = mechcheck::models;
using namespace mechcheck;
using test::near_eps;

template <class T>
class model_definitions : public ::testing::Test {};
using tiers = ::testing::Types<double, float128, mpfr50>;
TYPED_TEST_SUITE(model_definitions, tiers, test::tier_names);

/// dU/dr and d2U/dr2 of a radial function by nested AD.
template <class T, class U>
std::pair<T, T> radial_derivatives(const U& u, const T& r) {
  dynamic_vector<T> x(1);
  x << r;
  const auto f = [&u]<class S>(const dynamic_vector<S>& v) { return u(S(v(0))); };
  const second_order<T> e = second_order_expansion(f, x);
  return {e.gradient(0), e.hessian(0, 0)};
}

TYPED_TEST(model_definitions, lennard_jones_minimum_zero_and_curvature) {
  using T = TypeParam;
  const T e = T(3) / 4, s = T(5) / 4;
  const models::lennard_jones_pair<T> u(e, s);
  // U = e ((s/r)^12 - 2 (s/r)^6): minimum -e at r = s, U''(s) = 72 e / s^2, zero at
  // r = s 2^(-1/6), U(2s) = e (2^-12 - 2^-5).
  EXPECT_TRUE(near_eps(u(s), T(-e), 8));
  const auto [du, d2u] = radial_derivatives(u, s);
  EXPECT_TRUE(near_eps(T(du + 1), T(1), 64));
  EXPECT_TRUE(near_eps(d2u, T(72 * e / (s * s)), 256));
  using std::pow;
  EXPECT_TRUE(near_eps(T(u(T(s * pow(T(2), T(-1) / 6))) + e), e, 64));
  EXPECT_TRUE(near_eps(u(T(2 * s)), T(e * (pow(T(2), -12) - pow(T(2), -5))), 16));
}

TYPED_TEST(model_definitions, morse_minimum_zero_and_curvature) {
  using T = TypeParam;
  const T d = T(2), a = T(3) / 2, r0 = T(1);
  const models::morse_pair<T> u(d, a, r0);
  // U = D (1 - exp(-a (r - r0)))^2 - D: minimum -D at r0, U''(r0) = 2 D a^2, zero at
  // r0 - ln 2 / a, U -> 0 far away.
  EXPECT_TRUE(near_eps(u(r0), T(-d), 8));
  const auto [du, d2u] = radial_derivatives(u, r0);
  EXPECT_TRUE(near_eps(T(du + 1), T(1), 64));
  EXPECT_TRUE(near_eps(d2u, T(2 * d * a * a), 64));
  using std::log;
  EXPECT_TRUE(near_eps(T(u(T(r0 - log(T(2)) / a)) + d), d, 64));
  using std::exp;
  const T far = T(40);
  EXPECT_TRUE(near_eps(u(far), T(d * (exp(T(-2 * a * (far - r0))) - 2 * exp(T(-a * (far - r0))))), 64));
}

TYPED_TEST(model_definitions, power_law_pair_and_vertical_field) {
  using T = TypeParam;
  const models::power_law_pair<T> cube(T(-3), 3), inverse(T(5), -2);
  EXPECT_TRUE(near_eps(cube(T(2)), T(-24), 4));
  EXPECT_TRUE(near_eps(inverse(T(2)), T(T(5) / 4), 4));
  EXPECT_TRUE(near_eps(radial_derivatives(inverse, T(2)).first, T(T(-5) / 4), 16));
  const models::vertical_field<T> v(T(3), T(-2));
  EXPECT_EQ(v(T(0)), T(0));
  EXPECT_TRUE(near_eps(v(T(2)), T(3 * 2 - 2 * 4), 4));
  EXPECT_TRUE(near_eps(radial_derivatives(v, T(0)).first, T(3), 8));
  EXPECT_TRUE(near_eps(radial_derivatives(v, T(0)).second, T(-4), 8));
}

TYPED_TEST(model_definitions, particles_feel_the_pair_force_and_the_field) {
  using T = TypeParam;
  // Two particles (m = 1, 2) at (0, 0, 0) and (3, 0, 4): r = 5, U = c r^k = 2 r^-1, V(z) = z.
  const models::particle_system<T, models::power_law_pair<T>, models::vertical_field<T>> sys(
      {T(1), T(2)}, models::power_law_pair<T>(T(2), -1), models::vertical_field<T>(T(1), T(0)));
  dynamic_vector<T> q(6), v(6);
  q << T(0), T(0), T(0), T(3), T(0), T(4);
  v << T(1), T(0), T(0), T(0), T(0), T(1);
  // E = (1 + 2)/2 + 2/5 + 4 (heights 0 and 4).
  EXPECT_TRUE(near_eps(energy_function(sys, q, v, T(0)), T(T(3) / 2 + T(2) / 5 + 4), 16));
  // Force on particle 1 from -dU/dr1 = (c k r^(k-1)) (r1 - r2)/r... = -2/25 (r1 - r2)/5
  // pointing away from 2 (repulsive for c > 0): (r1 - r2)/r = (-3, 0, -4)/5.
  const dynamic_vector<T> a = accelerations(sys, q, v, T(0));
  const T f = T(2) / 25;
  EXPECT_TRUE(near_eps(a(0), T(-f * 3 / 5), 16));
  EXPECT_TRUE(near_eps(a(2), T(-f * 4 / 5 - 1), 16));
  EXPECT_TRUE(near_eps(a(3), T(f * 3 / 5 / 2), 16));
  EXPECT_TRUE(near_eps(a(5), T((f * 4 / 5 - 1) / 2), 16));  // V is per particle, not per mass
}

TYPED_TEST(model_definitions, pendulum_equilibria_and_small_oscillations) {
  using T = TypeParam;
  const T m = T(2), l = T(3) / 2, g = T(10);
  const models::simple_pendulum<T> pendulum(m, l, g);
  const T pi = boost::math::constants::pi<T>();
  dynamic_vector<T> q(1), v(1);
  q << T(0);
  v << T(0);
  // Equilibria at 0 (stable, thetaddot = -(g/l) theta) and pi (unstable).
  EXPECT_TRUE(near_eps(T(accelerations(pendulum, q, v, T(0))(0) + 1), T(1), 8));
  q << T(1) / 1024;
  using std::sin;
  EXPECT_TRUE(near_eps(accelerations(pendulum, q, v, T(0))(0), T(-(g / l) * sin(q(0))), 16));
  q << pi;
  EXPECT_TRUE(near_eps(T(accelerations(pendulum, q, v, T(0))(0) + 1), T(1), 64));
  // E = m l^2 thetadot^2 / 2 - m g l cos(theta): at the horizontal at rest, 0; at the
  // bottom with thetadot = 2, 4 m l^2 / 2 - m g l.
  q << pi / 2;
  EXPECT_TRUE(near_eps(T(energy_function(pendulum, q, v, T(0)) + 1), T(1), 64));
  q << T(0);
  v << T(2);
  EXPECT_TRUE(near_eps(energy_function(pendulum, q, v, T(0)), T(2 * m * l * l - m * g * l), 16));
}

TYPED_TEST(model_definitions, spherical_pendulum_conical_motion) {
  using T = TypeParam;
  const T m = T(1), l = T(2), g = T(9);
  const models::spherical_pendulum<T> sp(m, l, g);
  // A conical pendulum at theta keeps theta when phidot^2 = g / (l cos theta).
  using std::cos;
  using std::sqrt;
  const T theta = T(1) / 2;
  dynamic_vector<T> q(2), v(2);
  q << theta, T(0);
  v << T(0), T(sqrt(T(g / (l * cos(theta)))));
  const dynamic_vector<T> a = accelerations(sp, q, v, T(0));
  EXPECT_TRUE(near_eps(T(a(0) + 1), T(1), 64));
  EXPECT_TRUE(near_eps(T(a(1) + 1), T(1), 64));
}

TYPED_TEST(model_definitions, spring_pendulum_hangs_at_mg_over_k_in_both_coordinates) {
  using T = TypeParam;
  const T m = T(2), k = T(8), l = T(1), g = T(10);
  const models::spring_pendulum<T> polar(m, k, l, g);
  const models::spring_pendulum_cartesian<T> cartesian(m, k, l, g);
  dynamic_vector<T> q(2), v(2);
  q << T(m * g / k), T(0);  // extension mg/k straight down: at rest
  v << T(0), T(0);
  const dynamic_vector<T> a = accelerations(polar, q, v, T(0));
  EXPECT_TRUE(near_eps(T(a(0) + 1), T(1), 16));
  EXPECT_TRUE(near_eps(T(a(1) + 1), T(1), 16));
  dynamic_vector<T> x(2);
  x << T(0), T(-(l + m * g / k));
  const dynamic_vector<T> b = accelerations(cartesian, x, v, T(0));
  EXPECT_TRUE(near_eps(T(b(0) + 1), T(1), 16));
  EXPECT_TRUE(near_eps(T(b(1) + 1), T(1), 16));
  // Displaced radially by d: xddot = -(k/m) d (the spring's frequency sqrt(k/m)).
  const T d = T(1) / 8;
  q(0) += d;
  EXPECT_TRUE(near_eps(accelerations(polar, q, v, T(0))(0), T(-(k / m) * d), 16));
}

TYPED_TEST(model_definitions, hamiltonian_systems_forces_and_energies) {
  using T = TypeParam;
  using vec = dynamic_vector<T>;
  // Kepler H = |p|^2/(2m) - k/|q|: at q = (3, 4), p = (1, 2), m = 2, k = 5: force
  // -k q / |q|^3 = -(3, 4)/25, energy 5/4 - 1.
  const kepler_system<T> kepler(T(2), T(5));
  vec q(2), p(2), f(2), dq(2);
  q << T(3), T(4);
  p << T(1), T(2);
  kepler.force(q, f);
  EXPECT_TRUE(near_eps(f(0), T(T(-3) / 25), 8));
  EXPECT_TRUE(near_eps(f(1), T(T(-4) / 25), 8));
  kepler.velocity(p, dq);
  EXPECT_TRUE(near_eps(dq(1), T(1), 4));
  EXPECT_TRUE(near_eps(kepler.energy(q, p), T(T(5) / 4 - 1), 8));
  // Oscillator H = |p|^2/(2m) + k |q|^2/2, m = 2, k = 3: force -k q, energy 5/4 + 75/2.
  const harmonic_oscillator_system<T> osc{T(2), T(3)};
  osc.force(q, f);
  EXPECT_TRUE(near_eps(f(1), T(-12), 4));
  EXPECT_TRUE(near_eps(osc.energy(q, p), T(T(5) / 4 + T(75) / 2), 8));
  // Pendulum H = p^2/(2 m l^2) - m g l cos q: m = 2, l = 1/2, g = 10 at q = pi/2: force
  // -m g l sin q = -10, energy p^2 / (2 * 1/2) = p^2.
  const pendulum_system<T> pend(T(2), T(1) / 2, T(10));
  vec q1(1), p1(1), f1(1);
  q1 << boost::math::constants::half_pi<T>();
  p1 << T(3);
  pend.force(q1, f1);
  EXPECT_TRUE(near_eps(f1(0), T(-10), 8));
  EXPECT_TRUE(near_eps(T(pend.energy(q1, p1)), T(9), 16));
}

}  // namespace models_test
