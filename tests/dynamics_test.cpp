// Lagrangian, Legendre and integrator errors on bad input, and tableau sanity.
#include <limits>

#include <gtest/gtest.h>

#include "mechcheck/mechcheck.hpp"
#include "tiers.hpp"

namespace {
using namespace mechcheck;
using mechcheck::test::near_eps;

using mechcheck::test::message_of;

/// L = (qdot_0 + qdot_1)^2 / 2: d2L/dqdot2 = [[1, 1], [1, 1]] is singular.
struct degenerate_lagrangian {
  template <class S>
  S operator()(const dynamic_vector<S>&, const dynamic_vector<S>& v, const S&) const {
    const S s = v(0) + v(1);
    return s * s * half<S>();
  }
};

TEST(dynamics_errors, singular_kinetic_matrix) {
  dynamic_vector<double> q(2), v(2);
  q << 1, 2;
  v << 0.5, -0.25;
  EXPECT_THROW(accelerations(degenerate_lagrangian{}, q, v, 0.0), singular_error);
  EXPECT_EQ(message_of([&] { accelerations(degenerate_lagrangian{}, q, v, 0.0); }),
            "accelerations: the kinetic matrix d2L/dqdot2 is singular (rank 1 of 2) at q = (1, 2), "
            "qdot = (0.5, -0.25), t = 0");
  const legendre_hamiltonian<degenerate_lagrangian> h{{}};
  EXPECT_THROW(h(q, v, 0.0), singular_error);
  EXPECT_NE(message_of([&] { h(q, v, 0.0); })
                .find("velocities_from_momenta: the kinetic matrix d2L/dqdot2 is singular (rank 1 of 2)"),
            std::string::npos);
}

// Newton for p = dL/dqdot starts at qdot = 0; for the relativistic particle,
// p = m v / sqrt(1 - v^2), its first step p/m leaves |v| < 1 whenever |p| > m and must be
// halved back. The solution is exactly v = p / sqrt(m^2 + p^2).
TEST(legendre, relativistic_particle_steps_back_inside_the_light_cone) {
  using pair = models::power_law_pair<double>;
  const models::velocity_coupled_system<double, pair> particle(
      {2.0}, pair(1.0, -1), models::kinetic_form::relativistic, 0.0, 0.0);
  dynamic_vector<double> q(3), p(3);
  q << 0.1, -0.2, 0.3;
  for (const double size : {0.5, 3.0, 40.0, 1e4, 1e8}) {
    p << size, -size / 2, size / 4;
    const dynamic_vector<double> v = velocities_from_momenta(particle, q, p, 0.0);
    const dynamic_vector<double> exact = p / std::sqrt(4.0 + p.squaredNorm());
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(near_eps(v(i), exact(i), 16)) << size;
  }
  dynamic_vector<double> fast(3);
  fast << 0.9, 0.5, 0.0;
  EXPECT_THROW(particle(q, fast, 0.0), domain_error);
  EXPECT_EQ(message_of([&] { particle(q, fast, 0.0); }),
            "velocity_coupled_system: relativistic particle 0 has |v|^2 = 1.0600000000000001, "
            "not below c^2 = 1");
}

TEST(dynamics_errors, non_finite_and_mismatched_state) {
  const models::free_particle<double> free(1.0);
  dynamic_vector<double> q(2), v(3);
  q << 1, 2;
  v << 0, 0, 0;
  EXPECT_EQ(message_of([&] { accelerations(free, q, v, 0.0); }),
            "accelerations: q has 2 components but qdot has 3");
  dynamic_vector<double> v2(2);
  v2 << std::numeric_limits<double>::infinity(), 0;
  EXPECT_THROW(accelerations(free, q, v2, 0.0), non_finite_error);
  EXPECT_EQ(message_of([&] { accelerations(free, q, v2, 0.0); }), "accelerations: qdot[0] = inf");
  EXPECT_EQ(message_of([] { models::free_particle<double>(0.0); }),
            "free_particle: mass must be positive and finite, got 0");
}

TEST(dynamics_errors, steppers_reject_non_finite_state) {
  using V = Eigen::Vector2d;
  const kepler_system<double> kepler(1.0, 1.0);
  stormer_verlet<kepler_system<double>, V> verlet(kepler);
  phase_state<V> x{V(1, std::numeric_limits<double>::quiet_NaN()), V(0, 1)};
  EXPECT_THROW(verlet(x, 0.1), non_finite_error);
  EXPECT_EQ(message_of([&] { verlet(x, 0.1); }), "stormer_verlet: state has q[1] = nan");
  gauss_legendre<kepler_system<double>, V, 2> gl(kepler);
  EXPECT_EQ(message_of([&] { gl(x, 0.1); }), "gauss_legendre: state has q[1] = nan");
  EXPECT_EQ(message_of([] { kepler_system<double>(1.0, -1.0); }),
            "kepler_system: k must be positive and finite, got -1");
}

TEST(dynamics_errors, a_step_that_overflows_says_so_and_leaves_the_state) {
  // Two particles 2 apart in U = -r^3 with h = 1: the kick 3 r^2 h / m is finite, but
  // |r|^2 of the drifted pair overflows double in the second kick's force.
  using V = dynamic_vector<double>;
  const pair_force_system<double, models::power_law_pair<double>> sys{{1e-300, 1e-300},
                                                                      {-1.0, 3}};
  stormer_verlet<decltype(sys), V> verlet(sys);
  V q(6), p(6);
  q << -1, 0, 0, 1, 0, 0;
  p << 0, 0, 0, 0, 0, 0;
  phase_state<V> x{q, p};
  EXPECT_THROW(verlet(x, 1.0), non_finite_error);
  EXPECT_EQ(x.q, q);
  EXPECT_EQ(x.p, p);
  const std::string m = message_of([&] { verlet(x, 1.0); });
  EXPECT_EQ(m.rfind("stormer_verlet: the step of h = 1 from q = (-1, 0, 0, 1, 0, 0), p = (0, 0, "
                    "0, 0, 0, 0) produced ", 0),
            0u)
      << m;
}

TEST(dynamics_errors, steps_must_be_finite_and_non_zero) {
  using V = Eigen::Vector2d;
  const kepler_system<double> kepler(1.0, 1.0);
  rk4<kepler_system<double>, V> method{kepler};
  phase_state<V> x{V(1, 0), V(0, 1)};
  EXPECT_EQ(message_of([&] { method(x, 0.0); }), "rk4: step h must be non-zero, got 0");
  EXPECT_THROW(method(x, std::numeric_limits<double>::infinity()), non_finite_error);
  EXPECT_EQ(message_of([&] { method(x, std::numeric_limits<double>::quiet_NaN()); }),
            "rk4: step h must be finite, got nan");
  EXPECT_EQ(x.q, V(1, 0));
  // In double h is checked after the step (the check costs nothing on the step's path):
  // an implicit method iterating on a bad h, a cached force, still name h.
  gauss_legendre<kepler_system<double>, V, 2> gl(kepler);
  EXPECT_EQ(message_of([&] { gl(x, 0.0); }), "gauss_legendre: step h must be non-zero, got 0");
  EXPECT_EQ(message_of([&] { gl(x, std::numeric_limits<double>::quiet_NaN()); }),
            "gauss_legendre: step h must be finite, got nan");
  stormer_verlet<kepler_system<double>, V> verlet(kepler);
  verlet(x, 0.1);
  const phase_state<V> before = x;
  EXPECT_EQ(message_of([&] { verlet(x, -std::numeric_limits<double>::infinity()); }),
            "stormer_verlet: step h must be finite, got -inf");
  EXPECT_EQ(message_of([&] { verlet(x, 0.0); }), "stormer_verlet: step h must be non-zero, got 0");
  EXPECT_EQ(x.q, before.q);
  EXPECT_EQ(x.p, before.p);
  x = {V(1, 0), V(0, 1)};
  method(x, -0.1);  // backwards in time is a step
  EXPECT_LT(x.q(1), 0);
}

TEST(dynamics_errors, implicit_step_that_cannot_converge) {
  // A stiff pendulum (w = 1000) with h = 1: the fixed-point iteration's contraction
  // factor is about h w >> 1, so it cannot converge, and the step says so.
  using V = Eigen::Matrix<double, 1, 1>;
  const pendulum_system<double> stiff{1.0, 1.0, 1.0e6};
  gauss_legendre<pendulum_system<double>, V, 3> gl(stiff);
  phase_state<V> x{V(0.5), V(0.0)};
  try {
    gl(x, 1.0);
    FAIL() << "no exception";
  } catch (const convergence_error& e) {
    EXPECT_NE(std::string(e.what()).find("gauss_legendre: the fixed-point iteration for the 3 "
                                         "stages did not converge in 500 iterations"),
              std::string::npos)
        << e.what();
  } catch (const non_finite_error& e) {
    EXPECT_NE(std::string(e.what()).find("gauss_legendre: stage derivatives became non-finite"),
              std::string::npos)
        << e.what();
  }
}

TEST(gauss_legendre_newton, beyond_double_the_stages_take_a_few_sweeps) {
  // In mpfr50 the fixed-point sweeps gain ~2.3 digits each on this orbit (17.9 sweeps a
  // step, measured before the Newton iteration); Newton's method with the Jacobian in
  // double gains ~15 (4.05 measured). A Jacobian that is wrong (a sign, a transposed
  // block, the wrong stage) still converges to the same stages, but slowly: this count
  // is what notices.
  using T = mpfr50;
  using V = Eigen::Matrix<T, 2, 1>;
  const kepler_system<T> kepler(T(1), T(1));
  gauss_legendre<kepler_system<T>, V, 4> gl(kepler);
  phase_state<V> x{V(T(1), T(0)), V(T(0), T(11) / 10)};
  const T h = 2 * boost::math::constants::pi<T>() / 500;
  const int steps = 200;
  for (int i = 0; i < steps; ++i) gl(x, h);
  const double sweeps = static_cast<double>(gl.sweeps()) / steps;
  EXPECT_LE(sweeps, 5.0) << sweeps << " sweeps a step";
  // Each Jacobian costs one evaluation per stage and state component (4 x 4).
  const double evaluations = static_cast<double>(gl.evaluations()) / steps;
  EXPECT_LE(evaluations, 4 * sweeps + 16 + 0.5) << evaluations << " evaluations a step";
  // In double the fixed point is kept (its sweeps are cheap and Brouwer's law is tuned
  // on it): 5.2 sweeps a step on the same orbit.
  using D = Eigen::Vector2d;
  gauss_legendre<kepler_system<double>, D, 4> gd(kepler_system<double>(1.0, 1.0));
  phase_state<D> y{D(1, 0), D(0, 1.1)};
  for (int i = 0; i < steps; ++i) gd(y, 2 * M_PI / 500);
  EXPECT_EQ(gd.evaluations(), 4 * gd.sweeps() + 1);  // + the first step's f(y)
}

template <class T>
class gauss_tableau : public ::testing::Test {};
TYPED_TEST_SUITE(gauss_tableau, mechcheck::test::all_tiers, mechcheck::test::tier_names);

TYPED_TEST(gauss_tableau, two_stage_matches_closed_form) {
  using T = TypeParam;
  using std::sqrt;
  const gauss_legendre_tableau<T> t(2);
  const T r = sqrt(T(3)) / 6;
  EXPECT_TRUE(near_eps(t.c[0], T(T(1) / 2 - r), 8));
  EXPECT_TRUE(near_eps(t.c[1], T(T(1) / 2 + r), 8));
  EXPECT_TRUE(near_eps(t.b[0], T(T(1) / 2), 8));
  EXPECT_TRUE(near_eps(t.a[0][0], T(T(1) / 4), 8));
  EXPECT_TRUE(near_eps(t.a[0][1], T(T(1) / 4 - r), 8));
  EXPECT_TRUE(near_eps(t.a[1][0], T(T(1) / 4 + r), 8));
}

// McLachlan's SB3A, derived in the tier: consistent, symmetric, the two third-order
// conditions to rounding, and (in double, correctly rounded) the decimals McLachlan published
// (a1 = 0.40518861839525227722, a2 = -0.28714404081652408900, also in Boost.Odeint).
TYPED_TEST(gauss_tableau, mclachlan_sb3a_coefficients_satisfy_the_order_conditions) {
  using T = TypeParam;
  const auto k = mclachlan_sb3a_coefficients<T>();
  ASSERT_EQ(k.a.size(), 6u);
  T sum_a = 0, sum_b = 0, c = 0, d = 0, kick = 0, drift = 0;
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(k.a[i], k.a[5 - i]);
    drift += k.a[i] * d * d;
    c += k.a[i];
    kick += k.b[i] * c * c;
    d += k.b[i];
    sum_a += k.a[i];
    sum_b += k.b[i];
  }
  EXPECT_TRUE(near_eps(sum_a, T(1), 8));
  EXPECT_TRUE(near_eps(sum_b, T(1), 8));
  EXPECT_TRUE(near_eps(kick, T(T(1) / 3), 16));
  EXPECT_TRUE(near_eps(drift, T(T(1) / 3), 16));
  if constexpr (std::is_same_v<T, double>) {
    EXPECT_TRUE(near_eps(k.a[0], 0.40518861839525227722, 1));
    EXPECT_TRUE(near_eps(k.a[1], -0.28714404081652408900, 1));
  }
}

