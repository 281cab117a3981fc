// The engine adapters this build found (adapters/found.hpp), each pinned on what the report
// says about it: every engine's box, sphere and cylinder to rounding, every adapter's start at
// the scenario's exact state and its clock, Simbody's integrators below their headers' order
// and its symplectic ones keeping the area, MuJoCo's integrators, its RK4's order, its error
// handler and its divergence.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "mechcheck/audit/engines/engines.hpp"
#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/studies.hpp"

#ifdef MECHCHECK_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace engine_adapters_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

TEST(engines, every_engine_computes_the_box_sphere_and_cylinder_to_rounding) {
  // Closed forms in double: a few roundings (4 eps relative); Bullet's capsule, cone and
  // compound come from bounding boxes (its source: "as an approximation, take the inertia of
  // the box that bounds the spheres"; "approximation: take the inertia from the aabb for
  // now") and are off by 42 %, 336 % and 67 % here, its convex hull (the same aabb) by 440 %.
  // MuJoCo keeps a mesh's vertices as float: the hull's moments, sums of their squares
  // (no cancellation: the tetrahedron's centroid is the origin), within two float roundings.
  constexpr double eps = 2.220446049250313e-16;
  for (const auto& engine : audit::shapes_found())
    for (const auto& a : audit::audit_shapes(engine)) {
      if (!a.refused.empty()) continue;
      if (engine.engine == "bullet" &&
          (a.shape == "capsule" || a.shape == "cone" || a.shape == "two_spheres" || a.shape == "convex_hull")) {
        EXPECT_GT(a.relative_error, 0.4) << a.shape;
        continue;
      }
      if (engine.engine == "mujoco" && a.shape == "convex_hull") {
        EXPECT_LE(a.relative_error, 0x1p-23);
        continue;
      }
      EXPECT_LE(a.relative_error, 4 * eps) << engine.engine << " " << a.shape;
    }
}

TEST(engines, every_adapter_starts_each_scenario_at_its_exact_state) {
  // The mapping of each scenario to the engine's frames, signs and units, checked where it
  // is exact: the observables at t = 0 (rounding of the engine's rotation and joint
  // bookkeeping: 1e-12 of the scale).
  for (const auto& e : audit::engines_found())
    for (const auto& s : audit::scenarios()) {
      if (e.contact_only) continue;  // a contact setting: contact scenarios alone (contact_test.cpp)
      // Multibody scenarios go to adapters that build them (audit_engine refuses the rest).
      if (s.structure != audit::body_structure::one_body && !e.multibody) continue;
      std::unique_ptr<audit::engine_run> run;
      try {
        run = e.start(s);
      } catch (const audit::scenario_refused& r) {
        // CPodes where SUNDIALS is linked; Bullet's btMultiBody adapter builds joints only.
        EXPECT_TRUE(e.name == "simbody::CPodes" || (e.name == "bullet::multibody" && s.joint == audit::joint_kind::free))
            << r.what();
        continue;
      }
      const Eigen::VectorXd x = audit::observe(s, run->read()).observables, exact = s.exact(0);
      ASSERT_EQ(x.size(), exact.size()) << e.name << " " << s.name;
      EXPECT_LT((x - exact).norm(), 1e-12 * s.scale) << e.name << " " << s.name << ": " << x.transpose()
                                                      << " against " << exact.transpose();
    }
}

