// Robots: the Lagrangian reference against closed forms (a two-link arm, a slider), the
// description's validation and its URDF round trip. The dynamics audit's tests (every library
// against the closed form and on random robots, wrong libraries caught):
// dynamics_audit_test.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <utility>

#include <rapidcheck.h>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/robots.hpp"
#include "two_link_arm.hpp"

namespace robots_test {
using namespace mechcheck;
namespace rb = mechcheck::robots;
namespace audit = mechcheck::audit;

TEST(robots, the_lagrangian_gives_the_two_link_arms_closed_form_in_double_and_mpfr50) {
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, g = 9.81;
  const rb::robot r = two_link_arm(m1, m2, l1, c1, c2, i1, i2);
  const Eigen::Vector2d q(0.3, -0.7), qdot(1.1, 0.4);
  const arm_closed_form want = arm_terms(m1, m2, l1, c1, c2, i1, i2, g, q, qdot);
  const rb::robot_model<double> md(r);
  const rb::motion_terms<double> d = rb::motion_terms_at(md, Eigen::VectorXd(q), Eigen::VectorXd(qdot));
  constexpr double eps = 0x1p-52;
  // The closed form is itself evaluated in double: 32 eps of the terms' scale between them.
  EXPECT_LE((d.mass_matrix - want.m).cwiseAbs().maxCoeff(), 32 * eps * want.m.cwiseAbs().maxCoeff());
  EXPECT_LE((d.bias - want.h).cwiseAbs().maxCoeff(), 32 * eps * (m1 + m2) * g * 2);
  // mpfr50 rounded once agrees with double to the double's own rounding.
  const rb::robot_model<mpfr50> mm(r);
  const rb::motion_terms<mpfr50> e = rb::motion_terms_at(mm, dynamic_vector<mpfr50>(q.cast<mpfr50>()),
                                                         dynamic_vector<mpfr50>(qdot.cast<mpfr50>()));
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(static_cast<double>(e.mass_matrix(i)), want.m(i), 32 * eps * want.m.cwiseAbs().maxCoeff()) << i;
  // Forward after inverse returns the acceleration.
  const Eigen::VectorXd qddot = Eigen::Vector2d(-0.5, 2.0);
  const Eigen::VectorXd tau = rb::inverse_dynamics(md, Eigen::VectorXd(q), Eigen::VectorXd(qdot), qddot);
  EXPECT_LE((rb::forward_dynamics(md, Eigen::VectorXd(q), Eigen::VectorXd(qdot), tau) - qddot).cwiseAbs().maxCoeff(),
            1e-13);
}

TEST(robots, the_recursive_algorithms_give_the_two_link_arms_closed_form_with_its_rotors_and_damping) {
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, g = 9.81;
  rb::robot r = two_link_arm(m1, m2, l1, c1, c2, i1, i2);
  r.joints[0].armature = 0.125;
  r.joints[1].damping = 0.75;
  const Eigen::Vector2d q(0.3, -0.7), qdot(1.1, 0.4), qddot(-0.5, 2.0);
  arm_closed_form want = arm_terms(m1, m2, l1, c1, c2, i1, i2, g, q, qdot);
  want.m(0, 0) += 0.125;
  want.h(1) += 0.75 * qdot(1);
  const rb::robot_model<double> md(r);
  const Eigen::VectorXd qv = q, qdotv = qdot, qddotv = qddot;
  constexpr double eps = 0x1p-52;
  // Both sides evaluated in double: 32 eps of the terms' scale, as the Lagrangian's test.
  EXPECT_LE((rb::recursive_mass_matrix(md, qv) - want.m).cwiseAbs().maxCoeff(), 32 * eps * want.m.cwiseAbs().maxCoeff());
  EXPECT_LE((rb::recursive_bias(md, qv, qdotv) - want.h).cwiseAbs().maxCoeff(), 32 * eps * (m1 + m2) * g * 2);
  const Eigen::Vector2d tau = want.m * qddot + want.h;
  EXPECT_LE((rb::recursive_inverse_dynamics(md, qv, qdotv, qddotv) - tau).cwiseAbs().maxCoeff(),
            32 * eps * ((m1 + m2) * g * 2 + 2 * want.m.cwiseAbs().maxCoeff() * 2));
}

TEST(robots, the_recursive_algorithms_refuse_a_state_of_the_wrong_size_or_not_finite) {
  const rb::robot_model<double> m(two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625));
  const Eigen::VectorXd two = Eigen::Vector2d(0.3, -0.7), three = Eigen::Vector3d(0, 0, 0);
  Eigen::VectorXd nan = two;
  nan(1) = std::nan("");
  EXPECT_THROW(rb::recursive_mass_matrix(m, three), dimension_error);
  EXPECT_THROW(rb::recursive_bias(m, two, three), dimension_error);
  EXPECT_THROW(rb::recursive_inverse_dynamics(m, two, two, three), dimension_error);
  EXPECT_THROW(rb::recursive_mass_matrix(m, nan), non_finite_error);
  EXPECT_THROW(rb::recursive_bias(m, two, nan), non_finite_error);
  EXPECT_THROW(rb::recursive_inverse_dynamics(m, two, two, nan), non_finite_error);
}

