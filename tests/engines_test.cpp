// The engine audit against engines whose answers are known: a reference engine
// (reference_engine.hpp: classical RK4 on Euler's equations and the quaternion, on the
// pendulum and on the projectile) is of order 4 on every scenario; the same engine with the
// sign of the gyroscopic term flipped, or with an explicit Euler step, is classified right
// (their long runs: engine_long_runs_test). The
// scenarios' references are checked against the conservation laws they must obey (the
// engines this build found: engine_adapters_test).

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>
#include <cmath>

#include "mechcheck/audit/engines/engines.hpp"
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/integrators.hpp"
#include "mechcheck/reference/tops.hpp"
#include "mechcheck/rigid_body/heavy_top.hpp"
#include "reference_engine.hpp"

namespace engines_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

TEST(engines, the_references_keep_their_conservation_laws) {
  for (const auto& s : audit::scenarios()) {
    SCOPED_TRACE(s.name);
    if (s.kind == audit::scenario_kind::free_top || s.kind == audit::scenario_kind::free_top_near_axis ||
        s.kind == audit::scenario_kind::boxes) {
      // Energy and |M| of the elliptic solution, at several times, to a few eps.
      const auto at = [&](double t) {
        const Eigen::Vector3d w = s.exact(t), m = s.inertia.cwiseProduct(w);
        return std::pair{w.dot(m), m.norm()};
      };
      const auto [e0, m0] = at(0);
      for (const double t : {0.7, 3.1, 9.9}) {
        const auto [e, m] = at(t);
        EXPECT_NEAR(e, e0, 8 * 2.2e-16 * e0) << t;
        EXPECT_NEAR(m, m0, 8 * 2.2e-16 * m0) << t;
      }
      EXPECT_LT((s.exact(0) - s.omega0).norm(), 4e-16 * s.scale);
    } else if (s.kind == audit::scenario_kind::projectile) {
      EXPECT_EQ(s.exact(0).tail(3), Eigen::VectorXd(s.velocity0));
    } else if (s.joint == audit::joint_kind::hinge_y) {
      const double i_hinge = audit::hinge_inertia(s), l = -s.com(2);
      const auto energy = [&](double t) {
        const Eigen::VectorXd x = s.exact(t);
        return i_hinge * x(1) * x(1) / 2 - s.mass * s.gravity * l * std::cos(x(0));
      };
      for (const double t : {0.3, 1.1, 5.0}) EXPECT_NEAR(energy(t), energy(0), 1e-14) << t;
    }
  }
}

TEST(engines, a_reference_rk4_engine_is_of_order_4) {
  const auto a = audit::audit_engine(reference_engine("reference::RK4", method::rk4, 1, 4), short_runs());
  EXPECT_EQ(a.order.result, outcome::confirmed) << a.order.evidence;
  for (const auto& s : a.scenarios) {
    if (s.scenario.rfind("free_", 0) == 0 || s.scenario.rfind("pendulum", 0) == 0 || s.scenario == "boxes") {
      ASSERT_EQ(s.refused, "") << s.scenario;
    } else {
      // Its own refusal, or the audit's for an adapter without multibody scenarios.
      EXPECT_TRUE(s.refused.find("no " + s.scenario) != std::string::npos ||
                  s.refused.find("one-body scenarios only") != std::string::npos)
          << s.scenario << ": " << s.refused;
      continue;
    }
    EXPECT_NEAR(s.global.fit.value, 4, 0.3) << s.scenario;
  }
}

TEST(engines, a_sign_error_in_the_gyroscopic_term_is_contradicted) {
  // With I w' = -(M x w) the body runs Euler's equations backwards: the error at t_end is
  // of order one and does not fall with h (a stall far above the floor).
  audit::engine_options opt = short_runs();
  opt.scenarios = {"free_top"};
  const auto a = audit::audit_engine(reference_engine("reference::RK4_sign", method::rk4, -1, 4), opt);
  EXPECT_EQ(a.order.result, outcome::contradicted) << a.order.evidence;
  EXPECT_TRUE(a.scenarios[0].global.stalled) << a.order.evidence;
}

