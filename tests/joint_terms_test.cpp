// A joint's own terms in the dynamics audit: the rotors' armature and the joints' viscous
// damping in the arm's closed form, in every library whose adapter sets them and refused by
// the others with the reason; DART's implicit damping at its own time step; the campaigns'
// random robots carrying the terms each library sets.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Cholesky>

#include "dynamics_fakes.hpp"
#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/robots.hpp"
#include "two_link_arm.hpp"

namespace joint_terms_test {
using namespace mechcheck;
namespace rb = mechcheck::robots;
namespace audit = mechcheck::audit;
using dynamics_fakes::disagrees;
using dynamics_fakes::wrong_library;
using robots_test::arm_closed_form;
using robots_test::arm_terms;
using robots_test::two_link_arm;

TEST(dynamics_audit, armature_and_damping_join_the_closed_form_where_a_library_sets_them_and_are_refused_where_not) {
  // A rotor's armature a adds a qdot^2 / 2 to T, so a to M's diagonal; viscous damping b adds
  // b qdot to h (the generalized force -b qdot). The arm's closed form with both, in the
  // reference and in every library whose adapter sets them (MuJoCo both; its URDF import, DART
  // and Simbody the damping: they have no rotor inertia; KDL the armature: its solvers read no
  // damping), on the arm with both, with the armature alone and with the damping alone; the
  // others refuse it naming the joint, the term and why.
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, g = 9.81;
  const Eigen::Vector2d armature(0.125, 0.03125), damping(0.5, 0.25);
  rb::robot r = two_link_arm(m1, m2, l1, c1, c2, i1, i2);
  for (int k = 0; k < 2; ++k) {
    r.joints[std::size_t(k)].armature = armature(k);
    r.joints[std::size_t(k)].damping = damping(k);
  }
  audit::dynamics_state x;
  x.q = Eigen::Vector2d(0.3, -0.7);
  x.qdot = Eigen::Vector2d(1.1, 0.4);
  x.qddot = Eigen::Vector2d(-0.5, 2.0);
  x.tau = Eigen::Vector2d(3.0, -1.0);
  arm_closed_form want = arm_terms(m1, m2, l1, c1, c2, i1, i2, g, Eigen::Vector2d(x.q), Eigen::Vector2d(x.qdot));
  want.m.diagonal() += armature;
  want.h += damping.cwiseProduct(Eigen::Vector2d(x.qdot));
  constexpr double eps = 0x1p-52;
  const rb::robot_model<double> md(r);
  const rb::motion_terms<double> d = rb::motion_terms_at(md, x.q, x.qdot);
  EXPECT_LE((d.mass_matrix - want.m).cwiseAbs().maxCoeff(), 32 * eps * want.m.cwiseAbs().maxCoeff());
  EXPECT_LE((d.bias - want.h).cwiseAbs().maxCoeff(), 32 * eps * (m1 + m2) * g * 2);
  // The same in URDF: <dynamics damping friction armature> read back to the same doubles.
  rb::robot with_friction = r;
  with_friction.joints[0].friction = 0.75;
  const rb::robot back = audit::parse_urdf(audit::to_urdf(with_friction), "arm.urdf");
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(back.joints[k].armature, r.joints[k].armature);
    EXPECT_EQ(back.joints[k].damping, r.joints[k].damping);
  }
  EXPECT_EQ(back.joints[0].friction, 0.75);
  ASSERT_EQ(back.readings.size(), 1u);
  EXPECT_NE(back.readings[0].find("friction 0.75"), std::string::npos) << back.readings[0];
  rb::robot armature_only = r, damping_only = r;
  for (rb::joint& j : armature_only.joints) j.damping = 0;
  for (rb::joint& j : damping_only.joints) j.armature = 0;
  int held = 0;
  for (const audit::dynamics_library& library : audit::dynamics_found()) {
    for (const rb::robot* robot : {&r, &armature_only, &damping_only}) {
      const bool sets = (robot == &damping_only || library.sets_armature) &&
                        (robot == &armature_only || library.sets_damping);
      const audit::dynamics_check c = audit::check_dynamics(library, *robot, x);
      if (!sets) {
        EXPECT_TRUE(c.residuals.empty()) << library.name;
        EXPECT_NE(c.refused.find("joint shoulder has "), std::string::npos) << library.name << ": " << c.refused;
        EXPECT_NE(c.refused.find(library.name), std::string::npos) << c.refused;
        if (library.selector.empty())  // a library of ours says why; a child cannot
          EXPECT_NE(c.refused.find(library.no_joint_terms), std::string::npos) << c.refused;
        EXPECT_FALSE(library.no_joint_terms.empty() && library.selector.empty()) << library.name;
        continue;
      }
      ASSERT_TRUE(c.refused.empty()) << library.name << ": " << c.refused;
      ASSERT_FALSE(c.residuals.empty()) << library.name;
      ++held;
      // A library that says which robot it holds (MuJoCo, read back from its compiled model) is
      // judged on that robot: its joint terms must be the given ones, or a term its model
      // builder dropped would pass unseen.
      if (const auto kept = library.load(*robot)->held_robot())
        for (const rb::joint& j : robot->joints)
          for (const rb::joint& k : kept->joints)
            if (k.name == j.name) {
              EXPECT_EQ(k.armature, j.armature) << library.name << ": joint " << j.name;
              EXPECT_EQ(k.damping, j.damping) << library.name << ": joint " << j.name;
            }
      for (const auto& res : c.residuals)
        EXPECT_TRUE(res.within()) << library.name << ": " << audit::dynamics_quantity_name(res.quantity) << ": "
                                  << res.residual << " eps of budget " << res.budget;
    }
  }
  int expect_held = 0;
#ifdef MECHCHECK_HAVE_MUJOCO
  expect_held += 3 + 1;  // MuJoCo sets both terms, its URDF import the damping
#endif
#ifdef MECHCHECK_HAVE_DART
  expect_held += 1;
#endif
#ifdef MECHCHECK_HAVE_SIMBODY
  expect_held += 1;
#endif
  EXPECT_GE(held, expect_held);
  // Wrong variants: the armature added twice, the damping dropped.
  const auto fails = [&](const char* what, std::function<void(rb::robot&)> change) {
    EXPECT_TRUE(disagrees(audit::check_dynamics(wrong_library(change), r, x))) << what;
  };
  fails("the armature added twice", [](rb::robot& w) {
    for (rb::joint& j : w.joints) j.armature *= 2;
  });
  fails("the damping dropped", [](rb::robot& w) {
    for (rb::joint& j : w.joints) j.damping = 0;
  });
  const audit::dynamics_check right = audit::check_dynamics(wrong_library([](rb::robot&) {}), r, x);
  ASSERT_EQ(right.residuals.size(), 4u);
  for (const auto& res : right.residuals) EXPECT_TRUE(res.within()) << res.residual;
}

