// The dynamics audit: a library against the exact Lagrangian -- every library this build
// found against the two-link arm's closed form and on random robots, wrong libraries caught
// (the budget, the scales, a library that holds another robot), a campaign's records. A
// joint's armature and damping: joint_terms_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <rapidcheck.h>

#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/robots.hpp"
#include "dynamics_fakes.hpp"
#include "two_link_arm.hpp"

namespace dynamics_audit_test {
using namespace mechcheck;
namespace rb = mechcheck::robots;
namespace audit = mechcheck::audit;
using dynamics_fakes::disagrees;
using dynamics_fakes::floating_state;
using dynamics_fakes::wrong_library;
using robots_test::arm_closed_form;
using robots_test::arm_terms;
using robots_test::seeded_check;
using robots_test::two_link_arm;

using audit::state_of;
using robots_test::free_body;
using robots_test::free_body_closed_form;
using robots_test::free_body_terms;


TEST(dynamics_audit, the_reference_in_double_is_within_its_budget_and_wrong_libraries_are_not) {
  // The reference's own double evaluation passes; a transposed inertia rotation, an axis
  // taken in the parent's frame and a parallel-axis sign each fail on the arm.
  const rb::robot arm = [] {
    rb::robot r = two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625);
    r.links[2].body->origin.rpy = {0.3, -0.2, 0.5};
    r.links[2].body->inertia << 0.125, 0.01, 0, 0.01, 0.0625, 0.02, 0, 0.02, 0.09;
    r.joints[1].origin.rpy = {0, 0.4, 0};
    r.joints[1].axis = Eigen::Vector3d(0.6, 0.8, 0);
    return r;
  }();
  audit::dynamics_state x;
  x.q = Eigen::Vector2d(0.3, -0.7);
  x.qdot = Eigen::Vector2d(1.1, 0.4);
  x.qddot = Eigen::Vector2d(-0.5, 2.0);
  x.tau = Eigen::Vector2d(3.0, -1.0);
  const audit::dynamics_check right = audit::check_dynamics(wrong_library([](rb::robot&) {}), arm, x);
  ASSERT_EQ(right.residuals.size(), 4u);
  for (const auto& r : right.residuals)
    EXPECT_TRUE(r.within()) << audit::dynamics_quantity_name(r.quantity) << ": " << r.residual << " eps";
  const auto fails = [&](const char* what, std::function<void(rb::robot&)> change) {
    EXPECT_TRUE(disagrees(audit::check_dynamics(wrong_library(change), arm, x))) << what;
  };
  fails("a transposed inertia rotation", [](rb::robot& r) {
    r.links[2].body->origin.rpy = -r.links[2].body->origin.rpy;
  });
  fails("the axis in the parent's frame", [](rb::robot& r) {
    r.joints[1].axis = rb::rpy_rotation<double>(r.joints[1].origin.rpy) * r.joints[1].axis;
  });
  fails("the centre of mass on the other side", [](rb::robot& r) { r.links[1].body->origin.xyz *= -1; });
}

TEST(dynamics_audit, a_library_that_holds_another_robot_is_judged_on_it_and_the_difference_measured) {
  // MuJoCo's compiler changes a link's inertia by about 1e-8 relative (docs/findings/dynamics.md):
  // a library that computes exactly with such a changed robot disagrees with the given robot's
  // Lagrangian unless it says which robot it holds; then it agrees with that robot's, and the
  // distance between the two robots' mass matrices is measured in eps of the scale.
  const rb::robot arm = two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625);
  audit::dynamics_state x;
  x.q = Eigen::Vector2d(0.3, -0.7);
  x.qdot = Eigen::Vector2d(1.1, 0.4);
  x.qddot = Eigen::Vector2d(-0.5, 2.0);
  x.tau = Eigen::Vector2d(3.0, -1.0);
  const double delta = 0x1p-26;  // 1.5e-8 of the forearm's moment about its hinge (y), 1/16
  const auto changed = [delta](rb::robot& r) { r.links[2].body->inertia(1, 1) *= 1 + delta; };
  const audit::dynamics_check silent = audit::check_dynamics(wrong_library(changed), arm, x);
  EXPECT_FALSE(silent.model_difference);
  bool any = false;
  for (const auto& r : silent.residuals) any = any || !r.within();
  EXPECT_TRUE(any) << "a changed robot not declared";
  const audit::dynamics_check declared = audit::check_dynamics(wrong_library(changed, true), arm, x);
  for (const auto& r : declared.residuals)
    EXPECT_TRUE(r.within()) << audit::dynamics_quantity_name(r.quantity) << ": " << r.residual << " eps";
  ASSERT_TRUE(declared.model_difference);
  // Every entry of M holds i2 once (both hinges are about y): the change is delta i2 = 2^-30
  // exactly, over eps and the scale of M; each M is rounded once to double before the
  // difference, half an ulp of its largest entry each: under 1 eps of the scale together.
  const double want = 0x1p-30 / (0x1p-52 * declared.model_scale);
  EXPECT_NEAR(*declared.model_difference, want, 1.0);
}