TEST(engines, every_adapter_advances_its_clock_by_h_a_step) {
  // No force along x on the projectile: x(T) = v0x T after n steps of T / n whatever the
  // integrator -- a step skipped or doubled by the adapter shows as x off by v0x T / n.
  const auto all = audit::scenarios();
  const auto s = *std::find_if(all.begin(), all.end(), [](const auto& x) { return x.name == "projectile"; });
  // An integrator that refuses the step size (Simbody's CPodes keeps its own error test)
  // must say so as a typed error naming the step.
  for (const auto& e : audit::engines_found()) {
    if (e.contact_only) continue;
    std::unique_ptr<audit::engine_run> run;
    try {
      run = e.start(s);
    } catch (const audit::scenario_refused& r) {
      EXPECT_TRUE(e.name == "simbody::CPodes" || e.name == "bullet::multibody") << r.what();
      continue;
    }
    try {
      for (int i = 0; i < 16; ++i) run->step(s.t_end / 16);
    } catch (const convergence_error& ex) {
      EXPECT_NE(std::string(ex.what()).find("step "), std::string::npos) << ex.what();
      EXPECT_EQ(e.name, "simbody::CPodes") << ex.what();
      continue;
    }
    EXPECT_NEAR(audit::observe(s, run->read()).observables(0), s.velocity0(0) * s.t_end, 1e-12) << e.name;
  }
}

#ifdef MECHCHECK_HAVE_SIMBODY
TEST(simbody, verlet_and_feldberg_are_of_lower_order_than_their_headers_say) {
  // VerletIntegrator.h: "a third order, semi-explicit integrator": 2.00 on the pendulum,
  // which the reading "third order = the local error" (Simbody's own error order 3)
  // confirms; RungeKuttaFeldbergIntegrator.h: "fifth order": 4.00 (it propagates the
  // 4th-order solution) under every reading; RungeKuttaMerson's "fourth order" holds.
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small"};
  opt.long_run_steps = 0;
  for (const auto& e : audit::simbody::integrators()) {
    if (e.name != "simbody::Verlet" && e.name != "simbody::RungeKuttaFeldberg" && e.name != "simbody::RungeKuttaMerson")
      continue;
    const auto a = audit::audit_engine(e, opt);
    const double expected = e.name == "simbody::Verlet" ? 2 : 4;
    EXPECT_NEAR(a.scenarios[0].global.fit.value, expected, 0.05) << e.name << ": " << a.order.evidence;
    EXPECT_EQ(a.order.result, e.name == "simbody::RungeKuttaMerson" ? outcome::confirmed
                              : e.name == "simbody::Verlet"          ? outcome::reading
                                                                     : outcome::contradicted)
        << e.name << ": " << a.order.evidence;
    if (e.name == "simbody::Verlet") {
      ASSERT_EQ(a.order.readings.size(), 2u);
      EXPECT_FALSE(a.order.readings[0].holds);
      EXPECT_TRUE(a.order.readings[1].holds);
    }
  }
}
#endif

#ifdef MECHCHECK_HAVE_SIMBODY
TEST(simbody, its_symplectic_integrators_keep_the_area) {
  // SemiExplicitEulerIntegrator.h ("also known as ... Symplectic Euler") and
  // VerletIntegrator.h ("with fixed size time steps, it is symplectic"): det M = 1 within
  // the resolution on both pendulums; ExplicitEuler's det - 1 = h^2 w0^2 cos theta.
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small", "pendulum_large"};
  opt.long_run_steps = 0;
  opt.max_study_steps = 256;
  for (const auto& e : audit::simbody::integrators()) {
    if (e.name != "simbody::SemiExplicitEuler" && e.name != "simbody::Verlet" && e.name != "simbody::ExplicitEuler")
      continue;
    const auto a = audit::audit_engine(e, opt);
    if (e.name == "simbody::ExplicitEuler") {
      EXPECT_EQ(a.symplectic.measured, "no (a defect above the resolution)") << a.symplectic.evidence;
      const double w02 = 9.81 / 1.001;  // m g l / (m l^2 + 1e-3)
      EXPECT_NEAR(*a.scenarios[0].det_minus_one, 0.01 * 0.01 * w02 * std::cos(0.1), a.scenarios[0].det_resolution);
    } else {
      EXPECT_EQ(a.symplectic.result, outcome::confirmed) << e.name << ": " << a.symplectic.evidence;
    }
  }
}
#endif