/// A compiled inertia read back (a library's, MuJoCo's held robot) may be a few eps off
/// symmetric, as validate() allows: T sees only its symmetric part, and so must Euler's
/// equations in Newton-Euler, or the two references part by the asymmetry (1e-16 of |h| on
/// MuJoCo's held robots, before the model kept the symmetric part).
TEST(robots, an_inertia_a_few_eps_off_symmetric_gives_the_same_recursive_and_lagrangian_terms) {
  // The elbow turned to hinge about x, so that the forearm turns about two axes at once and
  // w x I w and I alpha reach I's off-diagonal entries.
  rb::robot r = two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625);
  r.joints[1].axis = {1, 0, 0};
  for (auto& link : r.links)
    if (link.body) {
      link.body->inertia = Eigen::Vector3d(0.5, 0.375, 0.25).asDiagonal();
      for (const auto& [i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
        link.body->inertia(i, j) = 0.03125;
        link.body->inertia(j, i) = 0.03125 * (1 + 0x1p-50);
      }
    }
  const rb::robot_model<mpfr50> m(r);
  const dynamic_vector<mpfr50> q = Eigen::Vector2d(0.3, -0.7).cast<mpfr50>(), qdot = Eigen::Vector2d(1.1, 0.4).cast<mpfr50>();
  const rb::motion_terms<mpfr50> e = rb::motion_terms_at(m, q, qdot);
  const dynamic_matrix<mpfr50> dm = rb::recursive_mass_matrix(m, q) - e.mass_matrix;
  const dynamic_vector<mpfr50> dh = rb::recursive_bias(m, q, qdot) - e.bias;
  // 128 n eps of mpfr50 on the terms, as the law robots.recursive_dynamics (term_scales; the
  // asymmetry left in, 2^-51 of an entry, would part them by about 2e-17).
  const rb::term_scale ts = rb::term_scales(m, Eigen::Vector2d(0.3, -0.7));
  const double inertia = std::max(static_cast<double>(e.mass_matrix.cwiseAbs().maxCoeff()), ts.inertia);
  const double k = 128.0 * 2 * static_cast<double>(std::numeric_limits<mpfr50>::epsilon());
  EXPECT_LE(static_cast<double>(dm.cwiseAbs().maxCoeff()), k * inertia);
  EXPECT_LE(static_cast<double>(dh.cwiseAbs().maxCoeff()), k * (ts.gravity + inertia * 1.1 * 1.1));
}

/// On trees larger than the laws' four links (up to twelve, branching, sliding, fixed joints):
/// the recursive M and h against the Lagrangian's in double, k = 128 n on term_scales, as the
/// law robots.recursive_dynamics.
TEST(robots, the_recursive_algorithms_agree_with_the_lagrangian_on_random_trees_of_twelve_links) {
  const std::string failure = seeded_check(20, [] {
    const generators::robot_case c = *generators::robot_cases(12);
    const rb::robot_model<double> m(c.robot);
    const Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(c.q.data(), Eigen::Index(c.q.size()));
    const Eigen::VectorXd qdot = Eigen::Map<const Eigen::VectorXd>(c.qdot.data(), Eigen::Index(c.qdot.size()));
    const rb::motion_terms<double> e = rb::motion_terms_at(m, q, qdot);
    const rb::term_scale ts = rb::term_scales(m, q);
    const double inertia = std::max(e.mass_matrix.cwiseAbs().maxCoeff(), ts.inertia);
    const double v = qdot.cwiseAbs().maxCoeff(), k = 128.0 * m.dofs() * 0x1p-52;
    RC_ASSERT((rb::recursive_mass_matrix(m, q) - e.mass_matrix).cwiseAbs().maxCoeff() <= k * inertia);
    RC_ASSERT((rb::recursive_bias(m, q, qdot) - e.bias).cwiseAbs().maxCoeff() <= k * (ts.gravity + inertia * v * v));
  });
  EXPECT_EQ(failure, "");
}