TEST(dynamics_audit, every_library_gives_the_two_link_arms_closed_form) {
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, g = 9.81;
  const rb::robot r = two_link_arm(m1, m2, l1, c1, c2, i1, i2);
  audit::dynamics_state x;
  x.q = Eigen::Vector2d(0.3, -0.7);
  x.qdot = Eigen::Vector2d(1.1, 0.4);
  x.qddot = Eigen::Vector2d(-0.5, 2.0);
  x.tau = Eigen::Vector2d(3.0, -1.0);
  const arm_closed_form want = arm_terms(m1, m2, l1, c1, c2, i1, i2, g, Eigen::Vector2d(x.q), Eigen::Vector2d(x.qdot));
  for (const audit::dynamics_library& library : audit::dynamics_found()) {
    const audit::dynamics_check c = audit::check_dynamics(library, r, x);
    ASSERT_TRUE(c.refused.empty()) << library.name << ": " << c.refused;
    // Every library offers forward dynamics; Bullet's core nothing else.
    ASSERT_FALSE(c.residuals.empty()) << library.name;
    // Kinematics: frames and Jacobians (at the frames' origins and the links' centres of mass)
    // in KDL, MuJoCo, DART and Simbody, Jdot qdot in all but
    // MuJoCo; the centre of mass and J_c in MuJoCo, DART and Simbody, A_G in MuJoCo and Simbody.
    const std::size_t kinematics = library.name == "kdl"       ? 4
                                   : library.name == "dart"    ? 6
                                   : library.name == "simbody" ? 7
                                   : library.name == "mujoco"  ? 6
                                                               : 0;
    EXPECT_EQ(c.residuals.size(), library.name == "bullet" ? 1u : 4u + kinematics) << library.name;
    EXPECT_EQ(c.residuals[c.residuals.size() - kinematics - 1].quantity, audit::dynamics_quantity::forward)
        << library.name;
    if (c.residuals[0].quantity == audit::dynamics_quantity::mass_matrix)
      EXPECT_LE((c.residuals[0].library - want.m).cwiseAbs().maxCoeff(), 32 * 0x1p-52 * want.m.cwiseAbs().maxCoeff())
          << library.name;
    for (const auto& res : c.residuals)
      EXPECT_TRUE(res.within()) << library.name << ": " << audit::dynamics_quantity_name(res.quantity) << ": "
                                << res.residual << " eps of budget " << res.budget;
  }
}

/// The kinematics of the arm in closed form: the frames of base, upper arm and forearm (12 x 3,
/// origin over the rotation's columns) and their Jacobians (18 x 2, rows (v_o; omega) a link):
/// both hinges about y, R_y(a) = ((cos a, 0, sin a), (0, 1, 0), (-sin a, 0, cos a)); the elbow
/// at R_y(q1) (0, 0, -l1) = (-l1 sin q1, 0, -l1 cos q1), moved by the shoulder at
/// e_y x elbow = (-l1 cos q1, 0, l1 sin q1); each hinge's origin on its axis.
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> arm_kinematics(double l1, const Eigen::Vector2d& q) {
  const auto ry = [](double a) {
    Eigen::Matrix3d r;
    r << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
    return r;
  };
  const Eigen::Matrix3d frames[3] = {Eigen::Matrix3d::Identity(), ry(q(0)), ry(q(0) + q(1))};
  const Eigen::Vector3d origins[3] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                      Eigen::Vector3d(-l1 * std::sin(q(0)), 0, -l1 * std::cos(q(0)))};
  Eigen::MatrixXd poses(12, 3), jacobians = Eigen::MatrixXd::Zero(18, 2);
  for (int l = 0; l < 3; ++l) poses.col(l) << origins[l], frames[l].col(0), frames[l].col(1), frames[l].col(2);
  jacobians(10, 0) = 1;  // the upper arm turns about y with the shoulder
  jacobians.block<6, 1>(12, 0) << -l1 * std::cos(q(0)), 0, l1 * std::sin(q(0)), 0, 1, 0;
  jacobians(16, 1) = 1;  // the forearm with both
  return {poses, jacobians};
}

/// The arm's Jdot qdot (18 x 1, (a_o; alpha) a link): the elbow circles the shoulder, its
/// acceleration at qddot = 0 the centripetal -qdot1^2 elbow = (l1 sin q1, 0, l1 cos q1) qdot1^2;
/// every angular acceleration about the fixed y is qddot's, zero.
Eigen::VectorXd arm_bias_accelerations(double l1, const Eigen::Vector2d& q, const Eigen::Vector2d& qdot) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(18);
  out.segment<3>(12) << l1 * std::sin(q(0)) * qdot(0) * qdot(0), 0, l1 * std::cos(q(0)) * qdot(0) * qdot(0);
  return out;
}