TEST(engines, the_new_references_agree_with_the_library) {
  constexpr double eps = 2.220446049250313e-16;
  const auto all = audit::scenarios();
  {  // Kepler: energy and angular momentum of the orbit through the rounded start.
    const auto& s = named(all, "kepler");
    const auto at = [&](double t) {
      const Eigen::VectorXd x = s.exact(t);
      const Eigen::Vector3d r = x.head<3>(), v = x.tail<3>();
      return std::pair{v.squaredNorm() / 2 - s.central / r.norm(), Eigen::Vector3d(r.cross(v))};
    };
    const auto [e0, l0] = at(0);
    EXPECT_LT((s.exact(0).head<3>() - s.position0).norm(), 4 * eps);
    for (const double t : {0.9, 3.3, 5.0}) {
      const auto [e, l] = at(t);
      EXPECT_NEAR(e, e0, 16 * eps * std::abs(e0)) << t;
      EXPECT_LT((l - l0).norm(), 16 * eps * l0.norm()) << t;
    }
  }
  {  // Free symmetric top: Omega turns at the body frequency and x3 about M at |M| / I1,
     // as reference::free_symmetric_top (eqs 179-188, 224) has them.
    const auto& s = named(all, "free_symmetric_top");
    const Eigen::Vector3d m = s.inertia.cwiseProduct(s.omega0);
    const reference::free_symmetric_top<double> ref(s.inertia(0), s.inertia(2), m.norm(), 0,
                                                    std::acos(m(2) / m.norm()), 0);
    const Eigen::Vector3d axis = m.normalized();
    const auto perpendicular = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(v - axis.dot(v) * axis); };
    const Eigen::Vector3d e0 = perpendicular(Eigen::Vector3d::UnitZ());
    for (const double t : {0.4, 1.3}) {
      const Eigen::VectorXd x = s.exact(t);
      const double body_angle = std::atan2(x(1), x(0)) - std::atan2(s.omega0(1), s.omega0(0));
      EXPECT_NEAR(body_angle, ref.body_frequency() * t, 16 * eps) << t;
      const Eigen::Vector3d e = perpendicular(x.tail<3>());
      const double swept = std::atan2(e0.cross(e).dot(axis), e0.dot(e));
      EXPECT_NEAR(swept, ref.precession_rate() * t, 16 * eps) << t;
    }
  }
  {  // Steady precession: the torque m g l z x x3 equals dL/dt = phidot z x L (eq 231),
     // with L about the pivot from the reference's own omega, at t = 0.
    const auto& s = named(all, "heavy_top");
    const Eigen::VectorXd x0 = s.exact(0);
    const Eigen::Vector3d e3 = x0.head<3>(), w = x0.tail<3>() * s.omega0.norm();
    const double l = s.com(2), i1 = s.inertia(0) + s.mass * l * l, i3 = s.inertia(2);
    const Eigen::Vector3d lmom = i1 * (w - w.dot(e3) * e3) + i3 * w.dot(e3) * e3;
    const Eigen::Vector3d x1 = s.exact(1e-3).head<3>(), xm = s.exact(-1e-3).head<3>();
    const double phidot = std::atan2(x1(1), x1(0)) / 1e-3;
    const Eigen::Vector3d torque = s.mass * s.gravity * l * Eigen::Vector3d::UnitZ().cross(e3);
    EXPECT_LT((phidot * Eigen::Vector3d::UnitZ().cross(lmom) - torque).norm(), 64 * eps * torque.norm());
    // d x3 / dt = omega x x3 by a central difference (error (h^2 / 6) |x3'''| ~ 1e-6):
    EXPECT_LT(((x1 - xm) / 2e-3 - w.cross(e3)).norm(), 1e-5);
    EXPECT_LT((s.omega0 / s.omega0.norm() - x0.tail<3>()).norm(), 4 * eps);
  }
  {  // Nutation: Hamilton's equations of the library's heavy top (closed form, eq 229's
     // Legendre transform) by RK4 with 4096 steps over eq 243's period (error ~ (h 40)^4
     // ~ 1e-10): theta is back at theta0 with p_theta = 0, and at the other turning point
     // half-way.
    const auto& s = named(all, "heavy_top_nutation");
    const double l = s.com(2), i1 = s.inertia(0) + s.mass * l * l, i3 = s.inertia(2), spin = 40, theta0 = 0.5;
    const heavy_top<double> top(i1, i3, s.mass * s.gravity * l);
    Eigen::VectorXd q(3), p(3);
    q << 0, theta0, 0;
    p << i3 * spin * std::cos(theta0), 0, i3 * spin;  // phidot = 0: p_phi = p_psi cos theta (eq 236)
    const auto field = [&](const Eigen::VectorXd& y) {
      Eigen::VectorXd dq(3), dp(3), out(6);
      top.vector_field(Eigen::VectorXd(y.head(3)), Eigen::VectorXd(y.tail(3)), dq, dp);
      out << dq, dp;
      return out;
    };
    Eigen::VectorXd y(6);
    y << q, p;
    const int n = 4096;
    const double h = s.t_end / n;
    const nutation<double> nu = top.nutation_from_turning_point(theta0, 0, spin);
    for (int i = 0; i < n; ++i) {
      const Eigen::VectorXd k1 = field(y), k2 = field(y + h / 2 * k1), k3 = field(y + h / 2 * k2),
                            k4 = field(y + h * k3);
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      if (i == n / 2 - 1) EXPECT_NEAR(std::cos(y(1)), nu.u_low, 1e-9);  // the lower turning point
    }
    EXPECT_NEAR(y(1), theta0, 1e-9);
    EXPECT_NEAR(y(4), 0, 1e-9);
    EXPECT_EQ(s.exact(s.t_end)(0), std::cos(theta0));
  }
}