/// The free rigid body (two_link_arm.hpp: free_body) at a pose, twist and twist rate against
/// Newton and Euler in its own frame (free_body_terms).
template <class T>
void expect_free_body_closed_form() {
  const rb::robot r = free_body();
  const rb::robot_model<T> m(r);
  rb::pose at;
  at.xyz = {0.75, -0.5, 1.25};
  at.rpy = {0.5, -1.25, 2};
  const rb::base_pose<T> base = rb::base_pose_from<T>(at);
  dynamic_vector<T> u(6), udot(6);
  u << T(0.5), T(-1), T(1.5), T(2), T(-0.75), T(1.25);
  udot << T(-1), T(0.25), T(3), T(0.5), T(-2), T(1);
  const free_body_closed_form<T> closed = free_body_terms<T>(r, base.rotation, u, udot);
  const dynamic_vector<T>& want = closed.q;
  const dynamic_matrix<T>& mass = closed.m;
  const dynamic_vector<T> none(0);
  const rb::motion_terms<T> e = rb::floating_motion_terms_at(m, base, none, u);
  // Each side a few dozen roundings of terms up to |m g| and m |w|^2 |c| (about 30): 64 eps of
  // 64 (f, n) and of |M|.
  const T eps = std::numeric_limits<T>::epsilon(), forces = T(64), inertias = mass.cwiseAbs().maxCoeff();
  const auto expect_near = [&](const dynamic_vector<T>& got, const char* what) {
    for (int i = 0; i < 6; ++i) EXPECT_LE(T(abs(T(got(i) - want(i)))), 64 * eps * forces) << what << " " << i;
  };
  expect_near(rb::floating_recursive_inverse_dynamics(m, base, none, u, udot), "Newton-Euler");
  expect_near(dynamic_vector<T>(e.mass_matrix * udot + e.bias), "the chart's Euler-Lagrange");
  for (const auto& [got, what] : {std::pair{rb::floating_recursive_mass_matrix(m, base, none), "composite M"},
                                  std::pair{e.mass_matrix, "the Lagrangian's M"},
                                  std::pair{rb::base_spatial_inertia(m, base, none), "the spatial inertia"}})
    EXPECT_LE(T((got - mass).cwiseAbs().maxCoeff()), 64 * eps * inertias) << what;
}

TEST(robots, a_free_rigid_body_on_a_floating_base_obeys_newton_and_euler_in_its_own_frame) {
  expect_free_body_closed_form<double>();
  expect_free_body_closed_form<mpfr50>();
}

/// The two-link arm on a floating base held still (zero twist and zero twist rate) at any pose,
/// gravity turned with the base: its joints' forces are the bolted arm's closed form; the
/// base's force is the weight the hand holding it carries, R^T sum m (a_c - g).
TEST(robots, the_two_link_arm_on_a_base_held_still_has_the_bolted_arms_forces) {
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, g = 9.81;
  rb::robot r = two_link_arm(m1, m2, l1, c1, c2, i1, i2);
  rb::inertial torso;
  torso.mass = 5;
  torso.inertia = Eigen::Vector3d(0.5, 0.5, 0.25).asDiagonal();
  r.links[0].body = torso;
  rb::pose at;
  at.xyz = {0.25, 0.5, 1};
  at.rpy = {0.5, -0.25, 1.5};
  const rb::base_pose<double> base = rb::base_pose_from<double>(at);
  r.gravity = base.rotation * Eigen::Vector3d(0, 0, -g);
  const rb::robot_model<double> m(r);
  const Eigen::Vector2d q(0.3, -0.7), qdot(1.1, 0.4), qddot(-0.5, 2.0);
  const arm_closed_form want = arm_terms(m1, m2, l1, c1, c2, i1, i2, g, q, qdot);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(8), udot = Eigen::VectorXd::Zero(8);
  u.tail(2) = qdot;
  udot.tail(2) = qddot;
  const Eigen::VectorXd got = rb::floating_recursive_inverse_dynamics(m, base, Eigen::VectorXd(q), u, udot);
  constexpr double eps = 0x1p-52;
  const double scale = (m1 + m2) * g * 2 + 2 * want.m.cwiseAbs().maxCoeff() * 2;
  EXPECT_LE((got.tail(2) - (want.m * qddot + want.h)).cwiseAbs().maxCoeff(), 64 * eps * scale);
  // At rest with qddot = 0 the base carries the whole weight: f_b = -R^T g sum m.
  Eigen::VectorXd rest = Eigen::VectorXd::Zero(8);
  const Eigen::VectorXd held = rb::floating_recursive_inverse_dynamics(m, base, Eigen::VectorXd(q), rest, rest);
  EXPECT_LE((held.head(3) - Eigen::Vector3d(0, 0, g * (m1 + m2 + 5))).cwiseAbs().maxCoeff(), 64 * eps * scale);
}