/// The arm's centre of mass, J_c and A_G (the centres of mass at x1 = R_y(q1) (0, 0, -c1) and
/// x2 = elbow + R_y(q1 + q2) (0, 0, -c2), their derivatives in closed form; each inertia's y
/// moment i about the hinges' y, which R_y keeps: the spin i omega e_y; the orbit's angular
/// momentum about c only along y, (a x b)_y = a_z b_x - a_x b_z).
struct arm_mass_terms {
  Eigen::MatrixXd com, com_jacobian, momentum_matrix;
  Eigen::MatrixXd link_com_jacobians;  ///< 18 x 2: each link's at its centre of mass, (dx/dq; e_y)
};
arm_mass_terms arm_mass(double m1, double m2, double l1, double c1, double c2, double i1, double i2,
                        const Eigen::Vector2d& q) {
  const double s1 = std::sin(q(0)), k1 = std::cos(q(0)), s12 = std::sin(q(0) + q(1)), k12 = std::cos(q(0) + q(1));
  const Eigen::Vector3d x1(-c1 * s1, 0, -c1 * k1), x2(-l1 * s1 - c2 * s12, 0, -l1 * k1 - c2 * k12);
  Eigen::Matrix<double, 3, 2> d1, d2;  // dx/dq
  d1 << -c1 * k1, 0, 0, 0, c1 * s1, 0;
  d2 << -l1 * k1 - c2 * k12, -c2 * k12, 0, 0, l1 * s1 + c2 * s12, c2 * s12;
  const double m = m1 + m2;
  arm_mass_terms out;
  const Eigen::Vector3d c = (m1 * x1 + m2 * x2) / m;
  out.com = c;
  out.com_jacobian = (m1 * d1 + m2 * d2) / m;
  out.link_com_jacobians = Eigen::MatrixXd::Zero(18, 2);
  out.link_com_jacobians.block<3, 2>(6, 0) = d1;
  out.link_com_jacobians(10, 0) = 1;
  out.link_com_jacobians.block<3, 2>(12, 0) = d2;
  out.link_com_jacobians.block<1, 2>(16, 0).setOnes();
  out.momentum_matrix = Eigen::MatrixXd::Zero(6, 2);
  out.momentum_matrix.topRows<3>() = m1 * d1 + m2 * d2;
  const Eigen::Vector3d r1 = x1 - c, r2 = x2 - c;
  for (int k = 0; k < 2; ++k)
    out.momentum_matrix(4, k) = (k == 0 ? i1 : 0.0) + i2 + m1 * (r1(2) * d1(0, k) - r1(0) * d1(2, k)) +
                                m2 * (r2(2) * d2(0, k) - r2(0) * d2(2, k));
  return out;
}

TEST(dynamics_audit, every_library_with_kinematics_gives_the_arms_frames_and_jacobians_in_closed_form) {
  const double l1 = 1.25;
  const rb::robot r = two_link_arm(2, 1.5, l1, 0.5, 0.375, 0.25, 0.0625);
  audit::dynamics_state x;
  x.q = Eigen::Vector2d(0.3, -0.7);
  x.qdot = Eigen::Vector2d(1.1, 0.4);
  x.qddot = Eigen::Vector2d(-0.5, 2.0);
  x.tau = Eigen::Vector2d(3.0, -1.0);
  // Named, not a structured binding: Clang 14 does not capture bindings in a lambda.
  const std::pair<Eigen::MatrixXd, Eigen::MatrixXd> frames = arm_kinematics(l1, Eigen::Vector2d(x.q));
  const Eigen::MatrixXd &poses = frames.first, &jacobians = frames.second;
  const Eigen::MatrixXd accelerations = arm_bias_accelerations(l1, Eigen::Vector2d(x.q), Eigen::Vector2d(x.qdot));
  const arm_mass_terms mass = arm_mass(2, 1.5, l1, 0.5, 0.375, 0.25, 0.0625, Eigen::Vector2d(x.q));
  using dq = audit::dynamics_quantity;
  const auto closed = [&](audit::dynamics_quantity q) -> const Eigen::MatrixXd& {
    return q == dq::frame_poses ? poses
           : q == dq::frame_jacobians ? jacobians
           : q == dq::frame_bias_accelerations ? accelerations
           : q == dq::link_com_jacobians ? mass.link_com_jacobians
           : q == dq::centre_of_mass ? mass.com
           : q == dq::com_jacobian   ? mass.com_jacobian
                                     : mass.momentum_matrix;
  };
  // The reference within 2 eps of the scale max(1, l1 + c2) of the closed form (which rounds
  // its sines and cosines once, and l1 times them once; Jdot qdot's scale also carries w^2,
  // w = 1.5 the forearm's rate; A_G's is max(sum m r^2 + |I|, sum m lever), r the links' paths
  // to their centres of mass, 0.5 and 1.625, and its closed form sums four rounded products a
  // column: 4 eps); every library that offers them within its budget, 16 n eps of the scale,
  // of it.
  const double lever = l1 + 0.375, momentum_scale = std::max(2 * 0.5 * 0.5 + 0.5 + 1.5 * lever * lever + 0.125, 3.5 * lever);
  const auto kinematic = {dq::frame_poses,    dq::frame_jacobians, dq::frame_bias_accelerations, dq::link_com_jacobians,
                          dq::centre_of_mass, dq::com_jacobian,    dq::centroidal_momentum_matrix};
  for (const auto q : kinematic) {
    const audit::dynamics_residual ref = audit::reference_only(q, r, x);
    EXPECT_EQ(ref.scale, q == dq::frame_bias_accelerations      ? lever * 1.5 * 1.5
                         : q == dq::centroidal_momentum_matrix ? momentum_scale
                                                               : lever)
        << audit::dynamics_quantity_name(q);
    EXPECT_LE((ref.reference - closed(q)).cwiseAbs().maxCoeff(),
              (q == dq::centroidal_momentum_matrix ? 4 : 2) * 0x1p-52 * ref.scale)
        << audit::dynamics_quantity_name(q) << "\n" << ref.reference << "\n" << closed(q);
  }
  int offered = 0;
  for (const audit::dynamics_library& library : audit::dynamics_found())
    for (const auto& res : audit::check_dynamics(library, r, x).residuals) {
      if (std::find(kinematic.begin(), kinematic.end(), res.quantity) == kinematic.end()) continue;
      ++offered;
      const Eigen::MatrixXd& want = closed(res.quantity);
      EXPECT_TRUE(res.within()) << library.name << ": " << audit::dynamics_quantity_name(res.quantity) << ": "
                                << res.residual << " eps, budget " << res.budget;
      EXPECT_LE((res.library - want).cwiseAbs().maxCoeff(), res.budget * 0x1p-52 * res.scale)
          << library.name << ": " << audit::dynamics_quantity_name(res.quantity) << "\n" << res.library;
    }
#ifdef MECHCHECK_HAVE_MUJOCO
  EXPECT_GE(offered, 6) << "MuJoCo gives all but Jdot qdot";
#else
  (void)offered;
#endif
}