TYPED_TEST(gauss_tableau, every_tableau_is_symplectic_and_consistent) {
  using T = TypeParam;
  for (int s = 1; s <= 4; ++s) {
    const gauss_legendre_tableau<T> t(s);
    T sum_b = 0;
    for (int i = 0; i < s; ++i) {
      sum_b += t.b[i];
      T row = 0;
      for (int j = 0; j < s; ++j) {
        row += t.a[i][j];
        // b_i a_ij + b_j a_ji = b_i b_j: the symplecticity condition of RK methods
        EXPECT_TRUE(near_eps(T(t.b[i] * t.a[i][j] + t.b[j] * t.a[j][i]), T(t.b[i] * t.b[j]), 64));
      }
      EXPECT_TRUE(near_eps(row, t.c[i], 64));
    }
    EXPECT_TRUE(near_eps(sum_b, T(1), 16));
  }
}

// Order 2s: the quadrature conditions B(2s), sum b_i c_i^(k-1) = 1/k for k <= 2s, and the
// collocation conditions C(s), sum_j a_ij c_j^(k-1) = c_i^k / k for k <= s, up to the 12
// stages the tableau offers (10 carry the certified references in mpfr50).
TYPED_TEST(gauss_tableau, tableaus_up_to_twelve_stages_satisfy_B_2s_and_C_s) {
  using T = TypeParam;
  for (int s : {5, 8, 10, 12}) {
    const gauss_legendre_tableau<T> t(s);
    for (int k = 1; k <= 2 * s; ++k) {
      T sum = 0;
      for (int i = 0; i < s; ++i) sum += t.b[i] * pow(t.c[i], T(k - 1));
      EXPECT_TRUE(near_eps(sum, T(T(1) / T(k)), 64 * s)) << "s = " << s << ", B(" << k << ")";
    }
    for (int i = 0; i < s; ++i)
      for (int k = 1; k <= s; ++k) {
        T sum = 0;
        for (int j = 0; j < s; ++j) sum += t.a[i][j] * pow(t.c[j], T(k - 1));
        EXPECT_TRUE(near_eps(sum, T(pow(t.c[i], T(k)) / T(k)), 256 * s)) << "s = " << s << ", C(" << k << ") row " << i;
      }
  }
}