#if defined(MECHCHECK_HAVE_BULLET) && defined(MECHCHECK_HAVE_ODE)
TEST(engines, without_the_gyroscopic_term_a_free_top_converges_to_the_wrong_motion) {
  // Bullet with no gyroscopic flag and ODE with dBodySetGyroscopicMode(0) keep the world
  // angular velocity constant: the runs agree with each other, not with Euler's equations.
  audit::engine_options opt;
  opt.scenarios = {"free_top"};
  opt.long_run_steps = 0;
  for (const auto& e : audit::engines_found()) {
    if (e.name != "bullet::gyroscopic_none" && e.name != "ode::step/no_gyroscopic") continue;
    const auto a = audit::audit_engine(e, opt);
    ASSERT_TRUE(a.scenarios[0].global.stalled) << e.name;
    EXPECT_GT(a.scenarios[0].global.stalled->error, 0.5) << e.name;
  }
}
#endif

#ifdef MECHCHECK_HAVE_MUJOCO
TEST(mujoco, integrators_and_their_orders_on_the_free_top) {
  EXPECT_EQ(audit::mujoco::version(), "2.2.2");
  const auto all = audit::mujoco::integrators();
  // Euler, implicit, RK4, RK4/dexp_corrected, and Euler/elliptic for contact alone.
  ASSERT_EQ(all.size(), 5u);
  EXPECT_EQ(std::count_if(all.begin(), all.end(), [](const auto& e) { return e.contact_only && e.contact; }), 1);
  audit::engine_options opt;
  opt.scenarios = {"free_top", "pendulum_small"};
  opt.long_run_steps = 1 << 14;
  for (const auto& e : all) {
    if (e.contact_only) continue;
    const auto a = audit::audit_engine(e, opt);
    EXPECT_EQ(a.order.result, outcome::confirmed) << e.name << ": " << a.order.evidence;
    EXPECT_NEAR(a.scenarios[0].global.fit.value, *e.declared.order, 0.1) << e.name;
    if (e.name != "mujoco::RK4/dexp_corrected") EXPECT_NE(e.origin.find("mjmodel.h"), std::string::npos) << e.name;
  }
}

TEST(mujoco, rk4_is_of_second_order_once_the_orientation_matters) {
  // mj_RungeKutta adds up the stages' velocities and integrates the quaternion once with
  // their weighted sum: 4.00 where the observables do not depend on the orientation (the
  // free top's body angular velocity, the Kepler orbit), 2.00 where they do (the
  // symmetric top's axis, the heavy top).
  audit::engine_options opt;
  opt.scenarios = {"free_top", "free_symmetric_top", "heavy_top", "kepler"};
  opt.long_run_steps = 0;
  for (const auto& e : audit::mujoco::integrators()) {
    if (e.name != "mujoco::RK4") continue;
    const auto a = audit::audit_engine(e, opt);
    for (const auto& s : a.scenarios) {
      const double expected = s.scenario == "free_top" || s.scenario == "kepler" ? 4 : 2;
      EXPECT_NEAR(s.global.fit.value, expected, 0.1) << s.scenario;
      // Per class: 2 in the orientation; the free tops' body angular velocity (Euler's
      // equations do not involve the orientation), the position and the velocity keep 4;
      // on the heavy top gravity's torque turns with the body, and its angular velocity
      // inherits the orientation's 2.
      for (const auto& [name, study] : s.classes)
        EXPECT_NEAR(study.fit.value, name == "orientation" || s.scenario == "heavy_top" ? 2 : 4, 0.1)
            << s.scenario << " " << name;
    }
    EXPECT_EQ(a.order.result, outcome::contradicted) << a.order.evidence;
    for (const auto& v : a.order_by_class)
      EXPECT_EQ(v.result, v.claim == "order in the orientation" || v.claim == "order in the angular velocity"
                              ? outcome::contradicted
                              : outcome::confirmed)
          << v.claim << ": " << v.evidence;
    EXPECT_NE(a.order.measured.find("in the orientation"), std::string::npos) << a.order.measured;
  }
}