TEST(engines, observe_computes_energy_and_momentum_by_their_closed_forms) {
  // Hand-built body states against the textbook expressions of each scenario.
  constexpr double eps = 2.220446049250313e-16;
  const auto all = audit::scenarios();
  {  // hinge pendulum: E = I thetadot^2 / 2 - m g l cos theta, I about the hinge
    const auto s = audit::with_hinge_state(named(all, "pendulum_large"), 0.7, -1.3);
    audit::body_reading r;
    r.rotation = s.rotation0;
    r.position = s.position0;
    r.velocity = s.velocity0;
    r.omega = s.omega0;
    const auto o = audit::observe(s, r);
    const double l = -s.com(2), expected = audit::hinge_inertia(s) * 1.3 * 1.3 / 2 - s.mass * s.gravity * l * std::cos(0.7);
    EXPECT_NEAR(o.energy, expected, 8 * eps * std::abs(expected));
    EXPECT_NEAR(o.observables(0), 0.7, 4 * eps);
    EXPECT_EQ(o.observables(1), -1.3);
  }
  {  // Kepler: E = m v^2 / 2 - m k / r, L = m x x v
    const auto& s = named(all, "kepler");
    audit::body_reading r;
    r.position = {0.3, -0.4, 0};
    r.velocity = {1, 2, 0};
    const auto o = audit::observe(s, r);
    EXPECT_NEAR(o.energy, s.mass * 5.0 / 2 - s.mass * s.central / 0.5, 8 * eps);
    EXPECT_LT((o.momentum - s.mass * Eigen::Vector3d(0, 0, 0.3 * 2 + 0.4 * 1)).norm(), 4 * eps);
  }
  {  // heavy top: only the vertical angular momentum about the pivot is kept
    const auto& s = named(all, "heavy_top");
    audit::body_reading r;
    r.rotation = s.rotation0;
    r.position = s.position0;
    r.velocity = s.velocity0;
    r.omega = s.omega0;
    const auto o = audit::observe(s, r);
    const Eigen::Vector3d wb = s.rotation0.transpose() * s.omega0;
    const Eigen::Vector3d l = s.mass * s.position0.cross(s.velocity0) + s.rotation0 * s.inertia.cwiseProduct(wb);
    EXPECT_EQ(o.momentum(0), 0);
    EXPECT_EQ(o.momentum(1), 0);
    EXPECT_NEAR(o.momentum(2), l(2), 8 * eps * l.norm());
    const double e = s.mass * s.velocity0.squaredNorm() / 2 + wb.dot(s.inertia.cwiseProduct(wb)) / 2 +
                     s.mass * s.gravity * s.position0(2);
    EXPECT_NEAR(o.energy, e, 8 * eps * e);
    EXPECT_GT(s.position0(2), 0);  // the centre of mass above the pivot: the potential counts up
  }
}

TEST(engines, the_hinge_is_read_from_one_set_of_coordinates_and_its_constraint_apart) {
  // A body state whose centre of mass is off the hinge's circle (an unconverged joint):
  // the observables come from the body frame (angle of the rotation, rate of omega), or
  // from the engine's joint coordinates where it gives them -- never the angle of the
  // centre of mass -- and the violation is measured on its own, in metres, m/s and rad.
  constexpr double eps = 2.220446049250313e-16;
  const auto s = audit::with_hinge_state(named(audit::scenarios(), "pendulum_small"), 0.3, 0.5);
  audit::body_reading r;
  r.rotation = s.rotation0;
  r.omega = s.omega0;
  const Eigen::Vector3d off(2e-4, 0, -1e-4), drift(0, 0, 3e-3);
  r.position = s.position0 + off;
  r.velocity = s.velocity0 + drift;
  auto o = audit::observe(s, r);
  EXPECT_NEAR(o.observables(0), 0.3, 4 * eps);  // the rotation's angle, not atan2 of the centre
  EXPECT_EQ(o.observables(1), 0.5);
  EXPECT_EQ(o.readout, "the body frame (rotation about y and angular velocity)");
  ASSERT_TRUE(o.constraint);
  EXPECT_NEAR(o.constraint->position, off.norm(), 4 * eps);
  EXPECT_NEAR(o.constraint->velocity, drift.norm(), 4 * eps);
  EXPECT_NEAR(o.constraint->axis, 0, 4 * eps);
  r.joint_q = Eigen::VectorXd::Constant(1, 0.31);
  r.joint_v = Eigen::VectorXd::Constant(1, 0.49);
  o = audit::observe(s, r);
  EXPECT_EQ(o.observables(0), 0.31);
  EXPECT_EQ(o.observables(1), 0.49);
  EXPECT_EQ(o.readout, "the engine's joint coordinates");
  // A tilted hinge axis: the body turned by 1e-3 about x as well.
  r.rotation = Eigen::AngleAxisd(1e-3, Eigen::Vector3d::UnitX()) * s.rotation0;
  o = audit::observe(s, r);
  EXPECT_NEAR(o.constraint->axis, 2 * std::sin(1e-3 / 2), 1e-15);
  // A free body has none.
  EXPECT_FALSE(audit::observe(named(audit::scenarios(), "free_top"), r).constraint);
}