TYPED_TEST(gauss_tableau, triple_jump_weights_sum_to_one) {
  using T = TypeParam;
  for (int order : {4, 6, 8}) {
    T sum = 0;
    T odd = 0;  // sum w^3 vanishes: the order-3 condition of a symmetric composition
    for (const T& w : triple_jump_weights<T>(order)) {
      sum += w;
      odd += w * w * w;
    }
    EXPECT_TRUE(near_eps(sum, T(1), 64)) << order;
    EXPECT_TRUE(near_eps(T(odd + 1), T(1), 1024)) << order;
  }
  EXPECT_EQ(message_of([] { triple_jump_weights<double>(5); }),
            "triple_jump_weights: order must be even and >= 2, got 5");
}
}  // namespace

namespace {
TEST(pair_force_system, force_is_minus_gradient_and_energy_matches_the_model) {
  using namespace mechcheck;
  const models::lennard_jones_pair<double> lj{0.5, 0.9};
  const pair_force_system<double, models::lennard_jones_pair<double>> sys{{1.0, 2.0, 0.5}, lj};
  const models::particle_system<double, models::lennard_jones_pair<double>> model({1.0, 2.0, 0.5},
                                                                                  lj);
  dynamic_vector<double> q(9), p(9), f(9), v(9);
  q << 0, 0, 0, 1.1, 0.2, -0.1, -0.3, 0.9, 0.4;
  p << 0.1, -0.2, 0.3, 0.0, 0.5, -0.1, 0.2, 0.2, 0.2;
  sys.force(q, f);
  const auto potential = [&model]<class S>(const dynamic_vector<S>& x) -> S { return model.potential(x); };
  const dynamic_vector<double> grad = gradient(potential, q);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(f(i), -grad(i), 64 * std::numeric_limits<double>::epsilon() * grad.norm()) << i;
  for (int i = 0; i < 9; ++i) v(i) = p(i) / model.masses[i / 3];
  EXPECT_DOUBLE_EQ(sys.energy(q, p), model.kinetic(v) + model.potential(q));
  // Pair forces cancel: total force zero to rounding.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f(c) + f(3 + c) + f(6 + c), 0.0, 8 * std::numeric_limits<double>::epsilon() * f.norm());
}
}  // namespace