TEST(robots, a_floating_base_refuses_a_state_of_the_wrong_size_and_a_joint_with_nothing_on_its_base_side) {
  rb::robot r = two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625);
  const rb::base_pose<double> base = rb::base_pose_from<double>(rb::pose{});
  const Eigen::VectorXd q = Eigen::Vector2d(0.3, -0.7), u = Eigen::VectorXd::Zero(8), short_u = Eigen::VectorXd::Zero(7);
  // The arm's base has no body: the shoulder's rate turns the same links as the base's.
  const rb::robot_model<double> bare(r);
  try {
    rb::floating_recursive_mass_matrix(bare, base, q);
    ADD_FAILURE() << "a shoulder with a massless base was taken";
  } catch (const rb::robot_error& e) {
    EXPECT_NE(std::string(e.what()).find("joint shoulder has no mass on the base's side"), std::string::npos) << e.what();
  }
  r.joints[0].armature = 0.125;  // a rotor gives the shoulder inertia of its own
  const rb::robot_model<double> m(r);
  EXPECT_NO_THROW(rb::floating_recursive_mass_matrix(m, base, q));
  EXPECT_THROW(rb::floating_recursive_bias(m, base, q, short_u), dimension_error);
  EXPECT_THROW(rb::floating_motion_terms_at(m, base, Eigen::VectorXd(Eigen::Vector3d::Zero()), u), dimension_error);
  Eigen::VectorXd nan = u;
  nan(3) = std::nan("");
  EXPECT_THROW(rb::floating_forward_dynamics(m, base, q, u, nan), non_finite_error);
  rb::pose bad;
  bad.rpy(1) = INFINITY;
  EXPECT_THROW(rb::base_pose_from<double>(bad), non_finite_error);
}

TEST(robots, the_kinematics_give_the_two_link_arms_closed_form) {
  // The arm turns about y and hangs along -z: R_y(a) takes (0, 0, -d) to (-d sin a, 0, -d cos a).
  // A point p = (0, 0, -d) of the forearm is at x = -(l1 s1 + d s12, 0, l1 c1 + d c12), with
  // s12 = sin(q1 + q2); J's columns are dx/dq1, dx/dq2 over omega = (0, 1, 0) each; Jdot qdot
  // at qddot = 0 is (l1 s1 w1^2 + d s12 w12^2, 0, l1 c1 w1^2 + d c12 w12^2), no angular part;
  // the centre of mass and the centroidal momentum from the links' centres and velocities.
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, d = 0.8;
  const rb::robot_model<double> m(two_link_arm(m1, m2, l1, c1, c2, i1, i2));
  const Eigen::VectorXd q = Eigen::Vector2d(0.3, -0.7), qdot = Eigen::Vector2d(1.1, 0.4);
  const double s1 = std::sin(q(0)), co1 = std::cos(q(0)), s12 = std::sin(q(0) + q(1)), co12 = std::cos(q(0) + q(1));
  const double w1 = qdot(0), w12 = qdot(0) + qdot(1);
  Eigen::MatrixXd j(6, 2);
  j << -l1 * co1 - d * co12, -d * co12, 0, 0, l1 * s1 + d * s12, d * s12, 0, 0, 1, 1, 0, 0;
  constexpr double eps = 0x1p-52;
  const int fore = 2;
  EXPECT_LE((rb::point_jacobian(m, q, fore, Eigen::Vector3d(0, 0, -d)) - j).cwiseAbs().maxCoeff(), 32 * eps * (l1 + d));
  Eigen::VectorXd a(6);
  a << l1 * s1 * w1 * w1 + d * s12 * w12 * w12, 0, l1 * co1 * w1 * w1 + d * co12 * w12 * w12, 0, 0, 0;
  EXPECT_LE((rb::point_bias_acceleration(m, q, qdot, fore, Eigen::Vector3d(0, 0, -d)) - a).cwiseAbs().maxCoeff(),
            32 * eps * (l1 + d) * w12 * w12);
  // The centres: upper at -c1 (s1, 0, c1), fore at -(l1 s1 + c2 s12, 0, l1 c1 + c2 c12).
  const Eigen::Vector3d x1 = -c1 * Eigen::Vector3d(s1, 0, co1);
  const Eigen::Vector3d x2 = -Eigen::Vector3d(l1 * s1 + c2 * s12, 0, l1 * co1 + c2 * co12);
  const Eigen::Vector3d v1 = -c1 * w1 * Eigen::Vector3d(co1, 0, -s1);
  const Eigen::Vector3d v2 = -Eigen::Vector3d(l1 * co1 * w1 + c2 * co12 * w12, 0, -l1 * s1 * w1 - c2 * s12 * w12);
  const Eigen::Vector3d c = (m1 * x1 + m2 * x2) / (m1 + m2);
  EXPECT_LE((rb::centre_of_mass(m, q) - c).cwiseAbs().maxCoeff(), 32 * eps * (l1 + c2));
  Eigen::VectorXd h(6);
  h << m1 * v1 + m2 * v2, Eigen::Vector3d(0, i1 * w1 + i2 * w12, 0) + m1 * (x1 - c).cross(v1) + m2 * (x2 - c).cross(v2);
  const double scale = (m1 + m2) * (l1 + c2) * (l1 + c2) * w12 + (i1 + i2) * w12;
  EXPECT_LE((rb::centroidal_momentum_matrix(m, q) * qdot - h).cwiseAbs().maxCoeff(), 32 * eps * scale);
  EXPECT_LE((rb::com_jacobian(m, q) * qdot - (m1 * v1 + m2 * v2) / (m1 + m2)).cwiseAbs().maxCoeff(),
            32 * eps * (l1 + c2) * w12);
  // Bad input: a link that is not the robot's, coordinates of the wrong size, a NaN or an
  // infinity among them or in the point.
  EXPECT_THROW(rb::point_jacobian(m, q, 3), domain_error);
  EXPECT_THROW(rb::point_jacobian(m, Eigen::VectorXd(Eigen::Vector3d::Zero()), 1), dimension_error);
  EXPECT_THROW(rb::point_bias_acceleration(m, q, Eigen::VectorXd(Eigen::Vector3d::Zero()), 1), dimension_error);
  const Eigen::VectorXd nan = Eigen::Vector2d(0.3, std::nan(""));
  EXPECT_THROW(rb::point_jacobian(m, nan, 1), non_finite_error);
  EXPECT_THROW(rb::point_bias_acceleration(m, q, nan, 1), non_finite_error);
  EXPECT_THROW(rb::centroidal_momentum(m, nan, qdot), non_finite_error);
  EXPECT_THROW(rb::point_jacobian(m, q, 1, Eigen::Vector3d(0, INFINITY, 0)), non_finite_error);
}