TEST(dynamics_audit, a_free_rigid_body_gives_newton_and_euler_in_every_library_with_a_floating_base) {
  // The free body at a turned pose with a twist and its rate; Q from the closed form. Each
  // library with a floating base gives the closed form's M and Q, and udot back from Q, within
  // the budget; the others refuse it by their reason (KDL: no floating base).
  const rb::robot r = free_body();
  rb::pose at;
  at.xyz = {0.75, -0.5, 1.25};
  at.rpy = {0.5, -1.25, 2};
  Eigen::VectorXd u(6), udot(6);
  u << 0.5, -1, 1.5, 2, -0.75, 1.25;
  udot << -1, 0.25, 3, 0.5, -2, 1;
  const Eigen::Matrix3d rotation = rb::rpy_rotation<double>(at.rpy);
  const free_body_closed_form<double> given = free_body_terms<double>(r, rotation, u, udot);
  const audit::dynamics_state x = floating_state(at, Eigen::VectorXd(0), u, udot, given.q);
  constexpr double eps = 0x1p-52;
  int floating = 0;
  for (const audit::dynamics_library& library : audit::dynamics_found()) {
    const audit::dynamics_check c = audit::check_dynamics(library, r, x);
    if (!library.no_floating_base.empty()) {
      EXPECT_NE(c.refused.find(library.no_floating_base), std::string::npos) << library.name << ": " << c.refused;
      EXPECT_TRUE(c.residuals.empty()) << library.name;
      continue;
    }
    ++floating;
    ASSERT_TRUE(c.refused.empty()) << library.name << ": " << c.refused;
    ASSERT_GE(c.residuals.size(), 4u) << library.name;
    // The closed form of the body the library holds (MuJoCo's compiler turns the inertia into
    // principal moments and a frame, to about 1e-10), Q the given body's.
    const rb::robot held = library.load(r)->held_robot().value_or(r);
    const free_body_closed_form<double> want = free_body_terms<double>(held, rotation, u, udot);
    // udot = M^-1 (Q - h) of the held body, h = its M udot + h less M udot.
    const Eigen::VectorXd rate = want.m.llt().solve(Eigen::VectorXd(given.q - (want.q - want.m * udot)));
    for (const auto& res : c.residuals) {
      const char* what = audit::dynamics_quantity_name(res.quantity);
      EXPECT_TRUE(res.within()) << library.name << ": " << what << ": " << res.residual << " eps, budget " << res.budget;
      // The body's frame: (p; R's columns); its Jacobian diag(R, R): v_o = R v_b, omega = R w_b.
      Eigen::MatrixXd pose(12, 1), jacobian = Eigen::MatrixXd::Zero(6, 6);
      pose << at.xyz, rotation.col(0), rotation.col(1), rotation.col(2);
      jacobian.topLeftCorner<3, 3>() = jacobian.bottomRightCorner<3, 3>() = rotation;
      // Jdot qdot at udot = 0: the origin's d/dt (R v_b) = R (w_b x v_b), no angular one.
      Eigen::MatrixXd bias_acceleration = Eigen::MatrixXd::Zero(6, 1);
      bias_acceleration.topRows<3>() = rotation * Eigen::Vector3d(u.segment<3>(3)).cross(Eigen::Vector3d(u.head<3>()));
      // The centre of mass p + R c; cdot = R (v_b + w_b x c): J_c = [R, -R [c]x]; A_G = [m J_c;
      // 0, R I_c] (the spin about the centre of mass, I_c = R_o I R_o^T in the body's axes, of
      // the body the library holds).
      const rb::inertial& body = *held.links.front().body;
      const Eigen::Vector3d c = body.origin.xyz;
      Eigen::Matrix3d lever;
      lever << 0, -c(2), c(1), c(2), 0, -c(0), -c(1), c(0), 0;
      const Eigen::Matrix3d ro = rb::rpy_rotation<double>(body.origin.rpy);
      const Eigen::MatrixXd com = at.xyz + rotation * c;
      Eigen::MatrixXd com_jacobian(3, 6), momentum_matrix = Eigen::MatrixXd::Zero(6, 6);
      com_jacobian << rotation, -rotation * lever;
      // Its Jacobian at the centre of mass: (J_c; 0, R).
      Eigen::MatrixXd at_com = Eigen::MatrixXd::Zero(6, 6);
      at_com.topRows<3>() = com_jacobian;
      at_com.bottomRightCorner<3, 3>() = rotation;
      momentum_matrix.topRows<3>() = body.mass * com_jacobian;
      momentum_matrix.bottomRightCorner<3, 3>() = rotation * ro * body.inertia * ro.transpose();
      const Eigen::MatrixXd closed = res.quantity == audit::dynamics_quantity::mass_matrix ? want.m
                                     : res.quantity == audit::dynamics_quantity::inverse ? Eigen::MatrixXd(want.q)
                                     : res.quantity == audit::dynamics_quantity::forward ? Eigen::MatrixXd(rate)
                                     : res.quantity == audit::dynamics_quantity::frame_poses ? pose
                                     : res.quantity == audit::dynamics_quantity::frame_jacobians ? jacobian
                                     : res.quantity == audit::dynamics_quantity::frame_bias_accelerations
                                         ? bias_acceleration
                                     : res.quantity == audit::dynamics_quantity::link_com_jacobians ? at_com
                                     : res.quantity == audit::dynamics_quantity::centre_of_mass ? com
                                     : res.quantity == audit::dynamics_quantity::com_jacobian   ? com_jacobian
                                     : res.quantity == audit::dynamics_quantity::centroidal_momentum_matrix
                                         ? momentum_matrix
                                         : res.reference;
      EXPECT_LE((res.library - closed).cwiseAbs().maxCoeff(), res.budget * eps * res.scale) << library.name << ": " << what;
    }
  }
#ifdef MECHCHECK_HAVE_MUJOCO
  EXPECT_GE(floating, 1) << "MuJoCo has a floating base";
#endif
}