TEST(engines, a_start_that_throws_is_a_recorded_failure_and_a_misspelt_scenario_an_error) {
  audit::engine_integrator e;
  e.name = "broken";
  e.start = [](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    if (s.name == "pendulum_small") throw std::runtime_error("cannot build the model");
    return std::make_unique<reference_run>(s, method::rk4, 1);
  };
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small", "free_top"};
  opt.long_run_steps = 64;
  opt.max_study_steps = 256;
  audit::engine_audit a;
  ASSERT_NO_THROW(a = audit::audit_engine(e, opt));
  ASSERT_EQ(a.scenarios.size(), 2u);  // in the order of scenarios(): free_top first
  ASSERT_EQ(a.scenarios[1].scenario, "pendulum_small");
  EXPECT_NE(a.scenarios[1].failure.find("cannot build the model"), std::string::npos) << a.scenarios[1].failure;
  EXPECT_TRUE(a.scenarios[0].failure.empty()) << a.scenarios[0].failure;
  EXPECT_GT(a.scenarios[0].global.fit.used, 0);
  opt.scenarios = {"pendulum_smal"};
  try {
    audit::audit_engine(e, opt);
    ADD_FAILURE() << "a misspelt scenario was accepted";
  } catch (const domain_error& x) {
    EXPECT_NE(std::string(x.what()).find("pendulum_smal"), std::string::npos);
    EXPECT_NE(std::string(x.what()).find("pendulum_small"), std::string::npos);  // the valid names
  }
}