TEST(robots, a_slider_carries_its_own_and_its_childrens_mass) {
  // A prismatic joint along a skew axis under a revolute one: M(slide) = m2 + m3 whatever
  // the angle, and gravity's force along the slide is -(m2 + m3) g . a_world.
  rb::robot r;
  r.links.push_back({"base", std::nullopt});
  rb::inertial b;
  b.mass = 3;
  b.inertia = Eigen::Vector3d(1, 1, 1).asDiagonal();
  r.links.push_back({"carriage", b});
  b.mass = 0.5;
  b.origin.xyz = {0.25, 0, 0};
  r.links.push_back({"arm", b});
  rb::joint slide;
  slide.name = "slide";
  slide.type = rb::joint_type::prismatic;
  slide.parent = "base";
  slide.child = "carriage";
  slide.axis = Eigen::Vector3d(0, 0.6, 0.8);
  r.joints.push_back(slide);
  rb::joint spin;
  spin.name = "spin";
  spin.parent = "carriage";
  spin.child = "arm";
  spin.axis = {0, 0, 1};
  r.joints.push_back(spin);
  const rb::robot_model<double> m(r);
  for (const double angle : {0.0, 1.0, -2.5}) {
    const Eigen::VectorXd q = Eigen::Vector2d(0.3, angle), zero = Eigen::Vector2d::Zero();
    const Eigen::MatrixXd mm = rb::mass_matrix(m, q);
    EXPECT_NEAR(mm(0, 0), 3.5, 4 * 0x1p-52 * 3.5) << angle;
    EXPECT_NEAR(rb::gravity_forces(m, q)(0), 3.5 * 9.81 * 0.8, 16 * 0x1p-52 * 3.5 * 9.81) << angle;
  }
}