TEST(dynamics_audit, the_two_link_arm_on_a_floating_base_agrees_and_held_still_gives_the_bolted_arms_forces) {
  // On a moving base every quantity within its budget; on a base held still, with gravity
  // turned with it, the joints' forces of inverse dynamics are the bolted arm's closed form.
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, g = 9.81;
  rb::robot r = robots_test::floating_two_link_arm();  // the arm of these numbers, on a torso
  rb::pose at;
  at.xyz = {0.25, 0.5, 1};
  at.rpy = {0.5, -0.25, 1.5};
  r.gravity = rb::rpy_rotation<double>(at.rpy) * Eigen::Vector3d(0, 0, -g);
  const Eigen::Vector2d q(0.3, -0.7), qdot(1.1, 0.4), qddot(-0.5, 2.0);
  Eigen::VectorXd u(8), udot(8), force(8);
  u << 0.5, -1, 1.5, 2, -0.75, 1.25, qdot;
  udot << -1, 0.25, 3, 0.5, -2, 1, qddot;
  force << 1, -2, 3, 0.5, 0.25, -1, 3, -1;
  const audit::dynamics_state moving = floating_state(at, q, u, udot, force);
  Eigen::VectorXd still = Eigen::VectorXd::Zero(8), still_rate = Eigen::VectorXd::Zero(8);
  still.tail(2) = qdot;
  still_rate.tail(2) = qddot;
  const audit::dynamics_state held = floating_state(at, q, still, still_rate, force);
  const robots_test::arm_closed_form want = robots_test::arm_terms(m1, m2, l1, c1, c2, i1, i2, g, q, qdot);
  constexpr double eps = 0x1p-52;
  int floating = 0;
  for (const audit::dynamics_library& library : audit::dynamics_found()) {
    if (!library.no_floating_base.empty()) continue;
    ++floating;
    const audit::dynamics_check c = audit::check_dynamics(library, r, moving);
    ASSERT_TRUE(c.refused.empty()) << library.name << ": " << c.refused;
    for (const auto& res : c.residuals)
      EXPECT_TRUE(res.within()) << library.name << ": " << audit::dynamics_quantity_name(res.quantity) << ": "
                                << res.residual << " eps, budget " << res.budget;
    for (const auto& res : audit::check_dynamics(library, r, held).residuals)
      if (res.quantity == audit::dynamics_quantity::inverse)
        EXPECT_LE((res.library.col(0).tail(2) - (want.m * qddot + want.h)).cwiseAbs().maxCoeff(),
                  res.budget * eps * res.scale)
            << library.name;
  }
#ifdef MECHCHECK_HAVE_MUJOCO
  EXPECT_GE(floating, 1) << "MuJoCo has a floating base";
#else
  (void)floating;
#endif
}

TEST(dynamics_audit, every_library_holds_to_the_lagrangian_on_random_robots) {
  // Every quantity within 16 n eps of its scale; a failure prints the minimal robot as URDF.
  // 40 robots a library, fixed and floating (ci/test runs the command on 100 more); a robot
  // the library refuses by its own rule (MuJoCo's A + B >= C on the moments it computed) is
  // not counted, nor a floating one where it has no floating base, and at least half of the
  // rest must be run.
  for (const audit::dynamics_library& library : audit::dynamics_found()) {
    int run = 0, offered = 0;
    EXPECT_EQ(seeded_check(40, [&library, &run, &offered] {
                const generators::robot_case c = *audit::dynamics_robot_cases(8);
                if (c.robot.floating && !library.no_floating_base.empty()) return;
                ++offered;
                const audit::dynamics_check check = audit::check_dynamics(library, c.robot, state_of(c));
                if (!check.refused.empty()) return;
                ++run;
                for (const auto& r : check.residuals)
                  if (!r.within())
                    RC_FAIL(library.name + ": " + audit::dynamics_quantity_name(r.quantity) + ": residual " +
                            std::to_string(r.residual) + " eps of its scale " + std::to_string(r.scale) + ", budget " +
                            std::to_string(r.budget) + "\nthe robot:\n" + audit::to_urdf(c.robot));
              }),
              "")
        << library.name;
    EXPECT_GE(2 * run, offered) << library.name << " refused " << offered - run << " of " << offered << " robots";
    EXPECT_GE(offered, 10) << library.name;
  }
}