#ifdef MECHCHECK_HAVE_DART
TEST(dynamics_audit, dart_applies_the_damping_implicitly_with_its_time_step_as_it_documents) {
  // DART's joint damping is -d (qdot + h qddot), h the Skeleton's time step (Joint.hpp,
  // GenericJoint::updateForceID): its inverse dynamics is the arm's closed form plus h d qddot,
  // its forward dynamics solves (M + h D) qddot = tau - h_bias. At DART's own default h =
  // 0.001 s that term (here up to 1e-3 * 0.25 * 2 = 5e-4) is 3e10 eps of the force's scale
  // (m1 + m2) g 2, and the adapter's default h = 2^-80 s puts it under rounding (the test
  // above holds it there).
  const double m1 = 2, m2 = 1.5, l1 = 1, c1 = 0.5, c2 = 0.375, i1 = 0.25, i2 = 0.0625, g = 9.81, h = 1e-3;
  const Eigen::Vector2d damping(0.5, 0.25);
  rb::robot r = two_link_arm(m1, m2, l1, c1, c2, i1, i2);
  for (int k = 0; k < 2; ++k) r.joints[std::size_t(k)].damping = damping(k);
  const Eigen::Vector2d q(0.3, -0.7), qdot(1.1, 0.4), qddot(-0.5, 2.0), tau(3.0, -1.0);
  arm_closed_form want = arm_terms(m1, m2, l1, c1, c2, i1, i2, g, q, qdot);
  want.h += damping.cwiseProduct(qdot);
  const Eigen::Matrix2d implicit = want.m + Eigen::Matrix2d(h * damping.asDiagonal());
  constexpr double eps = 0x1p-52;
  const double scale = (m1 + m2) * g * 2;
  const auto model = audit::dart_engine::dynamics(h).load(r);
  const Eigen::VectorXd inverse = *model->inverse(q, qdot, qddot);
  EXPECT_LE((inverse - (implicit * qddot + want.h)).cwiseAbs().maxCoeff(), 32 * eps * scale);
  EXPECT_GT((inverse - (want.m * qddot + want.h)).cwiseAbs().maxCoeff(), 1e9 * eps * scale);
  const Eigen::VectorXd forward = *model->forward(q, qdot, tau);
  const Eigen::Vector2d expected = implicit.llt().solve(tau - want.h);
  EXPECT_LE((forward - expected).cwiseAbs().maxCoeff(), 64 * eps * expected.cwiseAbs().maxCoeff());
  // M and the bias carry no time step.
  EXPECT_LE((*model->mass_matrix(q) - want.m).cwiseAbs().maxCoeff(), 32 * eps * want.m.cwiseAbs().maxCoeff());
  EXPECT_LE((*model->bias(q, qdot) - want.h).cwiseAbs().maxCoeff(), 32 * eps * scale);
  EXPECT_THROW(audit::dart_engine::dynamics(0), domain_error);
  EXPECT_THROW(audit::dart_engine::dynamics(std::nan("")), domain_error);
}
#endif