TEST(engines, the_jacobian_study_has_known_answers) {
  // Explicit Euler on the pendulum: M = [[1, h], [-h w0^2 cos theta, 1]], det - 1 =
  // h^2 w0^2 cos theta exactly; symplectic Euler: det = 1. Declared symplectic, the first
  // is contradicted and the second confirmed.
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small", "pendulum_large"};
  opt.long_run_steps = 0;
  opt.max_study_steps = 256;
  auto euler = reference_engine("reference::Euler", method::euler, 1, 1);
  auto symplectic = reference_engine("reference::SymplecticEuler", method::symplectic_euler, 1, 1);
  euler.declared.symplectic = symplectic.declared.symplectic = true;
  const auto a = audit::audit_engine(euler, opt), b = audit::audit_engine(symplectic, opt);
  const auto all = audit::scenarios();
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& s = named(all, a.scenarios[i].scenario);
    const double w02 = s.mass * s.gravity * -s.com(2) / audit::hinge_inertia(s);
    const double theta = std::atan2(s.rotation0(0, 2), s.rotation0(0, 0));
    const double expected = s.h_long * s.h_long * w02 * std::cos(theta);
    ASSERT_TRUE(a.scenarios[i].det_minus_one);
    EXPECT_LE(a.scenarios[i].det_resolution, 1e-9) << s.name;
    EXPECT_NEAR(*a.scenarios[i].det_minus_one, expected, a.scenarios[i].det_resolution) << s.name;
    ASSERT_TRUE(b.scenarios[i].det_minus_one);
    EXPECT_LE(std::abs(*b.scenarios[i].det_minus_one), b.scenarios[i].det_resolution) << s.name;
  }
  EXPECT_EQ(a.symplectic.result, outcome::contradicted) << a.symplectic.evidence;
  EXPECT_EQ(b.symplectic.result, outcome::confirmed) << b.symplectic.evidence;
  // A step that contracts area (symplectic Euler, then the rate damped by exp(-0.5 h): det =
  // exp(-0.5 h), det - 1 = -5.0e-3 at h = 0.01) declared symplectic: contradicted too.
  auto damped = reference_engine("reference::DampedSymplecticEuler", method::damped, 1, 1);
  damped.declared.symplectic = true;
  const auto d = audit::audit_engine(damped, opt);
  for (const auto& sc : d.scenarios) {
    ASSERT_TRUE(sc.det_minus_one) << sc.scenario;
    const auto& s = named(all, sc.scenario);
    EXPECT_NEAR(*sc.det_minus_one, std::expm1(-damping * s.h_long), sc.det_resolution) << sc.scenario;
  }
  EXPECT_EQ(d.symplectic.result, outcome::contradicted) << d.symplectic.evidence;
  // A Jacobian that ran and resolved nothing (the state rounded to 2^-16 = 1.5e-5 a step, the
  // engine saying double): declared symplectic, not resolvable, with what it needs.
  auto coarse = reference_engine("reference::CoarseSymplecticEuler", method::coarse, 1, 1);
  coarse.declared.symplectic = true;
  const auto c = audit::audit_engine(coarse, opt);
  for (const auto& sc : c.scenarios) {
    ASSERT_TRUE(sc.det_minus_one) << sc.scenario << ": " << sc.long_run_failure;
    EXPECT_GT(sc.det_resolution, 1e-6) << sc.scenario;
  }
  EXPECT_EQ(c.symplectic.result, outcome::not_resolvable) << c.symplectic.evidence;
  EXPECT_EQ(c.symplectic.measured, "not resolved");
  EXPECT_NE(c.symplectic.needs.find("a Jacobian resolved to 1e-06 or better"), std::string::npos) << c.symplectic.needs;
  // Nothing declared: the defect is reported, the verdict says nothing was declared.
  euler.declared.symplectic.reset();
  const auto u = audit::audit_engine(euler, opt);
  EXPECT_EQ(u.symplectic.result, outcome::not_declared) << u.symplectic.evidence;
  EXPECT_EQ(u.symplectic.measured, "no (a defect above the resolution)");
}

TEST(engines, the_reversal_study_has_known_answers) {
  // h then -h: Stormer-Verlet returns to its start to rounding; explicit Euler misses it
  // by O(h^2) (the defect falls by 4 when h halves).
  audit::engine_options opt;
  opt.scenarios = {"pendulum_large"};
  opt.long_run_steps = 0;
  opt.max_study_steps = 256;
  const auto v = audit::audit_engine(reference_engine("reference::Verlet", method::verlet, 1, 2), opt);
  const auto e = audit::audit_engine(reference_engine("reference::Euler", method::euler, 1, 1), opt);
  ASSERT_TRUE(v.scenarios[0].reversal_defect && e.scenarios[0].reversal_defect);
  EXPECT_LT(*v.scenarios[0].reversal_defect, 16 * 2.2e-16);
  EXPECT_NEAR(*e.scenarios[0].reversal_defect / *e.scenarios[0].reversal_defect_half, 4, 0.1);
}