TEST(dynamics_audit, the_reference_jdot_qdot_is_the_derivative_of_the_twist_by_automatic_differentiation) {
  // The reference's Jdot qdot (link_accelerations at qddot = 0, in mpfr50) against
  // robots::point_bias_acceleration (forward-mode AD of each link's twist along qdot, in
  // double) on random fixed robots: two computations that share only link_states, within
  // the budget 16 n eps of the reference's scale.
  EXPECT_EQ(seeded_check(40, [] {
              const generators::robot_case c = *generators::robot_cases(6);
              const audit::dynamics_state x = state_of(c);
              const audit::dynamics_residual ref =
                  audit::reference_only(audit::dynamics_quantity::frame_bias_accelerations, c.robot, x);
              const rb::robot_model<double> m(c.robot);
              const int n = m.dofs();
              for (std::size_t l = 0; l < c.robot.links.size(); ++l) {
                const Eigen::VectorXd ad =
                    rb::point_bias_acceleration(m, Eigen::VectorXd(x.q), Eigen::VectorXd(x.qdot), static_cast<int>(l));
                const double off = (ad - ref.reference.block<6, 1>(6 * static_cast<Eigen::Index>(l), 0)).cwiseAbs().maxCoeff();
                RC_ASSERT(off <= 16 * n * 0x1p-52 * ref.scale);
              }
            }),
            "");
}

/// A chain of revolute joints about skew axes, links of masses `masses` (each 0.4 below its
/// hinge, the next hinge 0.5 below): the robots of the budget and scale tests.
rb::robot chain(const std::vector<double>& masses) {
  rb::robot r;
  r.name = "chain";
  r.links.push_back({"base", std::nullopt});
  for (std::size_t k = 0; k < masses.size(); ++k) {
    rb::inertial b;
    b.mass = masses[k];
    b.origin.xyz = {0.05, 0, -0.4};
    b.inertia = Eigen::Vector3d(0.02, 0.03, 0.01).asDiagonal();
    b.inertia *= masses[k];
    r.links.push_back({"l" + std::to_string(k), b});
    rb::joint j;
    j.name = "j" + std::to_string(k);
    j.parent = k == 0 ? "base" : "l" + std::to_string(k - 1);
    j.child = "l" + std::to_string(k);
    if (k > 0) j.origin.xyz = {0, 0, -0.5};
    j.axis = k % 2 ? Eigen::Vector3d(0, 0.6, 0.8) : Eigen::Vector3d(0.8, 0.6, 0);
    r.joints.push_back(j);
  }
  return r;
}

audit::dynamics_state chain_state(int n, double sign = 1) {
  audit::dynamics_state x;
  x.q = x.qdot = x.qddot = x.tau = Eigen::VectorXd(n);
  for (int i = 0; i < n; ++i) {
    x.q(i) = 0.3 - 0.2 * i;
    x.qdot(i) = 0.7 + 0.1 * i;
    x.qddot(i) = sign * (1.5 - 0.5 * i);
    x.tau(i) = sign * (2.0 - 0.75 * i);
  }
  return x;
}

/// A library that returns the reference of `quantity`, rounded once, with `eps_off` eps of
/// its scale added to the first entry: an error of a known size.
audit::dynamics_library off_by(audit::dynamics_quantity quantity, const audit::dynamics_state& x, double eps_off) {
  struct model final : audit::dynamics_model {
    audit::dynamics_quantity quantity;
    Eigen::MatrixXd value;
    std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd&) override {
      return quantity == audit::dynamics_quantity::mass_matrix ? std::optional<Eigen::MatrixXd>(value) : std::nullopt;
    }
    std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd&, const Eigen::VectorXd&) override {
      return quantity == audit::dynamics_quantity::bias ? std::optional<Eigen::VectorXd>(value.col(0)) : std::nullopt;
    }
    std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&) override {
      return quantity == audit::dynamics_quantity::inverse ? std::optional<Eigen::VectorXd>(value.col(0)) : std::nullopt;
    }
    std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&) override {
      return quantity == audit::dynamics_quantity::forward ? std::optional<Eigen::VectorXd>(value.col(0)) : std::nullopt;
    }
  };
  audit::dynamics_library l;
  l.name = "off_by";
  l.load = [quantity, x, eps_off](const rb::robot& r) -> std::unique_ptr<audit::dynamics_model> {
    const audit::dynamics_residual ref = audit::reference_only(quantity, r, x);
    auto m = std::make_unique<model>();
    m->quantity = quantity;
    m->value = ref.reference;
    m->value(0, 0) += eps_off * 0x1p-52 * ref.scale;
    return m;
  };
  return l;
}

TEST(dynamics_audit, the_budget_is_16_n_eps_of_the_scale_and_an_error_a_few_times_it_disagrees) {
  // A 4-link chain: budget 16 n = 64 eps of each quantity's scale. An error of 48 eps is
  // within it, 100 eps (between the budget and a few times it) is not, for every quantity.
  const rb::robot r = chain({1.0, 0.8, 0.6, 0.5});
  const audit::dynamics_state x = chain_state(4);
  for (const auto q : {audit::dynamics_quantity::mass_matrix, audit::dynamics_quantity::bias,
                       audit::dynamics_quantity::inverse, audit::dynamics_quantity::forward}) {
    SCOPED_TRACE(audit::dynamics_quantity_name(q));
    const audit::dynamics_check inside = audit::check_dynamics(off_by(q, x, 48), r, x);
    ASSERT_EQ(inside.residuals.size(), 1u);
    EXPECT_EQ(inside.residuals[0].budget, 64);
    EXPECT_NEAR(inside.residuals[0].residual, 48, 1);
    EXPECT_TRUE(inside.residuals[0].within());
    const audit::dynamics_check outside = audit::check_dynamics(off_by(q, x, 100), r, x);
    EXPECT_NEAR(outside.residuals[0].residual, 100, 1);
    EXPECT_FALSE(outside.residuals[0].within());
  }
}