TEST(robots, a_description_that_is_not_a_robot_is_refused_by_name) {
  const rb::robot good = two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625);
  const auto refused = [](rb::robot r, const std::string& words) {
    try {
      rb::validate(r);
      ADD_FAILURE() << "accepted; expected: " << words;
    } catch (const rb::robot_error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  rb::robot r = good;
  r.joints[1].axis = {0, 2, 0};
  refused(r, "joint elbow: axis (0, 2, 0) is not a unit vector");
  r = good;
  r.joints[1].axis = {0, 0, 0};
  refused(r, "is not a unit vector");
  r = good;
  r.links[2].body->mass = -1;
  refused(r, "link fore: mass -1 is negative");
  r = good;
  r.links[2].body->mass = 0;
  refused(r, "link fore: mass 0 on a moving link must be positive");
  r = good;
  r.links[2].body->inertia = Eigen::Vector3d(1, 1, 3).asDiagonal();
  refused(r, "triangle inequality");
  r = good;
  r.links[2].body->inertia(0, 1) = 0.01;
  refused(r, "not symmetric");
  r = good;
  r.joints[0].parent = "fore";  // upper <- fore <- upper: a loop, no root
  refused(r, "loop");
  r = good;
  r.joints[1].parent = "nowhere";
  refused(r, "its parent \"nowhere\" is not a link");
  r = good;
  r.links.push_back({"stray", std::nullopt});
  refused(r, "both have no parent");
  r = good;
  r.joints[1].parent = "base";
  r.joints[1].child = "upper";
  refused(r, "link upper already has a parent (joint shoulder)");
  r = good;
  r.joints[1].child = "upper";
  refused(r, "link upper is its own parent");
}

TEST(robots, a_moving_joint_that_carries_no_mass_is_refused_by_name_and_a_massless_frame_is_not) {
  // A link without <inertial> is massless (urdfdom's reading): refused where it leaves a
  // moving joint with nothing to move (M's row and column zero), accepted elsewhere.
  const rb::robot good = two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625);
  rb::robot r = good;
  r.links[2].body.reset();  // the forearm, a moving leaf, massless
  try {
    rb::validate(r);
    ADD_FAILURE() << "a massless moving leaf was accepted";
  } catch (const rb::robot_error& e) {
    EXPECT_NE(std::string(e.what()).find("joint elbow moves link fore, which carries no mass, nor does any link below it"),
              std::string::npos) << e.what();
  }
  r = good;
  r.links[1].body.reset();  // the upper arm massless, the forearm below it not: M is regular
  EXPECT_NO_THROW(rb::validate(r));
  const rb::robot_model<double> m(r);
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(2);
  EXPECT_GT(rb::mass_matrix(m, q).determinant(), 0);
  r = good;
  r.links.push_back({"tool", std::nullopt});  // a frame on a fixed joint
  rb::joint tool;
  tool.name = "tool_mount";
  tool.type = rb::joint_type::fixed;
  tool.parent = "fore";
  tool.child = "tool";
  r.joints.push_back(tool);
  EXPECT_NO_THROW(rb::validate(r));
  rb::joint moving = tool;  // the same frame on a moving joint: nothing to move
  moving.type = rb::joint_type::continuous;
  r.joints.back() = moving;
  EXPECT_THROW(rb::validate(r), rb::robot_error);
}

TEST(robots, urdf_gives_an_axis_its_default_and_its_unit_length_and_says_so) {
  const std::string head = "<robot name='r'><link name='a'/><link name='b'><inertial><mass value='1'/>"
                           "<inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link>";
  const auto joint = [&](const std::string& type, const std::string& axis) {
    return head + "<joint name='j' type='" + type + "'><parent link='a'/><child link='b'/>" + axis + "</joint></robot>";
  };
  rb::robot r = audit::parse_urdf(joint("continuous", ""), "test.urdf");
  EXPECT_EQ(r.joints[0].axis, Eigen::Vector3d(1, 0, 0));
  ASSERT_EQ(r.readings.size(), 1u);
  EXPECT_EQ(r.readings[0], "test.urdf: robot r: joint j: no axis given: URDF's default (1, 0, 0)");
  r = audit::parse_urdf(joint("revolute", "<axis xyz='0 0 2'/>"), "test.urdf");
  EXPECT_EQ(r.joints[0].axis, Eigen::Vector3d(0, 0, 1));
  ASSERT_EQ(r.readings.size(), 1u);
  EXPECT_NE(r.readings[0].find("joint j: axis \"0 0 2\" (length 1 + 1) normalized to (0, 0, 1)"), std::string::npos)
      << r.readings[0];
  r = audit::parse_urdf(joint("continuous", "<axis xyz='0 0.7071 0.7071'/>"), "test.urdf");
  EXPECT_LE(std::abs(r.joints[0].axis.norm() - 1), 2 * 0x1p-52);
  ASSERT_EQ(r.readings.size(), 1u);
  EXPECT_NE(r.readings[0].find("(length 1 - 9.59"), std::string::npos) << r.readings[0];
  // A unit axis as written, and a fixed joint's axis (unused): kept, nothing said.
  r = audit::parse_urdf(joint("continuous", "<axis xyz='0 0.6 0.8'/>"), "test.urdf");
  EXPECT_EQ(r.joints[0].axis, Eigen::Vector3d(0, 0.6, 0.8));
  EXPECT_TRUE(r.readings.empty());
  r = audit::parse_urdf(joint("fixed", "<axis xyz='0 0 0'/>"), "test.urdf");
  EXPECT_TRUE(r.readings.empty());
  try {
    audit::parse_urdf(joint("continuous", "<axis xyz='0 0 0'/>"), "test.urdf");
    ADD_FAILURE() << "a zero axis was accepted";
  } catch (const rb::robot_error& e) {
    EXPECT_NE(std::string(e.what()).find("joint j: axis \"0 0 0\" has no direction"), std::string::npos) << e.what();
  }
}