TEST(dynamics_audit, a_campaigns_robots_carry_the_joint_terms_its_library_sets_and_are_the_same_robots_otherwise) {
  // Each library's random robots draw the terms its adapter sets (options.armature, damping:
  // run_dynamics_campaign takes them from the library's flags), after the rest: the robots and
  // states with them are the ones without them, joint for joint.
  const auto robots_of = [](bool armature, bool damping) {
    std::vector<rb::robot> seen;
    audit::dynamics_options opt;
    opt.robots = 60;
    opt.seed = 5;
    opt.armature = armature;
    opt.damping = damping;
    const audit::dynamics_campaign c = audit::run_dynamics_checker(
        "recorder", "", [&seen](const rb::robot& r, const audit::dynamics_state&) {
          seen.push_back(r);
          return audit::dynamics_check{};
        }, opt);
    EXPECT_EQ(c.joint_terms, armature && damping ? "an armature and a damping"
                             : armature          ? "an armature"
                             : damping           ? "a damping"
                                                 : "");
    return seen;
  };
  const std::vector<rb::robot> plain = robots_of(false, false), rotors = robots_of(true, false),
                               both = robots_of(true, true);
  ASSERT_EQ(plain.size(), 60u);
  ASSERT_EQ(rotors.size(), 60u);
  ASSERT_EQ(both.size(), 60u);
  int with_armature = 0, with_damping = 0, floating = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    ASSERT_EQ(plain[i].joints.size(), both[i].joints.size()) << "robot " << i;
    floating += plain[i].floating;
    EXPECT_EQ(plain[i].floating, both[i].floating);
    for (std::size_t k = 0; k < plain[i].joints.size(); ++k) {
      const rb::joint &a = plain[i].joints[k], &r = rotors[i].joints[k], &b = both[i].joints[k];
      EXPECT_EQ(a.origin.xyz, b.origin.xyz);
      EXPECT_EQ(a.axis, b.axis);
      EXPECT_EQ(a.armature, 0.0);
      EXPECT_EQ(a.damping, 0.0);
      EXPECT_EQ(r.damping, 0.0);
      EXPECT_EQ(r.origin.rpy, b.origin.rpy);
      if (a.type == rb::joint_type::fixed) {
        EXPECT_EQ(b.armature + b.damping, 0.0);
        continue;
      }
      with_armature += b.armature > 0;
      with_damping += b.damping > 0;
    }
  }
  EXPECT_GT(floating, 10);
  EXPECT_GT(with_armature, 30);
  EXPECT_GT(with_damping, 30);
}

}  // namespace joint_terms_test