TEST(dynamics_audit, the_forward_scale_carries_cond_m_on_an_ill_conditioned_robot) {
  // Masses 1 and 2^-6 down a 2-link chain: cond(M) near 10^3. The forward dynamics' scale is
  // |M^-1| (max(|M|, I) |qddot| + max(scale of h, |tau|)) (docs/audit.md), all norms the
  // largest row sum or component, computed here apart from the audit in mpfr50; here |M|
  // and the terms' I are within 3 % of each other, so that the first term is cond(M) |qddot|
  // to that.
  const rb::robot r = chain({1.0, 0x1p-6});
  audit::dynamics_state x = chain_state(2);
  const rb::robot_model<mpfr50> m(r);
  dynamic_vector<mpfr50> q(2), v(2);
  for (int i = 0; i < 2; ++i) q(i) = x.q(i), v(i) = x.qdot(i);
  const auto terms = rb::motion_terms_at(m, q, v);
  const dynamic_matrix<mpfr50> inv = terms.mass_matrix.inverse();
  const auto row_sum = [](const dynamic_matrix<mpfr50>& a) {
    mpfr50 best = 0;
    for (Eigen::Index i = 0; i < a.rows(); ++i) best = std::max(best, mpfr50(a.row(i).cwiseAbs().sum()));
    return static_cast<double>(best);
  };
  const double cond = row_sum(terms.mass_matrix) * row_sum(inv);
  const double m_terms = std::max(row_sum(terms.mass_matrix), rb::term_scales(rb::robot_model<double>(r), x.q).inertia);
  EXPECT_LT(m_terms, 1.03 * row_sum(terms.mass_matrix));
  EXPECT_GT(cond, 100);
  EXPECT_LT(cond, 3000);
  dynamic_vector<mpfr50> tau(2);
  for (int i = 0; i < 2; ++i) tau(i) = x.tau(i);
  const dynamic_vector<mpfr50> qddot = inv * (tau - terms.bias);
  const double qddot_max = static_cast<double>(mpfr50(qddot.cwiseAbs().maxCoeff()));
  const double scale_h = audit::reference_only(audit::dynamics_quantity::bias, r, x).scale;
  const double second = row_sum(inv) * std::max(scale_h, x.tau.cwiseAbs().maxCoeff());
  // The cond(M) term is the larger here: a scale without it is off by more than a factor 2.
  EXPECT_GT(cond * qddot_max, second);
  const double scale = audit::reference_only(audit::dynamics_quantity::forward, r, x).scale;
  EXPECT_NEAR(scale, m_terms * row_sum(inv) * qddot_max + second, 1e-9 * scale);
}

TEST(dynamics_audit, the_forward_scale_takes_ms_error_from_its_terms_where_a_moment_about_the_axis_cancels) {
  // One link spinning about x, its centre of mass on the axis (no gravity torque), an inertia
  // of entries near 1 turned so that its moment about the axis is 0.06: M's rounding is
  // relative to the entries, and the scale is |M^-1| (I |qddot| + |tau|), not cond(M) |qddot| +
  // |M^-1| |tau| = 2 |qddot| (Simbody's 16.8 eps near miss under that scale, seed 1).
  const rb::robot r = audit::parse_urdf(R"(<robot name="thin"><link name="base"/>
    <link name="link1"><inertial><origin xyz="0 0 0" rpy="0.21875 -1.1953125 -0.0390625"/>
      <mass value="0.02166748046875"/><inertia ixx="0.67907161617369383" ixy="0.03524841800135195"
      ixz="0.46371339261761135" iyy="0.99612853520045674" iyz="-0.05091752572334407" izz="0.32519657714147415"/>
    </inertial></link>
    <joint name="joint1" type="continuous"><parent link="base"/><child link="link1"/>
      <origin xyz="0 0 0" rpy="0 0.16015625 1.23828125"/><axis xyz="1 0 0"/></joint></robot>)");
  audit::dynamics_state x;
  x.q = Eigen::VectorXd::Constant(1, -1.2421875);
  x.qdot = x.qddot = Eigen::VectorXd::Zero(1);
  x.tau = Eigen::VectorXd::Constant(1, 0.00390625);
  const audit::dynamics_residual m = audit::reference_only(audit::dynamics_quantity::mass_matrix, r, x);
  const double moment = m.reference(0, 0), inertia = rb::term_scales(rb::robot_model<double>(r), x.q).inertia;
  EXPECT_LT(moment, inertia / 10);
  const double qddot = x.tau(0) / moment;
  EXPECT_NEAR(audit::reference_only(audit::dynamics_quantity::forward, r, x).scale,
              (inertia * std::abs(qddot) + x.tau(0)) / moment, 1e-12 * inertia / moment);
}

TEST(dynamics_audit, a_robot_beyond_the_size_limit_is_refused_by_a_typed_error_before_any_library_runs) {
  // A chain of dynamics_max_joints links is taken; one more link is robot_too_large, named,
  // from the campaign's entry as from require_dynamics_size (the command's check after
  // reading a file).
  const std::vector<double> masses(std::size_t(audit::dynamics_max_joints), 1.0);
  rb::robot r = chain(masses);
  EXPECT_NO_THROW(audit::require_dynamics_size(r));
  rb::robot longer = chain(std::vector<double>(std::size_t(audit::dynamics_max_joints) + 1, 1.0));
  try {
    audit::require_dynamics_size(longer);
    ADD_FAILURE() << "513 moving joints taken";
  } catch (const audit::robot_too_large& e) {
    EXPECT_NE(std::string(e.what()).find("robot chain has 513 moving joints, more than the 512"), std::string::npos)
        << e.what();
  }
  int loaded = 0;
  audit::dynamics_library counting = wrong_library([&loaded](rb::robot&) { ++loaded; });
  audit::dynamics_options o;
  o.robots = 1;
  EXPECT_THROW(audit::run_dynamics_on(counting, longer, o), audit::robot_too_large);
  EXPECT_EQ(loaded, 0);
}