TEST(robots, urdf_round_trips_every_number_and_refuses_what_is_not_urdf) {
  EXPECT_EQ(seeded_check(100, [] {
    const rb::robot r = (*audit::dynamics_robot_cases(8)).robot;  // fixed and floating
    const rb::robot back = audit::parse_urdf(audit::to_urdf(r), "round trip");
    RC_ASSERT(back.floating == r.floating);
    RC_ASSERT(back.links.size() == r.links.size());
    RC_ASSERT(back.joints.size() == r.joints.size());
    RC_ASSERT(back.gravity == r.gravity);
    for (std::size_t i = 0; i < r.links.size(); ++i) {
      RC_ASSERT(back.links[i].name == r.links[i].name);
      RC_ASSERT(back.links[i].body.has_value() == r.links[i].body.has_value());
      if (!r.links[i].body) continue;
      RC_ASSERT(back.links[i].body->mass == r.links[i].body->mass);
      RC_ASSERT(back.links[i].body->inertia == r.links[i].body->inertia);
      RC_ASSERT(back.links[i].body->origin.xyz == r.links[i].body->origin.xyz);
      RC_ASSERT(back.links[i].body->origin.rpy == r.links[i].body->origin.rpy);
    }
    for (std::size_t j = 0; j < r.joints.size(); ++j) {
      const rb::joint &a = r.joints[j], &b = back.joints[j];
      RC_ASSERT(a.name == b.name && a.parent == b.parent && a.child == b.child && a.type == b.type);
      RC_ASSERT(a.origin.xyz == b.origin.xyz && a.origin.rpy == b.origin.rpy);
      if (a.type != rb::joint_type::fixed) RC_ASSERT(a.axis == b.axis);
    }
  }), "");
  const auto refused = [](const std::string& text, const std::string& words) {
    try {
      audit::parse_urdf(text, "test.urdf");
      ADD_FAILURE() << "accepted; expected: " << words;
    } catch (const rb::robot_error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused("not xml <", "test.urdf: not XML");
  refused("<model/>", "not URDF: no <robot> element");
  const std::string head = "<robot name='r'><link name='a'/><link name='b'><inertial><mass value='1'/>"
                           "<inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link>";
  // A floating joint from a link that is nothing else floats the base; anywhere else it is
  // refused by name.
  const rb::robot floating =
      audit::parse_urdf(head + "<joint name='j' type='floating'><parent link='a'/><child link='b'/></joint></robot>", "f");
  EXPECT_TRUE(floating.floating);
  ASSERT_EQ(floating.links.size(), 1u);
  EXPECT_EQ(floating.links[0].name, "b");
  EXPECT_TRUE(floating.joints.empty());
  const std::string third = "<link name='c'><inertial><mass value='1'/><inertia ixx='1' ixy='0' ixz='0' iyy='1' "
                            "iyz='0' izz='1'/></inertial></link>";
  refused(head + third + "<joint name='k' type='revolute'><parent link='a'/><child link='c'/><axis xyz='0 0 1'/></joint>"
          "<joint name='j' type='floating'><parent link='a'/><child link='b'/></joint></robot>",
          "joint j (floating): its parent link a is joined to others (joint k)");
  refused(head + third + "<joint name='j' type='floating'><parent link='c'/><child link='b'/></joint></robot>",
          "joint j (floating): its parent link c has an <inertial>");
  refused(head + "<joint name='j' type='planar'><parent link='a'/><child link='b'/></joint></robot>",
          "joint j: type planar is not modelled");
  refused(head + "<joint name='j' type='hinge'><parent link='a'/><child link='b'/></joint></robot>",
          "joint j: unknown type \"hinge\"");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 1'/></joint></robot>",
          "joint j axis: \"0 1\" has 2 numbers, 3 expected");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/>"
                 "<origin xyz='0 0 x'/></joint></robot>",
          "joint j origin xyz: \"x\" is not a number");
  // Four numbers where URDF has three (xyz, rpy, axis): refused by name, not cut to three.
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 0 1 0'/></joint></robot>",
          "joint j axis: \"0 0 1 0\" has more than three numbers");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/>"
                 "<origin xyz='0.1 0.2 0.3 0.4'/></joint></robot>",
          "joint j origin xyz: \"0.1 0.2 0.3 0.4\" has more than three numbers");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/>"
                 "<origin rpy='0 0 0 1'/></joint></robot>",
          "joint j origin rpy: \"0 0 0 1\" has more than three numbers");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='c'/></joint></robot>",
          "its child \"c\" is not a link");
  // What URDF does not have is refused by name, not read as absent (issue 44, item 9).
  const std::string joint = "<joint name='j' type='revolute'><parent link='a'/><child link='b'/></joint></robot>";
  refused("<robot name='r'><link name='a'/><link name='b'><inertail><mass value='1'/></inertail></link>" + joint,
          "link b: <inertail> is not an element of URDF's <link> (it has inertial, visual, collision)");
  refused("<robot name='r'><link name='a'/><link name='b'><inertial><mass value='1'/><inertia ixx='1' iyx='0' "
          "ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link>" + joint,
          "link b inertia: iyx= is not an attribute of URDF's <inertia> (it has ixx, ixy, ixz, iyy, iyz, izz)");
  refused("<robot name='r'><link name='a'/><link name='b'><inertial><mass value='1'/><mass value='2'/><inertia "
          "ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link>" + joint,
          "link b inertial: <inertial> has more than one <mass>");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 0 1' "
                 "rpy='0 0 0'/></joint></robot>",
          "joint j axis: rpy= is not an attribute of URDF's <axis> (it has xyz)");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/><orgin xyz='0 0 1'/></joint></robot>",
          "joint j: <orgin> is not an element of URDF's <joint>");
  refused(head + "<joint name='j' type='revolute'><parent link='a'/><child link='b'/><origin xyz='0 0 1' "
                 "rpy='0 0 0' ryp='1 0 0'/></joint></robot>",
          "joint j origin: ryp= is not an attribute of URDF's <origin> (it has xyz, rpy)");
  refused(head + "<jiont name='k'/></robot>", "robot r: <jiont> is not an element of URDF's <robot>");
  // URDF's own elements that are not dynamics are accepted and not read.
  EXPECT_NO_THROW(audit::parse_urdf(
      "<robot name='r' xmlns:xacro='http://ros.org/wiki/xacro'><material name='m'/><link name='a'><visual/>"
      "<collision/><collision/></link><link name='b'><inertial><origin xyz='0 0 0' rpy='0 0 0'/><mass value='1'/>"
      "<inertia ixx='1' ixy='0' ixz='0' iyy='1' iyz='0' izz='1'/></inertial></link><joint name='j' type='revolute'>"
      "<parent link='a'/><child link='b'/><axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='1' velocity='1'/>"
      "<dynamics damping='0.1'/></joint><gazebo/></robot>",
      "test.urdf"));
}

