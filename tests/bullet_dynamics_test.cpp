// Bullet's btMultiBody on a floating base (bullet::dynamics(true)): held through its
// convention where its base solve is exact, and its base solve measured on a light base
// carrying a heavy arm (docs/findings/dynamics.md, "Bullet's floating base").
#ifdef MECHCHECK_HAVE_BULLET
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "mechcheck/audit/adapters/bullet.hpp"
#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/robots.hpp"
#include "dynamics_fakes.hpp"
#include "two_link_arm.hpp"

namespace bullet_dynamics_test {
using namespace mechcheck;
namespace rb = mechcheck::robots;
namespace audit = mechcheck::audit;
using dynamics_fakes::floating_state;
using robots_test::free_body;
using robots_test::free_body_closed_form;

/// A light base (1/8 kg, moments 1/8) carrying a heavy arm (256 kg) on a hinge.
rb::robot light_base_heavy_arm() {
  rb::robot r;
  r.name = "light_base_heavy_arm";
  r.floating = true;
  rb::inertial base, arm;
  base.mass = 0.125;
  base.origin.xyz = {0, 0, -0.5};
  base.inertia = Eigen::Matrix3d::Identity() * 0.125;
  arm.mass = 256;
  arm.origin.xyz = {-0.0625, 0.09375, -0.375};
  arm.inertia = Eigen::Vector3d(0.125, 0.5, 0.5).asDiagonal();
  r.links = {{"base", base}, {"arm", arm}};
  rb::joint hinge;
  hinge.name = "hinge";
  hinge.parent = "base";
  hinge.child = "arm";
  hinge.origin.xyz = {0, 0, 0.125};
  hinge.origin.rpy = {1, -1.25, 2.5};
  hinge.axis = {0, 1, 0};
  r.joints = {hinge};
  return r;
}

TEST(bullet_dynamics, bullets_floating_base_is_held_through_its_convention_and_its_base_solve_measured_apart) {
  // Bullet's floating base (bullet::dynamics(true)): its point at the root's centre of mass,
  // velocities and forces in the world. The free body (no links: Bullet divides by its mass
  // and moments) gives the closed form's udot within the budget, the floating arm too; the
  // library of the campaigns refuses a floating robot with the finding's reason.
  constexpr double eps = 0x1p-52;
  const audit::dynamics_library floating = audit::bullet::dynamics(true);
  EXPECT_TRUE(floating.no_floating_base.empty());
  EXPECT_NE(audit::bullet::dynamics().no_floating_base.find("solveImatrix"), std::string::npos);
  {
    const rb::robot r = free_body();
    rb::pose at;
    at.xyz = {0.75, -0.5, 1.25};
    at.rpy = {0.5, -1.25, 2};
    Eigen::VectorXd u(6), udot(6);
    u << 0.5, -1, 1.5, 2, -0.75, 1.25;
    udot << -1, 0.25, 3, 0.5, -2, 1;
    const free_body_closed_form<double> given =
        robots_test::free_body_terms<double>(r, rb::rpy_rotation<double>(at.rpy), u, udot);
    const audit::dynamics_check c = audit::check_dynamics(floating, r, floating_state(at, Eigen::VectorXd(0), u, udot, given.q));
    ASSERT_EQ(c.residuals.size(), 1u) << c.refused;
    const audit::dynamics_residual& f = c.residuals.front();
    EXPECT_EQ(f.quantity, audit::dynamics_quantity::forward);
    EXPECT_TRUE(f.within()) << f.residual << " eps, budget " << f.budget;
    EXPECT_LE((f.library - udot).cwiseAbs().maxCoeff(), f.budget * eps * f.scale) << f.library.transpose();
  }
  {
    const rb::robot r = robots_test::floating_two_link_arm();
    rb::pose at;
    at.xyz = {0.25, 0.5, 1};
    at.rpy = {0.5, -0.25, 1.5};
    Eigen::VectorXd u(8), udot(8), force(8);
    u << 0.5, -1, 1.5, 2, -0.75, 1.25, 1.1, 0.4;
    udot << -1, 0.25, 3, 0.5, -2, 1, -0.5, 2;
    force << 1, -2, 0.5, 0.25, -0.5, 1, 3, -1;
    const audit::dynamics_check c =
        audit::check_dynamics(floating, r, floating_state(at, Eigen::Vector2d(0.3, -0.7), u, udot, force));
    ASSERT_EQ(c.residuals.size(), 1u) << c.refused;
    EXPECT_TRUE(c.residuals.front().within()) << c.residuals.front().residual << " eps";
  }
  // A light base carrying a heavy arm, at 200 random states (poses, twists, wrenches, the
  // hinge's angle, rate and torque uniform in [-3, 3], seed 1) for each of three base masses:
  // Bullet beyond the budget on some (its base solve, solveImatrix: docs/findings/dynamics.md),
  // DART, Simbody and MuJoCo within it on all, the largest residual of each printed.
  std::mt19937 g(1);
  std::uniform_real_distribution<double> d(-3, 3);
  for (const double mass : {0.125, 0.03125, 0.0078125}) {
    rb::robot r = light_base_heavy_arm();
    r.links[0].body->mass = mass;
    double bullet = 0, others = 0;
    int beyond = 0;
    for (int k = 0; k < 200; ++k) {
      rb::pose at;
      at.xyz = {d(g), d(g), d(g)};
      at.rpy = {d(g), d(g) / 2, d(g)};
      Eigen::VectorXd u(7), force(7);
      for (int i = 0; i < 7; ++i) u(i) = d(g), force(i) = d(g);
      const audit::dynamics_state x =
          floating_state(at, Eigen::VectorXd::Constant(1, d(g)), u, Eigen::VectorXd::Zero(7), force);
      const audit::dynamics_check c = audit::check_dynamics(floating, r, x);
      ASSERT_EQ(c.residuals.size(), 1u) << c.refused;
      beyond += c.residuals.front().within() ? 0 : 1;
      bullet = std::max(bullet, c.residuals.front().residual);
      for (const audit::dynamics_library& library : audit::dynamics_found())
        if (library.no_floating_base.empty())
          for (const audit::dynamics_residual& res : audit::check_dynamics(library, r, x).residuals)
            if (res.quantity == audit::dynamics_quantity::forward) {
              EXPECT_TRUE(res.within()) << library.name << ": " << res.residual << " eps";
              others = std::max(others, res.residual);
            }
    }
    std::printf("a base of %g kg under an arm of 256 kg, 200 states: Bullet's forward dynamics beyond the budget at %d, "
                "largest %.0f eps of the scale; the other libraries' largest %.2f\n",
                mass, beyond, bullet, others);
    EXPECT_GT(beyond, 0) << "Bullet's base solve within the budget on every state: the finding no longer holds";
  }
}

}  // namespace bullet_dynamics_test
#endif