TEST(dynamics_audit, a_second_check_at_the_same_q_and_qdot_uses_its_own_qddot_and_tau) {
  // The reference is remembered across calls; two checks of one robot at the same q and qdot
  // with other qddot and tau must each be held to their own inverse and forward dynamics.
  const rb::robot r = chain({1.0, 0.8, 0.6});
  const audit::dynamics_state first = chain_state(3, 1), second = chain_state(3, -1);
  const audit::dynamics_library exact = wrong_library([](rb::robot&) {});
  const audit::dynamics_check a = audit::check_dynamics(exact, r, first);
  const audit::dynamics_check b = audit::check_dynamics(exact, r, second);
  ASSERT_EQ(a.residuals.size(), 4u);
  ASSERT_EQ(b.residuals.size(), 4u);
  for (const auto* c : {&a, &b})
    for (const auto& res : c->residuals)
      EXPECT_TRUE(res.within()) << audit::dynamics_quantity_name(res.quantity) << ": " << res.residual << " eps";
  // Inverse and forward dynamics differ between the two states; the mass matrix does not.
  EXPECT_GT((a.residuals[2].reference - b.residuals[2].reference).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_GT((a.residuals[3].reference - b.residuals[3].reference).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_EQ(a.residuals[0].reference, b.residuals[0].reference);
}

TEST(dynamics_audit, a_users_robot_with_fixed_joints_gets_one_coordinate_per_moving_joint) {
  // A user's URDF with two fixed joints among three moving ones, through the campaign's state
  // generator (run_dynamics_on, the command's --urdf): three coordinates a state, every
  // quantity within on every state.
  rb::robot r = chain({1.0, 0.5, 0.7, 0.4, 0.6});
  r.joints[1].type = rb::joint_type::fixed;
  r.joints[3].type = rb::joint_type::fixed;
  ASSERT_EQ(rb::validate(r).dofs, 3);
  audit::dynamics_options opt;
  opt.robots = 5;
  const audit::dynamics_campaign c = audit::run_dynamics_on(wrong_library([](rb::robot&) {}), r, opt);
  EXPECT_TRUE(c.agrees()) << c.note << c.disagreement;
  EXPECT_EQ(c.robots, 5);
  for (const auto& f : c.figures) {
    const bool kinematic = audit::kinematic_quantity(f.quantity);
    EXPECT_EQ(f.checked, kinematic ? 0 : 5) << audit::dynamics_quantity_name(f.quantity);
    EXPECT_EQ(audit::dynamics_verdict(c, f), kinematic ? "not offered" : "within");  // the test library offers none
  }
}

TEST(dynamics_audit, a_disagreement_on_a_users_robot_prints_a_command_that_runs_with_its_file) {
  // The command's --urdf campaign: the reproduction names the file as given (quoted for the
  // shell), not a placeholder, and the seed the campaign ran with, once.
  const rb::robot r = chain({1.0, 0.5});
  audit::dynamics_options opt;
  opt.robots = 3;
  opt.seed = 7;
  opt.urdf_file = "my arm.urdf";
  const audit::dynamics_campaign c =
      audit::run_dynamics_on(wrong_library([](rb::robot& x) { x.links.back().body->mass *= 2; }), r, opt);
  ASSERT_FALSE(c.disagreement.empty());
  EXPECT_NE(c.disagreement.find("(mechcheck-audit -o dynamics-case --urdf 'my arm.urdf' --robots 3 --seed 7 --dynamics wrong finds"),
            std::string::npos) << c.disagreement;
}

TEST(dynamics_audit, a_campaign_that_stopped_never_clears_the_quantities_it_did_not_finish) {
  // A library whose mass matrix is wrong: the campaign stops at its first disagreement. The
  // other quantities were checked on the robots reached before it, not on the 40 asked for:
  // they read "not cleared", with the count, never "within".
  audit::dynamics_options opt;
  opt.robots = 40;
  const audit::dynamics_campaign c = audit::run_dynamics_campaign(
      wrong_library([](rb::robot& r) {
        for (auto& l : r.links)
          if (l.body) l.body->inertia *= 1.001;
      }),
      opt);
  ASSERT_FALSE(c.agrees());
  EXPECT_TRUE(c.stopped());
  EXPECT_EQ(c.asked, 40);
  bool disagreed = false;
  for (const auto& f : c.figures) {
    const std::string v = audit::dynamics_verdict(c, f);
    EXPECT_NE(v, "within") << audit::dynamics_quantity_name(f.quantity);
    if (v == "DISAGREES") {
      disagreed = true;
      continue;
    }
    EXPECT_EQ(v.rfind("not ", 0), 0u) << v;
    if (f.checked > 0)
      EXPECT_NE(v.find(std::to_string(f.checked) + " of 40 robots"), std::string::npos) << v;
  }
  EXPECT_TRUE(disagreed);
}

}  // namespace dynamics_audit_test