TEST(mujoco, the_dexp_corrected_rk4_is_of_fourth_order_where_rk4_is_of_second) {
  // The same four mj_forward evaluations, each stage's body angular velocity through the
  // dexp^-1 series: 4.00 in every class of every scenario where mujoco::RK4 measures 2
  // (on heavy_top_nutation the axis is read at a turning point, where both gain an order:
  // 5 against 3).
  audit::engine_options opt;
  opt.scenarios = {"free_symmetric_top", "heavy_top", "heavy_top_nutation"};
  opt.long_run_steps = 0;
  const auto all = audit::mujoco::integrators();
  const auto corrected = std::find_if(all.begin(), all.end(), [](const auto& e) { return e.name == "mujoco::RK4/dexp_corrected"; });
  const auto plain = std::find_if(all.begin(), all.end(), [](const auto& e) { return e.name == "mujoco::RK4"; });
  ASSERT_NE(corrected, all.end());
  const auto a = audit::audit_engine(*corrected, opt), b = audit::audit_engine(*plain, opt);
  EXPECT_EQ(a.order.result, outcome::confirmed) << a.order.evidence;
  EXPECT_EQ(b.order.result, outcome::contradicted) << b.order.evidence;
  for (std::size_t i = 0; i < a.scenarios.size(); ++i)
    for (std::size_t c = 0; c < a.scenarios[i].classes.size(); ++c) {
      const auto& [name, study] = a.scenarios[i].classes[c];
      const double gained = a.scenarios[i].scenario == "heavy_top_nutation" && name == "orientation" ? 1 : 0;
      EXPECT_NEAR(study.fit.value, 4 + gained, 0.15) << a.scenarios[i].scenario << " " << name;
      if (name == "orientation")
        EXPECT_NEAR(b.scenarios[i].classes[c].second.fit.value, 2 + gained, 0.1) << a.scenarios[i].scenario;
    }
}

TEST(mujoco, its_error_handler_throws_instead_of_exiting) {
  audit::mujoco::install_handlers();
  EXPECT_THROW(mju_error("a test of the handler"), mechcheck::error);
}

TEST(mujoco, a_run_that_diverges_ends_with_its_step_named) {
  // Semi-implicit Euler on the heavy top at h = 0.002 gains energy until MuJoCo's
  // bad-acceleration warning: the long run records the step and stops there.
  audit::engine_options opt;
  opt.scenarios = {"heavy_top"};
  opt.long_run_steps = 100000;
  opt.max_study_steps = 64;
  const auto a = audit::audit_engine(audit::mujoco::integrators().front(), opt);
  ASSERT_EQ(a.integrator, "mujoco::Euler");
  EXPECT_NE(a.scenarios[0].long_run_failure.find("MuJoCo warning"), std::string::npos)
      << a.scenarios[0].long_run_failure;
  EXPECT_LT(a.scenarios[0].long_run_steps, 100000);
  // It stops near t = 30 with an energy error far past order one (finite: the diverged state
  // is not read): not conserved, whatever the length of the run.
  EXPECT_EQ(a.scenarios[0].energy_class, audit::lost_class);
  EXPECT_GE(a.scenarios[0].energy_max, 0.25);
  EXPECT_TRUE(std::isfinite(a.scenarios[0].energy_max));
}

TEST(mujoco, a_zero_or_non_finite_step_is_a_typed_error) {
  const auto e = audit::mujoco::integrators().front();
  auto r = e.start(audit::scenarios().front());
  EXPECT_THROW(r->step(0), domain_error);
  EXPECT_THROW(r->step(std::nan("")), domain_error);
  EXPECT_NO_THROW(r->step(-0.01));  // MuJoCo integrates backwards (the reversal study)
}
#endif

}  // namespace engine_adapters_test
