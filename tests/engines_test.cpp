// The engine audit against engines whose answers are known: a reference engine written
// here (classical RK4 on Euler's equations and the quaternion, on the pendulum and on the
// projectile) is of order 4 on every scenario; the same engine with the sign of the
// gyroscopic term flipped, or with an explicit Euler step, is classified right. The
// scenarios' references are checked against the conservation laws they must obey, and
// MuJoCo (where found) is pinned on what the report says about it.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "mechcheck/audit/engines.hpp"
#include "mechcheck/audit/found.hpp"

namespace engines_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

/// A reference engine: the scenario's equations of motion stepped by RK4 (or explicit
/// Euler), with the gyroscopic term's sign as given.
class reference_run final : public audit::engine_run {
 public:
  reference_run(const audit::scenario& s, bool rk4, double gyroscopic_sign)
      : s_(s), rk4_(rk4), sign_(gyroscopic_sign) {
    switch (s.kind) {
      case audit::scenario_kind::free_top:
      case audit::scenario_kind::free_top_near_axis:
        y_.resize(7);
        y_ << s.omega0, 1, 0, 0, 0;  // omega (body), quaternion (w, x, y, z)
        break;
      case audit::scenario_kind::pendulum_small:
      case audit::scenario_kind::pendulum_large:
        y_.resize(2);
        y_ << s.theta0, 0;
        break;
      case audit::scenario_kind::projectile:
        throw audit::scenario_refused("reference engine: no projectile here (to test refusal)");
    }
  }
  Eigen::VectorXd f(const Eigen::VectorXd& y) const {
    Eigen::VectorXd d(y.size());
    if (y.size() == 7) {
      const Eigen::Vector3d w = y.head<3>(), m = s_.inertia.cwiseProduct(w);
      d.head<3>() = (sign_ * m.cross(w)).cwiseQuotient(s_.inertia);  // I w' = M x w
      const Eigen::Quaterniond q(y(3), y(4), y(5), y(6)), wq(0, w(0), w(1), w(2));
      const Eigen::Quaterniond dq = q * wq;  // q' = q (0, w) / 2, body-frame w
      d.tail<4>() << dq.w() / 2, dq.x() / 2, dq.y() / 2, dq.z() / 2;
    } else {
      const double i_hinge = s_.mass * s_.length * s_.length + 1e-3;
      d << y(1), -s_.mass * s_.gravity * s_.length / i_hinge * std::sin(y(0));
    }
    return d;
  }
  void step(double h) override {
    if (!rk4_) {
      y_ += h * f(y_);
      return;
    }
    const Eigen::VectorXd k1 = f(y_), k2 = f(y_ + h / 2 * k1), k3 = f(y_ + h / 2 * k2), k4 = f(y_ + h * k3);
    y_ += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  audit::engine_observation observe() const override {
    audit::engine_observation o;
    if (y_.size() == 7) {
      const Eigen::Vector3d w = y_.head<3>(), m = s_.inertia.cwiseProduct(w);
      o.observables = w;
      o.energy = w.dot(m) / 2;
      o.momentum = Eigen::Quaterniond(y_(3), y_(4), y_(5), y_(6)).normalized().toRotationMatrix() * m;
    } else {
      o.observables = y_;
      const double i_hinge = s_.mass * s_.length * s_.length + 1e-3;
      o.energy = i_hinge * y_(1) * y_(1) / 2 - s_.mass * s_.gravity * s_.length * std::cos(y_(0));
    }
    return o;
  }

 private:
  audit::scenario s_;
  bool rk4_;
  double sign_;
  Eigen::VectorXd y_;
};

audit::engine_integrator reference_engine(const std::string& name, bool rk4, double sign, int declared) {
  audit::engine_integrator e;
  e.name = name;
  e.declared_order = declared;
  e.start = [rk4, sign](const audit::scenario& s) -> std::unique_ptr<audit::engine_run> {
    return std::make_unique<reference_run>(s, rk4, sign);
  };
  return e;
}

audit::engine_options short_runs() {
  audit::engine_options opt;
  opt.long_run_steps = 1 << 14;
  return opt;
}

TEST(engines, the_references_keep_their_conservation_laws) {
  for (const auto& s : audit::scenarios()) {
    SCOPED_TRACE(s.name);
    if (s.kind == audit::scenario_kind::free_top || s.kind == audit::scenario_kind::free_top_near_axis) {
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
    } else {
      const double i_hinge = s.mass * s.length * s.length + 1e-3;
      const auto energy = [&](double t) {
        const Eigen::VectorXd x = s.exact(t);
        return i_hinge * x(1) * x(1) / 2 - s.mass * s.gravity * s.length * std::cos(x(0));
      };
      for (const double t : {0.3, 1.1, 5.0}) EXPECT_NEAR(energy(t), energy(0), 1e-14) << t;
      EXPECT_DOUBLE_EQ(s.exact(0)(0), s.theta0);
    }
  }
}

TEST(engines, a_reference_rk4_engine_is_of_order_4) {
  const auto a = audit::audit_engine(reference_engine("reference::RK4", true, 1, 4), short_runs());
  EXPECT_EQ(a.order.result, outcome::confirmed) << a.order.evidence;
  for (const auto& s : a.scenarios) {
    if (s.scenario == "projectile") {
      EXPECT_NE(s.refused.find("no projectile"), std::string::npos);
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
  const auto a = audit::audit_engine(reference_engine("reference::RK4_sign", true, -1, 4), opt);
  EXPECT_EQ(a.order.result, outcome::contradicted) << a.order.evidence;
  EXPECT_TRUE(a.scenarios[0].global.stalled) << a.order.evidence;
}

TEST(engines, explicit_euler_declared_second_order_is_contradicted_and_gains_energy) {
  audit::engine_options opt = short_runs();
  opt.scenarios = {"pendulum_small"};
  const auto a = audit::audit_engine(reference_engine("reference::Euler", false, 1, 2), opt);
  EXPECT_EQ(a.order.result, outcome::contradicted) << a.order.evidence;
  EXPECT_NEAR(a.scenarios[0].global.fit.value, 1, 0.1);
  ASSERT_TRUE(a.scenarios[0].energy_growth);
  EXPECT_GT(*a.scenarios[0].energy_growth, 0.75);  // explicit Euler: energy grows
}

TEST(engines, every_adapter_starts_each_scenario_at_its_exact_state) {
  // The mapping of each scenario to the engine's frames, signs and units, checked where it
  // is exact: the observables at t = 0 (rounding of the engine's rotation and joint
  // bookkeeping: 1e-12 of the scale).
  for (const auto& e : audit::engines_found())
    for (const auto& s : audit::scenarios()) {
      std::unique_ptr<audit::engine_run> run;
      try {
        run = e.start(s);
      } catch (const audit::scenario_refused& r) {
        EXPECT_EQ(e.name, "simbody::CPodes") << r.what();
        continue;
      }
      const Eigen::VectorXd x = run->observe().observables, exact = s.exact(0);
      ASSERT_EQ(x.size(), exact.size()) << e.name << " " << s.name;
      EXPECT_LT((x - exact).norm(), 1e-12 * s.scale) << e.name << " " << s.name << ": " << x.transpose()
                                                      << " against " << exact.transpose();
    }
}

TEST(engines, every_adapter_advances_its_clock_by_h_a_step) {
  // No force along x on the projectile: x(T) = v0x T after n steps of T / n whatever the
  // integrator -- a step skipped or doubled by the adapter shows as x off by v0x T / n.
  const auto s = audit::scenarios().back();
  ASSERT_EQ(s.name, "projectile");
  // An integrator that refuses the step size (Simbody's CPodes keeps its own error test)
  // must say so as a typed error naming the step.
  for (const auto& e : audit::engines_found()) {
    std::unique_ptr<audit::engine_run> run;
    try {
      run = e.start(s);
    } catch (const audit::scenario_refused& r) {
      EXPECT_EQ(e.name, "simbody::CPodes") << r.what();
      continue;
    }
    try {
      for (int i = 0; i < 16; ++i) run->step(s.t_end / 16);
    } catch (const convergence_error& ex) {
      EXPECT_NE(std::string(ex.what()).find("step "), std::string::npos) << ex.what();
      EXPECT_EQ(e.name, "simbody::CPodes") << ex.what();
      continue;
    }
    EXPECT_NEAR(run->observe().observables(0), s.velocity0(0) * s.t_end, 1e-12) << e.name;
  }
}

#ifdef MECHCHECK_HAVE_SIMBODY
TEST(simbody, verlet_and_feldberg_are_of_lower_order_than_their_headers_say) {
  // VerletIntegrator.h: "a third order, semi-explicit integrator": 2.00 on the pendulum;
  // RungeKuttaFeldbergIntegrator.h: "fifth order": 4.00 (it propagates the 4th-order
  // solution); RungeKuttaMerson's "fourth order" holds.
  audit::engine_options opt;
  opt.scenarios = {"pendulum_small"};
  opt.long_run_steps = 0;
  for (const auto& e : audit::simbody::integrators()) {
    if (e.name != "simbody::Verlet" && e.name != "simbody::RungeKuttaFeldberg" && e.name != "simbody::RungeKuttaMerson")
      continue;
    const auto a = audit::audit_engine(e, opt);
    const double expected = e.name == "simbody::Verlet" ? 2 : 4;
    EXPECT_NEAR(a.scenarios[0].global.fit.value, expected, 0.05) << e.name << ": " << a.order.evidence;
    EXPECT_EQ(a.order.result, e.name == "simbody::RungeKuttaMerson" ? outcome::confirmed : outcome::contradicted)
        << e.name << ": " << a.order.evidence;
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
  ASSERT_EQ(all.size(), 3u);
  audit::engine_options opt;
  opt.scenarios = {"free_top", "pendulum_small"};
  opt.long_run_steps = 1 << 14;
  for (const auto& e : all) {
    const auto a = audit::audit_engine(e, opt);
    EXPECT_EQ(a.order.result, outcome::confirmed) << e.name << ": " << a.order.evidence;
    EXPECT_NEAR(a.scenarios[0].global.fit.value, *e.declared_order, 0.1) << e.name;
    EXPECT_NE(e.origin.find("mjmodel.h"), std::string::npos);
  }
}

TEST(mujoco, a_negative_step_is_a_typed_error) {
  const auto e = audit::mujoco::integrators().front();
  auto r = e.start(audit::scenarios().front());
  EXPECT_THROW(r->step(-0.01), domain_error);
  EXPECT_THROW(r->step(std::nan("")), domain_error);
}
#endif

}  // namespace engines_test
