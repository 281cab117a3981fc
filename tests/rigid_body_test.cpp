// Inertia tensors: typed errors on bad input, messages included.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "mechcheck/reference.hpp"
#include "mechcheck/rigid_body.hpp"
#include "tiers.hpp"

namespace {
using namespace mechcheck;
using mechcheck::test::message_of;
using V = vector3<double>;
using M = matrix3<double>;

TEST(inertia_errors, masses_and_positions) {
  const point_cloud<double> zero_mass{{1.0, 0.0}, {V(0, 0, 0), V(1, 0, 0)}};
  EXPECT_THROW(inertia_tensor(zero_mass, V::Zero().eval()), domain_error);
  EXPECT_EQ(message_of([&] { inertia_tensor(zero_mass, V::Zero().eval()); }),
            "inertia_tensor: mass 1 must be positive and finite, got 0");
  const point_cloud<double> negative{{-2.0}, {V(0, 0, 0)}};
  EXPECT_EQ(message_of([&] { centre_of_mass(negative); }),
            "centre_of_mass: mass 0 must be positive and finite, got -2");
  const point_cloud<double> nan_position{{1.0}, {V(0, std::numeric_limits<double>::quiet_NaN(), 0)}};
  EXPECT_THROW(inertia_tensor(nan_position, V::Zero().eval()), non_finite_error);
  EXPECT_EQ(message_of([&] { inertia_tensor(nan_position, V::Zero().eval()); }),
            "inertia_tensor: position 0 has component 1 = nan");
  const point_cloud<double> mismatched{{1.0, 2.0}, {V(0, 0, 0)}};
  EXPECT_EQ(message_of([&] { inertia_tensor(mismatched, V::Zero().eval()); }),
            "inertia_tensor: 2 masses for 1 positions");
  EXPECT_EQ(message_of([] { reference::cube_inertia(1.0, -1.0); }),
            "cube_inertia: edge l must be positive and finite, got -1");
}

TEST(inertia_errors, invalid_tensors) {
  M not_symmetric;
  not_symmetric << 2, 0.5, 0, 0, 2, 0, 0, 0, 2;
  EXPECT_THROW(validate_inertia(not_symmetric, "check"), domain_error);
  EXPECT_EQ(message_of([&] { validate_inertia(not_symmetric, "check"); }),
            "check: inertia tensor is not symmetric: I(0,1) = 0.5 but I(1,0) = 0");
  const M negative = M(V(1, 2, -1).asDiagonal());
  EXPECT_EQ(message_of([&] { validate_inertia(negative, "check"); }),
            "check: inertia tensor is not positive semi-definite: principal moment -1");
  const M triangle = M(V(1, 1, 3).asDiagonal());
  EXPECT_EQ(message_of([&] { validate_inertia(triangle, "check"); }),
            "check: principal moments violate the triangle inequality I1 + I2 >= I3: 1 + 1 < 3");
  M infinite = M::Identity();
  infinite(2, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(validate_inertia(infinite, "check"), non_finite_error);
  EXPECT_EQ(message_of([&] { principal_axes(infinite); }),
            "principal_axes: inertia tensor entry (2,1) = inf");
  EXPECT_THROW(classify(infinite), non_finite_error);
}

TEST(inertia_errors, valid_tensors_pass_after_a_shift) {
  // A thin rod (I3 = 0: the triangle inequality holds with equality) shifted far away.
  const M rod = reference::thin_rod_inertia(2.0, 3.0);
  EXPECT_NO_THROW(validate_inertia(rod, "check"));
  EXPECT_NO_THROW(validate_inertia(shift_from_centre(rod, 2.0, V(1e3, -2e3, 5e2)), "check"));
  EXPECT_EQ(classify(reference::solid_sphere_inertia(1.0, 2.0)), top_kind::spherical);
  EXPECT_EQ(classify(reference::solid_cylinder_inertia(1.0, 2.0, 1.0)), top_kind::symmetric);
  EXPECT_EQ(classify(reference::box_inertia(1.0, 1.0, 2.0, 3.0)), top_kind::asymmetric);
}

TEST(inertia, a_prolate_and_an_oblate_body_are_symmetric_and_a_near_tie_is_judged_by_the_tolerance) {
  // A long cylinder (r = 0.1, h = 2): I1 = m r^2 / 2 = 0.005 below I2 = I3 = m (3 r^2 + h^2) / 12
  // (prolate); a flat one (r = 2, h = 1): I1 = I2 = 13/12 below I3 = 2 (oblate).
  EXPECT_EQ(classify(reference::solid_cylinder_inertia(1.0, 0.1, 2.0)), top_kind::symmetric);
  EXPECT_EQ(classify(reference::solid_cylinder_inertia(1.0, 2.0, 1.0)), top_kind::symmetric);
  // Two moments apart by 64 eps I_max (the default tolerance is 64 eps I_max = 128 eps
  // here): tied; by 200 eps: not, on either side of the middle moment.
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (const double apart : {64 * eps, 200 * eps}) {
    const top_kind expected = apart < 128 * eps ? top_kind::symmetric : top_kind::asymmetric;
    EXPECT_EQ(classify(M(V(1, 2, 2 + apart).asDiagonal())), expected) << apart / eps;
    EXPECT_EQ(classify(M(V(1, 1 + apart, 2).asDiagonal())), expected) << apart / eps;
  }
}


TEST(top_errors, free_body_moments) {
  EXPECT_EQ(message_of([] { free_rigid_body<double>(V(1, 0, 1)); }),
            "free_rigid_body: principal moment I2 must be positive and finite, got 0");
  EXPECT_EQ(message_of([] { free_rigid_body<double>(V(1, 2, 3.5)); }),
            "free_rigid_body: principal moments violate the triangle inequality I1 + I2 >= I3: "
            "1 + 2 < 3.5");
  const free_rigid_body<double> body(V(1, 2, 2.5));
  dynamic_vector<double> q(3), p(4), dq(3), dp(4);
  q.setZero();
  p.setZero();
  EXPECT_EQ(message_of([&] { body.vector_field(q, p, dq, dp); }),
            "free_rigid_body: the state is M (3 components) and the rows of R (9, or none), "
            "got 3 and 4");
}

TEST(top_errors, heavy_top) {
  EXPECT_EQ(message_of([] { heavy_top<double>(-1, 1, 1); }),
            "heavy_top: I1 must be positive and finite, got -1");
  const heavy_top<double> top(1, 0.5, 1);
  EXPECT_EQ(message_of([&] { top.steady_precession_rates(0.5, 1); }),
            "heavy_top::steady_precession_rates: Omega_3 = 1 is below the minimum spin for "
            "theta = 0.5 (discriminant -3.260330247561491)");  // 0.5^2 - 4 cos(0.5)
  EXPECT_THROW(top.minimum_spin(2.0), domain_error);  // hanging below the pivot
  EXPECT_THROW(top.nutation_from_turning_point(0.0, 1.0, 2.0), domain_error);
  EXPECT_THROW(heavy_top<double>(1, 1, 0).nutation_from_turning_point(0.5, 1.0, 2.0),
               domain_error);
  EXPECT_EQ(message_of([&] { top.nutation_from_turning_point(0.5, std::nan(""), 2.0); }),
            "heavy_top::nutation_from_turning_point: theta0 = 0.5, phidot0 = nan, Omega_3 = 2");
}

TEST(top_errors, asymmetric_reference) {
  EXPECT_EQ(message_of([] { reference::asymmetric_top_angular_velocity(V(1, 1, 1.5), V(1, 1, 1), 0.0); }),
            "asymmetric_top_angular_velocity: need 0 < I1 < I2 < I3, got (1, 1, 1.5)");
  EXPECT_THROW(reference::asymmetric_top_angular_velocity(V(1, 2, 2.5), V(1, std::nan(""), 1), 0.0),
               non_finite_error);
  // M^2 = 2 E I2 exactly: Omega = (3, 0, 1) with I = (2, 3, 6): M^2 = 72, 2E = 24.
  EXPECT_EQ(message_of([] { reference::asymmetric_top_angular_velocity(V(2, 3, 6), V(3, 0, 1), 0.0); }),
            "asymmetric_top_angular_velocity: M^2 = 2 E I2 (the separatrix)");
}

// The period: Omega(T) = Omega(0) to rounding, and at T / 2 Omega_1 and Omega_2 have turned
// sign (cn(2K) = -1, sn(2K) = 0 from sn = 0), for both sides of the separatrix (M^2 > 2 E I2
// about axis 3, M^2 < 2 E I2 about axis 1 after the exchange).
TEST(top_reference, period) {
  const V moments(1, 2, 3);
  for (const V& omega0 : {V(0.3, 0, 0.5), V(1, 0, 0.2), V(0.01, 1, 0.01)}) {
    const double t = reference::asymmetric_top_period(moments, omega0);
    const V back = reference::asymmetric_top_angular_velocity(moments, omega0, t);
    const V half = reference::asymmetric_top_angular_velocity(moments, omega0, t / 2);
    const double tol = 64 * std::numeric_limits<double>::epsilon() * omega0.norm() * (1 + t);
    EXPECT_LT((back - omega0).norm(), tol) << omega0.transpose() << " T = " << t;
    EXPECT_GT((half - omega0).norm(), 0.1 * omega0.norm()) << omega0.transpose();
  }
  EXPECT_THROW(reference::asymmetric_top_period(V(1, 1, 1.5), V(1, 1, 1)), domain_error);
}

// Boost.Math's jacobi_elliptic returns a wrong dn at the quarter period; the reference
// takes dn from sn. Omega(0) with Omega_1 = 0 puts the phase exactly there.
TEST(top_reference, quarter_period_phase) {
  const V moments(0.625, 0.75, 0.875);
  const V omega0(0, 1.0 / 192, 1.0 / 224);
  const V at_zero = reference::asymmetric_top_angular_velocity(moments, omega0, 0.0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(at_zero(i), omega0(i), 4e-18) << i;
}
}  // namespace