/// mechcheck's own steppers as an engine on the hinge scenarios: the pendulum as
/// pendulum_system with m l^2 = I about the hinge and m g l the scenario's (l = 1), the
/// state (theta, p = I thetadot) read back as a body turned by theta about y.
template <template <class, class> class Method>
audit::engine_integrator library_engine(const std::string& name) {
  using V = dynamic_vector<double>;
  using stepper = Method<pendulum_system<double>, V>;
  struct run final : audit::engine_run {
    explicit run(const audit::scenario& s)
        : s_(s), i_(audit::hinge_inertia(s)),
          step_(pendulum_system<double>(i_, 1, s.mass * s.gravity * -s.com(2) / i_)) {
      if (s.joint != audit::joint_kind::hinge_y) throw audit::scenario_refused("library stepper: hinges only");
      x_.q = V::Constant(1, std::atan2(s.rotation0(0, 2), s.rotation0(0, 0)));
      x_.p = V::Constant(1, i_ * s.omega0(1));
    }
    void step(double h) override { step_(x_, h); }
    audit::body_reading read() const override {
      audit::body_reading r;
      r.rotation = Eigen::AngleAxisd(x_.q(0), Eigen::Vector3d::UnitY()).toRotationMatrix();
      r.position = r.rotation * s_.com;
      r.omega = {0, x_.p(0) / i_, 0};
      r.velocity = r.omega.cross(r.position);
      return r;
    }
    audit::scenario s_;
    double i_;
    mutable stepper step_;
    phase_state<V> x_;
  };
  audit::engine_integrator e;
  e.name = name;
  e.declared.order = stepper::order;
  e.declared.symplectic = stepper::symplectic;
  e.start = [](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> { return std::make_unique<run>(s); };
  return e;
}

TEST(engines, the_library_steppers_as_an_engine_get_the_stepper_audits_verdicts) {
  // The stepper audit confirms each one's declared order and symplecticity; so must the
  // engine audit, through a black box that only steps and reads a body back.
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small", "pendulum_large"};
  opt.long_run_steps = 1 << 14;
  for (const auto& e : {library_engine<explicit_euler>("library::explicit_euler"), library_engine<rk4>("library::rk4"),
                        library_engine<symplectic_euler>("library::symplectic_euler"),
                        library_engine<stormer_verlet>("library::stormer_verlet")}) {
    const auto a = audit::audit_engine(e, opt);
    EXPECT_EQ(a.order.result, outcome::confirmed) << e.name << ": " << a.order.evidence;
    // RK4's area defect at h = 0.01 (~1e-11) is below the resolution: not resolvable here.
    EXPECT_EQ(a.symplectic.result, e.name == "library::rk4" ? outcome::not_resolvable : outcome::confirmed)
        << e.name << ": " << a.symplectic.evidence;
    if (e.name == "library::stormer_verlet") {  // symmetric: back at the start to rounding
      EXPECT_LT(*a.scenarios[0].reversal_defect, 16 * 2.2e-16) << e.name;
      EXPECT_EQ(audit::growth_kind(*a.scenarios[1].energy_growth), "bounded") << e.name;
    }
  }
}

TEST(engines, the_shape_audit_has_known_answers) {
  // An engine that takes the capsule's inertia from its bounding box (2r, 2r, h + 2r):
  // its largest relative error is derived here from the two closed forms; the compound's
  // exact moments are (2/5) m r^2 and (2/5) m r^2 + m d^2 (eq 160).
  constexpr double eps = 2.220446049250313e-16;
  audit::engine_shapes boxy;
  boxy.engine = "boxy";
  boxy.moments = [](const audit::shape& s) -> Eigen::Vector3d {
    if (s.name != "capsule") return audit::exact_principal_moments(s);
    const double r = s.size(0), h = s.size(1), a = 2 * r, c = h + 2 * r;
    return s.mass / 12 * Eigen::Vector3d(a * a + c * c, a * a + c * c, 2 * a * a);
  };
  for (const auto& a : audit::audit_shapes(boxy)) {
    if (a.shape != "capsule") {
      EXPECT_EQ(a.relative_error, 0) << a.shape;
      continue;
    }
    const double r = 0.2, h = 0.6, m = 2, mc = m * h / (h + 4 * r / 3), mh = (m - mc) / 2;
    const double side = mc * (3 * r * r + h * h) / 12 + 2 * mh * (2 * r * r / 5 + h * h / 4 + 3 * h * r / 8);
    const double axial = mc * r * r / 2 + 4 * mh * r * r / 5;
    const double box_side = m / 12 * (4 * r * r + (h + 2 * r) * (h + 2 * r)), box_axial = m / 12 * 8 * r * r;
    EXPECT_NEAR(a.relative_error, std::max(box_side / side - 1, box_axial / axial - 1), 16 * eps);
  }
  const auto all = audit::shapes();
  // The convex hull, the tetrahedron (+-a, 0, c), (0, +-b, -c): C = (m/20) sum v v^T =
  // m diag(a^2/10, b^2/10, c^2/5), I = tr(C) - C; its volume |det(v1 - v0, v2 - v0, v3 - v0)| / 6.
  const auto& hull = *std::find_if(all.begin(), all.end(), [](const auto& s) { return s.name == "convex_hull"; });
  {
    const double a = hull.size(0), b = hull.size(1), c = hull.size(2), m = hull.mass;
    Eigen::Vector3d expected(m * (b * b / 10 + c * c / 5), m * (a * a / 10 + c * c / 5), m * (a * a + b * b) / 10);
    std::sort(expected.data(), expected.data() + 3);
    EXPECT_LT((audit::exact_principal_moments(hull) - expected).cwiseQuotient(expected).cwiseAbs().maxCoeff(), 8 * eps);
    Eigen::Matrix3d edges;
    edges << -2 * a, -a, -a, 0, b, -b, 0, -2 * c, -2 * c;  // columns v1 - v0, v2 - v0, v3 - v0
    EXPECT_NEAR(audit::shape_volume(hull), std::abs(edges.determinant()) / 6, 8 * eps * audit::shape_volume(hull));
  }
  const auto& two = *std::find_if(all.begin(), all.end(), [](const auto& s) { return s.name == "two_spheres"; });
  const double r = two.size(0), d = two.size(1), m = two.mass;
  const Eigen::Vector3d expected(0.4 * m * r * r, 0.4 * m * r * r + m * d * d, 0.4 * m * r * r + m * d * d);
  EXPECT_LT((audit::exact_principal_moments(two) - expected).cwiseQuotient(expected).cwiseAbs().maxCoeff(), 4 * eps);
}

TEST(engines, a_shape_without_a_mass_is_judged_at_the_mass_the_engine_gives_it) {
  // Without a mass: the box of a density of 1000 (the exact solid: no error), a fixed mass 1
  // and unit moments whatever the shape (the box's error derived from its smallest moment,
  // m (0.3^2 + 0.5^2) / 12), a static body of mass 0 (nothing compared, nothing NaN), a
  // negative mass and a NaN (failures, each its own row).
  constexpr double eps = 2.220446049250313e-16;
  const auto box = audit::shapes().front();
  ASSERT_EQ(box.name, "box");
  ASSERT_NEAR(audit::shape_volume(box), 0.3 * 0.5 * 0.7, 2 * eps * 0.105);
  for (const double given : {-1.0, 0.0, 1.0, 1000.0, std::nan("")}) {
    audit::engine_shapes e;
    e.engine = "e";
    e.moments = [](const audit::shape& s) -> Eigen::Vector3d { return audit::exact_principal_moments(s); };
    e.without_mass = [given](const audit::shape& s) {
      audit::shape at = s;
      at.mass = given == 1000 ? 1000 * audit::shape_volume(s) : given;
      const Eigen::Vector3d m = given == 1000 ? audit::exact_principal_moments(at) : Eigen::Vector3d::Constant(given == 1 ? 1 : 0);
      return audit::engine_default_mass{at.mass, m, "said"};
    };
    const auto rows = audit::audit_shapes(e);
    ASSERT_EQ(rows.size(), 2 * audit::shapes().size());
    const auto& a = rows[1];
    ASSERT_FALSE(a.mass_given);
    EXPECT_TRUE(rows[0].mass_given && rows[0].relative_error == 0);
    if (given < 0 || std::isnan(given)) {
      EXPECT_NE(a.failure.find(given < 0 ? "a negative mass" : "is not finite"), std::string::npos) << a.failure;
      continue;
    }
    EXPECT_TRUE(a.failure.empty()) << a.failure;
    EXPECT_EQ(a.said, "said");
    if (given == 0) {
      EXPECT_EQ(a.relative_error, 0);
      EXPECT_EQ(a.density, 0);
      EXPECT_EQ(a.exact, Eigen::Vector3d::Zero());
    } else if (given == 1) {
      EXPECT_NEAR(a.relative_error, 12 / (0.3 * 0.3 + 0.5 * 0.5) - 1, 64 * eps);
      EXPECT_NEAR(a.density, 1 / 0.105, 4 * eps / 0.105);
    } else {
      EXPECT_EQ(a.relative_error, 0);
      EXPECT_NEAR(a.density, 1000, 4 * eps * 1000);
    }
    const std::string md = audit::engines_to_markdown({}, rows), js = audit::engines_to_json({}, rows);
    EXPECT_NE(md.find("### A shape without mass properties"), std::string::npos);
    for (const std::string& text : {md, js}) EXPECT_EQ(text.find("nan"), std::string::npos) << text;
    EXPECT_NE(js.find("\"mass_given\": false"), std::string::npos);
  }
}

TEST(engines, random_bodies_are_drawn_by_their_seed_and_start_where_their_references_do) {
  const auto four = audit::random_body_scenarios(4, 7), two = audit::random_body_scenarios(2, 7);
  const auto other = audit::random_body_scenarios(1, 8);
  ASSERT_EQ(four.size(), 4u);
  EXPECT_EQ(four[1].name, "body_7_1");
  for (int k = 0; k < 2; ++k) EXPECT_EQ(four[k].description, two[k].description);
  EXPECT_NE(four[0].description, other[0].description);
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (const auto& s : four) {
    EXPECT_TRUE(s.inertia(0) < s.inertia(1) && s.inertia(1) < s.inertia(2) && s.inertia(2) < s.inertia(0) + s.inertia(1));
    const Eigen::Vector3d body = s.rotation0.transpose() * s.omega0;
    EXPECT_GE((body.array() != 0).count(), 2) << s.name;  // about no principal axis
    EXPECT_FALSE(s.rotation0.isIdentity(0.1)) << s.name;
    // The observation of the start the engine is given is the reference at 0, to rounding.
    audit::body_reading start;
    start.rotation = s.rotation0;
    start.omega = s.omega0;
    start.position = s.position0;
    start.velocity = s.velocity0;
    const Eigen::VectorXd seen = audit::observe(s, start).observables, exact = s.exact(0);
    EXPECT_LE((seen - exact).norm() / s.scale, 16 * eps) << s.name;
    // Energy and angular momentum of the reference: |I Omega| and Omega.I Omega kept.
    const Eigen::VectorXd later = s.exact(s.t_end);
    const Eigen::Vector3d w0 = exact.head<3>(), w1 = later.head<3>();
    EXPECT_NEAR(w1.dot(s.inertia.cwiseProduct(w1)), w0.dot(s.inertia.cwiseProduct(w0)),
                64 * eps * w0.dot(s.inertia.cwiseProduct(w0)));
    EXPECT_NEAR(later.segment<3>(3).norm(), 1, 16 * eps);
    EXPECT_LE((later.segment<3>(6) - (s.position0 + s.t_end * s.velocity0)).norm(), 16 * eps * s.scale);
  }
}

TEST(engines, rk4_is_of_order_4_on_random_bodies_in_every_class_and_a_wrong_turn_is_caught_in_the_orientation) {
  audit::engine_options opt = short_runs();
  opt.drawn = audit::random_body_scenarios(3, 1);
  for (const auto& s : opt.drawn) opt.scenarios.push_back(s.name);
  const auto a = audit::audit_engine(reference_engine("reference::RK4", method::rk4, 1, 4), opt);
  EXPECT_EQ(a.order.result, outcome::confirmed) << a.order.evidence;
  ASSERT_EQ(a.scenarios.size(), 3u);
  for (const auto& s : a.scenarios) {
    ASSERT_EQ(s.refused + s.failure, "") << s.scenario;
    for (const auto& [name, study] : s.classes)
      if (name == "angular velocity" || name == "orientation") EXPECT_NEAR(study.fit.value, 4, 0.3) << s.scenario << " " << name;
  }
  // Turned about the world's axes by the body's rates: Euler's equations still hold, so the
  // body angular velocity is of order 4, but the orientation stalls.
  const auto w = audit::audit_engine(reference_engine("reference::RK4_world_turn", method::rk4_world_turn, 1, 4), opt);
  EXPECT_EQ(w.order.result, outcome::contradicted) << w.order.evidence;
  for (const auto& s : w.scenarios)
    for (const auto& [name, study] : s.classes) {
      if (name == "angular velocity") EXPECT_NEAR(study.fit.value, 4, 0.3) << s.scenario;
      if (name == "orientation") EXPECT_TRUE(study.stalled) << s.scenario;
    }
  // The gyroscopic term's sign flipped: the angular velocity stalls too.
  const auto g = audit::audit_engine(reference_engine("reference::RK4_sign", method::rk4, -1, 4), opt);
  EXPECT_EQ(g.order.result, outcome::contradicted) << g.order.evidence;
}

TEST(engines, a_free_body_scenario_refuses_what_is_not_a_free_asymmetric_body) {
  const Eigen::Matrix3d one = Eigen::Matrix3d::Identity();
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero(), w(1, 0.2, 0.5);
  EXPECT_NO_THROW(audit::free_body_scenario("ok", 1, {1, 2, 2.5}, one, zero, zero, w));
  EXPECT_THROW(audit::free_body_scenario("b", 1, {1, 1, 2}, one, zero, zero, w), domain_error);    // symmetric
  EXPECT_THROW(audit::free_body_scenario("b", 1, {1, 2, 3.5}, one, zero, zero, w), domain_error);  // triangle
  EXPECT_THROW(audit::free_body_scenario("b", 0, {1, 2, 2.5}, one, zero, zero, w), domain_error);
  EXPECT_THROW(audit::free_body_scenario("b", 1, {1, 2, 2.5}, 2 * one, zero, zero, w), domain_error);
  EXPECT_THROW(audit::free_body_scenario("b", 1, {1, 2, 2.5}, one, zero, zero, zero), domain_error);
  EXPECT_THROW(audit::free_body_scenario("b", 1, {1, 2, 2.5}, one, zero, zero, {0, 1, 0}), domain_error);  // separatrix
  try {
    audit::free_body_scenario("b", 1, {1, 2, 2.5}, one, zero, zero, {NAN, 0, 1});
    ADD_FAILURE() << "a non-finite omega0 was taken";
  } catch (const non_finite_error& e) {
    EXPECT_NE(std::string(e.what()).find("omega0 = "), std::string::npos) << e.what();
  }
  EXPECT_THROW(audit::random_body_scenarios(-1, 1), domain_error);
}

}  // namespace engines_test