TEST(robots, a_pose_held_as_a_quaternion_is_that_rotation_in_every_tier_where_roll_pitch_yaw_loses_digits) {
  // A rotation 2^-20 rad short of pitch pi/2: roll and yaw are nearly one angle there, and
  // rpy_of's atan2 of the small third row loses about 2^20 of eps (the round trip's error).
  const Eigen::Quaterniond turn =
      Eigen::AngleAxisd(0.75, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(M_PI / 2 - 0x1p-20, Eigen::Vector3d::UnitY()) *
      Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitX());
  rb::pose p;
  p.quaternion = Eigen::Vector4d(turn.w(), turn.x(), turn.y(), turn.z()) * 4;  // normalized where used
  p.rpy = {1, 2, 3};  // not read
  const Eigen::Quaternion<mpfr50> exact(mpfr50(turn.w()), mpfr50(turn.x()), mpfr50(turn.y()), mpfr50(turn.z()));
  const matrix3<mpfr50> reference = exact.normalized().toRotationMatrix();
  const auto off = [&](const Eigen::Matrix3d& r) { return static_cast<double>((r.cast<mpfr50>() - reference).norm()); };
  constexpr double eps = std::numeric_limits<double>::epsilon();
  EXPECT_LE(off(rb::pose_rotation<double>(p)), 4 * eps);
  EXPECT_LE(static_cast<double>((rb::pose_rotation<mpfr50>(p) - reference).norm()), 1e-45);
  const double round_trip = off(rb::rpy_rotation<double>(rb::rpy_of(rb::pose_rotation<double>(p))));
  EXPECT_GE(round_trip, 1024 * eps) << "the roll-pitch-yaw round trip kept its digits";
  std::printf("a rotation 2^-20 short of pitch pi/2: %.3g eps as a quaternion, %.3g eps through roll-pitch-yaw\n",
              off(rb::pose_rotation<double>(p)) / eps, round_trip / eps);
  // Without a quaternion, the pose is its roll-pitch-yaw; a zero or non-finite quaternion on a
  // joint is the description's error, named.
  p.quaternion.reset();
  EXPECT_EQ(rb::pose_rotation<double>(p), rb::rpy_rotation<double>(p.rpy));
  rb::robot r = two_link_arm(1, 2, 1, 0.5, 0.25, 0.125, 0.0625);
  r.joints[0].origin.quaternion = Eigen::Vector4d::Zero();
  EXPECT_THROW(rb::validate(r), non_finite_error);
  r.joints[0].origin.quaternion = Eigen::Vector4d(1, NAN, 0, 0);
  EXPECT_THROW(rb::validate(r), non_finite_error);
}

}  // namespace robots_test
