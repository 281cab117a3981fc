// Inertia tensors: typed errors on bad input, messages included.
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
            "box_inertia: edge a must be positive and finite, got -1");
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
}  // namespace
